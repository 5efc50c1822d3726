// fill_short_loops, the fan that closes the sheet's holes below the envelope's resolution:
// it closes a pinhole and a cup's mouth but not the rim of a small island, which filling
// would close into a doubled shell.
#include "envcrust/topology.h"

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

// A flat disc of radius 1 in z = 0: a fan of `segments` triangles.
TaggedMesh flat_disc(int segments = 24) {
  TaggedMesh t;
  t.mesh.vertices.emplace_back(0, 0, 0);
  for (int s = 0; s < segments; ++s) {
    const double a = 2 * std::numbers::pi * s / segments;
    t.mesh.vertices.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  for (int s = 0; s < segments; ++s)
    t.mesh.triangles.push_back({0, static_cast<Index>(1 + s), static_cast<Index>(1 + (s + 1) % segments)});
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
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
