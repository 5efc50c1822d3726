// cut_to_orientable with a bound on the reversing loops: a small cross-cap glued into a plane
// (the kind of defect a sheet gets where it crosses itself) is cut, while the twist of a long
// Moebius strip, reversed only by loops around the whole strip, is kept; without a bound both
// are cut. A twist on a closed piece (the strip capped with a disc) is always cut: a closed
// surface in space is orientable.
#include "envcrust/topology.h"

#include "sheet_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace envcrust;
using namespace envcrust::extract;

namespace {

constexpr double kPi = std::numbers::pi;

// A Moebius strip around a circle of radius 1 in the xy plane, 0.4 wide, half a turn of
// twist: 64 segments along, 4 rows across (cells about 0.1 wide), its midline 2 pi long.
TaggedMesh moebius_strip() {
  constexpr int segments = 64, rows = 4;
  TaggedMesh t;
  for (int i = 0; i < segments; ++i) {
    const double u = 2 * kPi * i / segments;
    for (int k = 0; k <= rows; ++k) {
      const double s = -0.2 + 0.4 * k / rows;
      const double r = 1 + s * std::cos(u / 2);
      t.mesh.vertices.emplace_back(r * std::cos(u), r * std::sin(u), s * std::sin(u / 2));
    }
  }
  auto id = [](int i, int k) { return static_cast<Index>(i * (rows + 1) + k); };
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    auto next = [&](int k) { return j == 0 ? id(0, rows - k) : id(j, k); };  // the sides swap after half a turn
    for (int k = 0; k < rows; ++k) {
      const Index a = id(i, k), b = id(i, k + 1), c = next(k), d = next(k + 1);
      t.mesh.triangles.push_back({a, c, d});
      t.mesh.triangles.push_back({a, d, b});
    }
  }
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

// A 12 x 12 grid of 0.1 cells in z = 0 without the 4 x 4 cells at [4, 8)^2; the hole's rim
// (16 vertices) is sewn to the border of a Moebius band whose 8 rungs join opposite rim
// vertices: a cross-cap about 0.4 across.
TaggedMesh plane_with_a_cross_cap() {
  constexpr int n = 12;
  TaggedMesh t;
  auto id = [](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) t.mesh.vertices.emplace_back(0.1 * i, 0.1 * j, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (i >= 4 && i < 8 && j >= 4 && j < 8) continue;
      t.mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  std::vector<Index> rim;  // counter-clockwise from the corner (4, 4)
  for (int k = 0; k < 4; ++k) rim.push_back(id(4 + k, 4));
  for (int k = 0; k < 4; ++k) rim.push_back(id(8, 4 + k));
  for (int k = 0; k < 4; ++k) rim.push_back(id(8 - k, 8));
  for (int k = 0; k < 4; ++k) rim.push_back(id(4, 8 - k));
  // The band's border runs rung ends (i, 0) for i = 0..7, then (i, 1): (i, 0) = rim[i],
  // (i, 1) = rim[i + 8]; the last quad joins rung 7 to rung 0 with its ends swapped.
  for (int i = 0; i < 8; ++i) {
    const Index a = rim[i], b = rim[i + 8];
    const Index c = i < 7 ? rim[i + 1] : rim[8], d = i < 7 ? rim[i + 9] : rim[0];
    t.mesh.triangles.push_back({a, d, c});
    t.mesh.triangles.push_back({a, b, d});
  }
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

// The Moebius strip's border (one loop, 128 vertices) joined by a fan to an apex 10 above
// it: a projective plane (closed, non-orientable; the fan crosses the strip, which the
// combinatorics does not see). Loops through the apex are over 20 long, so the shortest
// reversing loops still run around the strip.
TaggedMesh capped_moebius_strip() {
  TaggedMesh t = moebius_strip();
  const auto loops = topology::boundary_loops(t.mesh);
  const auto apex = static_cast<Index>(t.mesh.vertices.size());
  t.mesh.vertices.emplace_back(0.0, 0.0, 10.0);
  const std::vector<Index>& rim = loops.front().vertices;
  for (std::size_t k = 0; k < rim.size(); ++k) t.mesh.triangles.push_back({rim[k], rim[(k + 1) % rim.size()], apex});
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

}  // namespace

TEST(CutToOrientable, the_test_meshes_are_what_they_claim) {
  const auto strip = topology::analyze_topology(moebius_strip().mesh);
  EXPECT_TRUE(strip.is_manifold());
  EXPECT_FALSE(strip.is_orientable);
  EXPECT_EQ(strip.euler_characteristic, 0);
  EXPECT_EQ(strip.boundary_loops.size(), 1u);
  const auto capped = topology::analyze_topology(plane_with_a_cross_cap().mesh);
  EXPECT_TRUE(capped.is_manifold());
  EXPECT_FALSE(capped.is_orientable);
  EXPECT_EQ(capped.euler_characteristic, 0);  // a disc (1) with a cross-cap (-1)
  EXPECT_EQ(capped.boundary_loops.size(), 1u);
  const auto projective_plane = topology::analyze_topology(capped_moebius_strip().mesh);
  EXPECT_TRUE(projective_plane.is_manifold());
  EXPECT_FALSE(projective_plane.is_orientable);
  EXPECT_EQ(projective_plane.euler_characteristic, 1);
  EXPECT_TRUE(projective_plane.boundary_loops.empty());
}

namespace {

// cut_to_orientable(t, 0.15, bound) cuts one seam and leaves an orientable manifold; returns
// its analysis.
topology::MeshTopology expect_one_seam_cut(TaggedMesh& t, double bound) {
  const OrientableCutStats stats = cut_to_orientable(t, 0.15, bound);
  EXPECT_EQ(stats.seams, 1u);
  EXPECT_EQ(stats.twists_kept, 0u);
  EXPECT_GT(stats.faces_removed, 0u);
  EXPECT_FALSE(stats.still_non_orientable);
  auto after = topology::analyze_topology(t.mesh);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_TRUE(after.is_orientable);
  return after;
}

}  // namespace

TEST(CutToOrientable, cuts_a_twist_on_a_closed_piece_whatever_the_loop_bound) {
  TaggedMesh t = capped_moebius_strip();
  EXPECT_FALSE(expect_one_seam_cut(t, 6.0).boundary_loops.empty());
}

TEST(CutToOrientable, cuts_a_small_cross_cap_under_the_loop_bound) {
  TaggedMesh t = plane_with_a_cross_cap();
  expect_one_seam_cut(t, 3.0);
  EXPECT_EQ(t.face_dot.size(), t.mesh.triangles.size());
}

TEST(CutToOrientable, keeps_a_twist_only_loops_longer_than_the_bound_reverse) {
  TaggedMesh t = moebius_strip();
  const std::size_t faces = t.mesh.triangles.size();
  // Its reversing loops run around the strip: about 2 pi long (between face centroids a
  // little longer).
  const OrientableCutStats kept = cut_to_orientable(t, 0.15, 6.0);
  EXPECT_EQ(kept.seams, 0u);
  EXPECT_EQ(kept.twists_kept, 1u);
  EXPECT_EQ(kept.faces_removed, 0u);
  EXPECT_FALSE(kept.still_non_orientable);
  EXPECT_EQ(t.mesh.triangles.size(), faces);
  EXPECT_FALSE(topology::analyze_topology(t.mesh).is_orientable);
  // A bound above the loop's length cuts it, as no bound does.
  for (const double bound : {9.0, std::numeric_limits<double>::infinity()}) {
    TaggedMesh u = moebius_strip();
    const OrientableCutStats cut = cut_to_orientable(u, 0.15, bound);
    EXPECT_EQ(cut.seams, 1u) << bound;
    EXPECT_EQ(cut.twists_kept, 0u) << bound;
    const auto after = topology::analyze_topology(u.mesh);
    EXPECT_TRUE(after.is_orientable) << bound;
    EXPECT_EQ(after.euler_characteristic, 1) << bound;  // a disc
    EXPECT_EQ(after.boundary_loops.size(), 1u) << bound;
  }
}
