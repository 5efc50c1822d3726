// Joining tessellations: T-junctions split, border vertices within the tolerance welded, and
// borders farther apart left open.
#include "envcrust/models.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

namespace envcrust::models {
namespace {

// The axis-aligned rectangle [x0, x1] x [y0, y1] at z = 0 as a grid of n x m quads.
TriangleMesh grid(double x0, double x1, double y0, double y1, int n, int m) {
  TriangleMesh mesh;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(x0 + (x1 - x0) * i / n, y0 + (y1 - y0) * j / m, 0.0);
  const auto at = [&](int i, int j) { return static_cast<Index>(i + (n + 1) * j); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return mesh;
}

TEST(JoinTessellations, splits_the_edges_where_the_other_side_has_more_vertices) {
  // One quad on the left, a 3 x 5 grid on the right: the left square's right edge meets 4
  // vertices inside it.
  const auto joined = join_tessellations({grid(0, 1, 0, 1, 1, 1), grid(1, 2, 0, 1, 3, 5)}, 1e-6);
  const auto t = topology::analyze_topology(joined.mesh);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.degenerate_faces, 0u);
  EXPECT_NEAR(t.boundary_loops.front().length, 6.0, 1e-12);
  EXPECT_EQ(joined.stats.split_edges, 1u);  // the left quad's right edge
  EXPECT_EQ(joined.stats.joined_edges, 5u);  // the right grid's five edges along x = 1
  EXPECT_EQ(joined.stats.largest_gap, 0.0);
  // No vertex of the join is lost and none is added but the 4 split points (welded back).
  EXPECT_EQ(joined.mesh.vertices.size(), 4u + 4u * 6u - 2u);
}

TEST(JoinTessellations, welds_borders_within_the_tolerance_and_leaves_wider_gaps_open) {
  // The right square moved 1e-4 away: joined at a tolerance of 1e-3, not at 1e-5.
  const std::vector<TriangleMesh> parts{grid(0, 1, 0, 1, 2, 2), grid(1.0001, 2, 0, 1, 2, 2)};
  const auto near = join_tessellations(parts, 1e-3);
  const auto t = topology::analyze_topology(near.mesh);
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_NEAR(near.stats.largest_gap, 1e-4, 1e-9);
  const auto far = join_tessellations(parts, 1e-5);
  const auto u = topology::analyze_topology(far.mesh);
  EXPECT_EQ(u.components.size(), 2u);
  EXPECT_EQ(u.euler_characteristic, 2);
  EXPECT_EQ(far.stats.joined_edges, 0u);
  // Left open, but within 20 tolerances: the three border vertices on either side are near misses.
  EXPECT_EQ(far.stats.near_misses, 6u);
  EXPECT_NEAR(far.stats.nearest_miss, 1e-4, 1e-9);
  EXPECT_EQ(near.stats.near_misses, 0u);
}

TEST(JoinTessellations, fans_a_face_split_on_two_edges_from_its_centre) {
  // A single triangle's two legs each meet a finer neighbour: both are split.
  TriangleMesh corner;
  corner.vertices = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)};
  corner.triangles = {{0, 1, 2}};
  const auto joined =
      join_tessellations({corner, grid(0, 1, -1, 0, 4, 1), grid(-1, 0, 0, 1, 1, 4)}, 1e-9);
  const auto t = topology::analyze_topology(joined.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.degenerate_faces, 0u);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(joined.stats.split_edges, 2u);
}

}  // namespace
}  // namespace envcrust::models
