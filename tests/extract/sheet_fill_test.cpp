// Small pieces of the sheet: fill_short_loops, the fan that closes the sheet's holes below
// the envelope's resolution, closes a pinhole and a cup's mouth but not the rim of a small
// island, which filling would close into a doubled shell; filter_components keeps a small
// island of the input but drops a crumb on samples the main piece covers.
#include "envcrust/topology.h"

#include "envcrust/nearest_index.h"

#include "sheet_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace envcrust;
using namespace envcrust::extract;

namespace {

// The unit sphere's latitude-longitude mesh from the south pole up to ring `last_ring` of
// `rings` (rings = last_ring: closed but for the north pole's fan; rings / 2: a hemisphere,
// a cup). Faces wound outward.
TaggedMesh sphere_part(int rings, int last_ring, int segments = 24) {
  TaggedMesh t;
  auto& v = t.mesh.vertices;
  v.emplace_back(0, 0, -1);  // the south pole
  for (int r = 1; r <= last_ring; ++r) {
    const double polar = std::numbers::pi * (1.0 - static_cast<double>(r) / rings);
    for (int s = 0; s < segments; ++s) {
      const double a = 2 * std::numbers::pi * s / segments;
      v.emplace_back(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    }
  }
  auto at = [&](int r, int s) { return static_cast<Index>(1 + (r - 1) * segments + (s % segments)); };
  for (int s = 0; s < segments; ++s) t.mesh.triangles.push_back({0, at(1, s + 1), at(1, s)});
  for (int r = 1; r < last_ring; ++r)
    for (int s = 0; s < segments; ++s) {
      t.mesh.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      t.mesh.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

// A flat disc of radius r about c in the plane z = c.z(): a fan of `segments` triangles,
// appended to t.
void add_flat_disc(TaggedMesh& t, const Point3& c, double r, int segments = 24) {
  const auto centre = static_cast<Index>(t.mesh.vertices.size());
  t.mesh.vertices.push_back(c);
  for (int s = 0; s < segments; ++s) {
    const double a = 2 * std::numbers::pi * s / segments;
    t.mesh.vertices.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a), c.z());
  }
  for (int s = 0; s < segments; ++s)
    t.mesh.triangles.push_back({centre, static_cast<Index>(centre + 1 + s),
                                static_cast<Index>(centre + 1 + (s + 1) % segments)});
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
}

TaggedMesh flat_disc() {
  TaggedMesh t;
  add_flat_disc(t, Point3(0, 0, 0), 1.0);
  return t;
}

// The square [-1, 1]^2 in z = 0 as an n x n grid of quads, two triangles each, appended.
void add_square(TaggedMesh& t, int n) {
  const auto first = static_cast<Index>(t.mesh.vertices.size());
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) t.mesh.vertices.emplace_back(-1.0 + 2.0 * i / n, -1.0 + 2.0 * j / n, 0.0);
  auto at = [&](int i, int j) { return static_cast<Index>(first + j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      t.mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      t.mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
}

// Samples on a grid of step h over the points within `r` of c in the plane z = c.z().
void add_disc_samples(std::vector<Point3>& samples, const Point3& c, double r, double h) {
  for (double y = -r; y <= r; y += h)
    for (double x = -r; x <= r; x += h)
      if (x * x + y * y <= r * r) samples.emplace_back(c.x() + x, c.y() + y, c.z());
}

}  // namespace

TEST(FillShortLoops, a_pinhole_in_a_closed_sheet_is_closed) {
  TaggedMesh t = sphere_part(12, 11);  // the north pole's fan missing: a loop 1.6 long
  ASSERT_EQ(topology::analyze_topology(t.mesh).boundary_loops.size(), 1u);
  EXPECT_EQ(fill_short_loops(t, 2.0), 1u);
  const auto topo = topology::analyze_topology(t.mesh);
  EXPECT_TRUE(topo.is_closed());
  EXPECT_EQ(topo.euler_characteristic, 2);
}

TEST(FillShortLoops, a_cup_spans_twice_its_mouth_and_is_closed) {
  TaggedMesh t = sphere_part(12, 6);  // the southern hemisphere: area 2 pi, mouth 2 pi long
  EXPECT_EQ(fill_short_loops(t, 7.0), 1u);
  EXPECT_TRUE(topology::analyze_topology(t.mesh).is_closed());
}

TEST(FillShortLoops, the_rim_of_a_small_island_is_kept) {
  TaggedMesh t = flat_disc();  // area about pi, its rim 2 pi long: a disc, not a hole
  EXPECT_EQ(fill_short_loops(t, 7.0), 0u);
  const auto topo = topology::analyze_topology(t.mesh);
  EXPECT_EQ(topo.euler_characteristic, 1);
  EXPECT_EQ(topo.boundary_loops.size(), 1u);
  // A longer loop is left alone whatever the piece: only loops shorter than the bound count.
  TaggedMesh cup = sphere_part(12, 6);
  EXPECT_EQ(fill_short_loops(cup, 6.0), 0u);
}

// With a unit (the local rho), the bound is in its units along each loop: the pinhole 1.6
// long is closed under a bound of 2 where the unit is 1, kept where it is 0.5 (a bound of 1
// there), and the cup's mouth (2 pi) is closed under 2 pi where the unit is over 1 on it.
TEST(FillShortLoops, the_bound_follows_the_local_unit_along_each_loop) {
  TaggedMesh fine = sphere_part(12, 11), coarse = sphere_part(12, 11);
  EXPECT_EQ(fill_short_loops(fine, 2.0, [](const Point3&) { return 0.5; }), 0u);
  EXPECT_EQ(fill_short_loops(coarse, 2.0, [](const Point3&) { return 1.0; }), 1u);
  EXPECT_TRUE(topology::analyze_topology(coarse.mesh).is_closed());
  // The unit read at each rim vertex: large above z = 0 (where the cup's mouth is), small below.
  TaggedMesh cup = sphere_part(12, 6);
  EXPECT_EQ(fill_short_loops(cup, 2.0 * std::numbers::pi, [](const Point3& p) { return p.z() > -0.1 ? 1.1 : 0.1; }), 1u);
  TaggedMesh low = sphere_part(12, 6);
  EXPECT_EQ(fill_short_loops(low, 2.0 * std::numbers::pi, [](const Point3& p) { return p.z() > -0.1 ? 0.9 : 2.0; }), 0u);
}

// The square (a grid 0.05 apart) and its samples (0.02 apart), beside it two small discs
// (0.75% and 0.5% of the area, below the 1% a crumb has): an island 0.3 above the plane with
// its own samples, and a disc on too few samples; on the square, a doubled patch (0.75%)
// over samples the square covers. Only the square and the island stay.
TEST(FilterComponents, a_small_island_of_the_input_stays_and_crumbs_go) {
  TaggedMesh t;
  add_square(t, 40);
  std::vector<Point3> samples;
  for (int j = 0; j <= 100; ++j)
    for (int i = 0; i <= 100; ++i) samples.emplace_back(-1.0 + 0.02 * i, -1.0 + 0.02 * j, 0.0);
  const Point3 island(1.5, 0.0, 0.3), sparse(1.5, 0.8, -0.3), doubled(0.3, 0.3, 0.001);
  add_flat_disc(t, island, 0.1);
  add_disc_samples(samples, island, 0.1, 0.02);  // about 80 samples
  add_flat_disc(t, sparse, 0.08);
  add_disc_samples(samples, sparse, 0.08, 0.08);  // 5 samples
  add_flat_disc(t, doubled, 0.1);
  const NearestIndex index(samples);
  const std::vector<double> max_distance(samples.size(), 0.05);
  EXPECT_EQ(filter_components(t, index, max_distance, 0.01), 2u);
  const auto topo = topology::analyze_topology(t.mesh);
  EXPECT_EQ(topo.components.size(), 2u);
  std::size_t on_island = 0, on_square = 0;
  for (const auto& f : t.mesh.triangles)
    for (const Index v : f) {
      const double z = t.mesh.vertices[v].z();
      on_island += z == 0.3;
      on_square += z == 0.0;
      EXPECT_TRUE(z == 0.3 || z == 0.0) << "a vertex at z = " << z << " stayed";  // -0.3, 0.001
    }
  EXPECT_EQ(on_island, 3u * 24u);
  EXPECT_EQ(on_square, 3u * 3200u);
}
