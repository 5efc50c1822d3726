// Tests of analyze_topology on generated meshes with known answers and on broken meshes.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/topology.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <CGAL/centroid.h>

#include <algorithm>
#include <functional>
#include <numbers>

using namespace envcrust;
using envcrust::topology::analyze_topology;

TEST(Topology, open_cylinder_is_an_orientable_annulus) {
  const auto t = analyze_topology(fixtures::open_cylinder(24, 6));
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_loops.size(), 2u);
  EXPECT_TRUE(t.is_orientable);
  EXPECT_TRUE(t.is_manifold());
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.components[0].genus, 0);
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(t.vertices, 24u * 7u);
  EXPECT_EQ(t.faces, 2u * 24u * 6u);
  for (const auto& loop : t.boundary_loops) {
    EXPECT_EQ(loop.vertices.size(), 24u);
    EXPECT_NEAR(loop.length, 24 * 2 * std::sin(std::numbers::pi / 24), 1e-12);
    EXPECT_TRUE(loop.is_oriented);
  }
}

TEST(Topology, disk_has_one_boundary_loop_and_euler_one) {
  for (const auto& m : {fixtures::square(5), fixtures::disk_fan(9)}) {
    const auto t = analyze_topology(m);
    EXPECT_EQ(t.euler_characteristic, 1);
    EXPECT_EQ(t.boundary_loops.size(), 1u);
    EXPECT_TRUE(t.is_orientable);
    EXPECT_EQ(t.components[0].genus, 0);
  }
}

TEST(Topology, mobius_strip_is_not_orientable) {
  const auto t = analyze_topology(fixtures::moebius(40, 4));
  EXPECT_EQ(t.euler_characteristic, 0);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_FALSE(t.is_orientable);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.boundary_loops[0].vertices.size(), 80u);  // runs around twice
  EXPECT_FALSE(t.boundary_loops[0].is_oriented);
  EXPECT_EQ(t.components[0].genus, 1);  // one cross-cap: chi = 2 - 1 - 1
}

TEST(Topology, closed_surfaces_have_no_boundary) {
  const auto sphere = analyze_topology(fixtures::octahedron());
  EXPECT_EQ(sphere.euler_characteristic, 2);
  EXPECT_TRUE(sphere.is_closed());
  EXPECT_EQ(sphere.components[0].genus, 0);
  const auto torus = analyze_topology(fixtures::torus());
  EXPECT_EQ(torus.euler_characteristic, 0);
  EXPECT_TRUE(torus.is_closed());
  EXPECT_EQ(torus.components[0].genus, 1);
  EXPECT_TRUE(torus.is_orientable);
}

namespace {

double signed_volume(const TriangleMesh& m) {
  double v = 0;
  for (const auto& t : m.triangles)
    v += CGAL::scalar_product(m.vertices[t[0]] - CGAL::ORIGIN,
                              CGAL::cross_product(m.vertices[t[1]] - CGAL::ORIGIN, m.vertices[t[2]] - CGAL::ORIGIN));
  return v / 6;
}

// Flip every third face: the mesh stays the same surface but is no longer wound consistently.
TriangleMesh scrambled(TriangleMesh m) {
  for (std::size_t f = 0; f < m.triangles.size(); f += 3) std::swap(m.triangles[f][1], m.triangles[f][2]);
  return m;
}

}  // namespace

TEST(OrientFaces, winds_open_and_closed_surfaces_consistently_and_closed_ones_outward) {
  for (auto m : {fixtures::open_cylinder(24, 6), fixtures::torus(24, 12), fixtures::capped_cylinder(24, 6)}) {
    m = scrambled(m);
    ASSERT_GT(analyze_topology(m).misoriented_edges, 0u);
    EXPECT_GT(topology::orient_faces(m), 0u);
    const auto t = analyze_topology(m);
    EXPECT_EQ(t.misoriented_edges, 0u);
    EXPECT_TRUE(t.is_orientable);
  }
  // A closed surface wound inward comes back outward.
  auto cube = fixtures::capped_cylinder(24, 6);
  const double outward = signed_volume(cube);
  ASSERT_GT(outward, 0);
  for (auto& t : cube.triangles) std::swap(t[1], t[2]);
  EXPECT_EQ(topology::orient_faces(cube), cube.triangles.size());
  EXPECT_NEAR(signed_volume(cube), outward, 1e-12);
}

// Per face: its area vector against `away(centroid)`; the count of faces that agree.
static std::size_t faces_facing(const TriangleMesh& m, const std::function<Vector3(const Point3&)>& away) {
  std::size_t agree = 0;
  for (const auto& t : m.triangles) {
    const Point3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    agree += CGAL::cross_product(b - a, c - a) * away(CGAL::centroid(a, b, c)) > 0;
  }
  return agree;
}

TEST(OrientFaces, turns_open_pieces_out_of_the_volume_their_borders_close) {
  // Dome of the unit sphere above z = 0.2 (one loop), the open cylinder (two): out is away
  // from the centre / the axis, whichever way the faces came wound.
  const auto dome = fixtures::grid_mesh(24, 6, [](double u, double v) {
    const double polar = 0.01 + v * std::acos(0.2), a = 2 * std::numbers::pi * u;
    return Point3(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
  }, fixtures::Glue::Periodic);
  auto from_centre = [](const Point3& p) { return p - CGAL::ORIGIN; };
  auto from_axis = [](const Point3& p) { return Vector3(p.x(), p.y(), 0); };
  for (bool reversed : {false, true}) {
    for (const auto& [mesh, away] : {std::pair{dome, std::function<Vector3(const Point3&)>(from_centre)},
                                     std::pair{fixtures::open_cylinder(24, 6), std::function<Vector3(const Point3&)>(from_axis)}}) {
      auto m = scrambled(mesh);
      if (reversed)
        for (auto& t : m.triangles) std::swap(t[1], t[2]);
      topology::orient_faces(m);
      EXPECT_EQ(faces_facing(m, away), m.triangles.size()) << "reversed " << reversed;
    }
  }
  // Two flat squares (no volume): each faces where its vector area's largest component is
  // positive, +z for the xy-plane one, +y for the xz-plane one, also when given the other way.
  auto flat = fixtures::square(4);
  for (auto& t : flat.triangles) std::swap(t[1], t[2]);
  auto upright = fixtures::square(4);
  for (auto& p : upright.vertices) p = Point3(p.x(), 0, p.y() + 3);
  const auto flat_faces = flat.triangles.size();
  for (auto t : upright.triangles) {
    for (auto& v : t) v += static_cast<Index>(flat.vertices.size());
    flat.triangles.push_back(t);
  }
  flat.vertices.insert(flat.vertices.end(), upright.vertices.begin(), upright.vertices.end());
  topology::orient_faces(flat);
  TriangleMesh first = flat, second = flat;
  first.triangles.resize(flat_faces);
  second.triangles.erase(second.triangles.begin(), second.triangles.begin() + static_cast<std::ptrdiff_t>(flat_faces));
  EXPECT_EQ(faces_facing(first, [](const Point3&) { return Vector3(0, 0, 1); }), first.triangles.size());
  EXPECT_EQ(faces_facing(second, [](const Point3&) { return Vector3(0, 1, 0); }), second.triangles.size());
}

TEST(OrientFaces, leaves_a_moebius_strip_with_one_seam) {
  auto m = scrambled(fixtures::moebius(40, 4));
  topology::orient_faces(m);
  const auto t = analyze_topology(m);
  EXPECT_FALSE(t.is_orientable);
  EXPECT_GT(t.misoriented_edges, 0u);
  EXPECT_LE(t.misoriented_edges, 8u);  // one seam across the 4 rows: at most 2 edges per row
  EXPECT_EQ(t.euler_characteristic, 0);
}

TEST(RemoveDuplicateFaces, repeated_faces_in_any_winding_go_and_the_surface_comes_back) {
  const auto original = fixtures::open_cylinder(24, 6);
  auto m = original;
  m.triangles.push_back(m.triangles[5]);                                   // the same again
  m.triangles.push_back({m.triangles[7][0], m.triangles[7][2], m.triangles[7][1]});  // reversed
  m.triangles.push_back({3, 3, 4});                                        // degenerate
  ASSERT_GT(analyze_topology(m).non_manifold_edges, 0u);
  EXPECT_EQ(mesh::remove_duplicate_faces(m), 3u);
  EXPECT_EQ(m.triangles, original.triangles);  // first occurrences kept, in order
  EXPECT_EQ(mesh::remove_duplicate_faces(m), 0u);
}

TEST(Topology, capping_a_cylinder_closes_it) {
  const auto t = analyze_topology(fixtures::capped_cylinder(24, 6));
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.boundary_loops.size(), 0u);
  EXPECT_EQ(t.misoriented_edges, 0u);
}

TEST(Topology, punching_a_hole_adds_a_boundary_loop) {
  auto m = fixtures::torus(24, 12);
  m.triangles.erase(m.triangles.begin() + 100, m.triangles.begin() + 102);  // one quad
  const auto t = analyze_topology(m);
  EXPECT_EQ(t.euler_characteristic, -1);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_EQ(t.boundary_loops[0].vertices.size(), 4u);
  EXPECT_EQ(t.components[0].genus, 1);
}

TEST(Topology, flipped_faces_are_misoriented_but_orientable) {
  auto m = fixtures::open_cylinder(24, 6);
  for (std::size_t f = 0; f < m.triangles.size() / 2; ++f) std::swap(m.triangles[f][1], m.triangles[f][2]);
  const auto t = analyze_topology(m);
  EXPECT_TRUE(t.is_orientable);
  EXPECT_GT(t.misoriented_edges, 0u);
  EXPECT_EQ(t.euler_characteristic, 0);
}

TEST(Topology, a_seam_glued_with_a_flip_makes_the_band_non_orientable) {
  // The same strip as the cylinder, but the seam identifies v with 1 - v.
  const auto m = fixtures::grid_mesh(24, 6, [](double u, double v) {
    const double a = fixtures::kTwoPi * u;
    return Point3(std::cos(a), std::sin(a), 2 * v - 1 + 0.0 * a);
  }, fixtures::Glue::Flipped);
  const auto t = analyze_topology(m);
  EXPECT_FALSE(t.is_orientable);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
}

TEST(Topology, three_faces_on_an_edge_make_it_non_manifold) {
  auto m = fixtures::square(2);
  // A fin on the edge between vertices 0 and 1 of the square.
  m.vertices.push_back({0.25, 0, 1});
  m.triangles.push_back({0, 1, Index(m.vertices.size() - 1)});
  auto fin2 = m;
  const auto t = analyze_topology(m);
  EXPECT_EQ(t.non_manifold_edges, 0u);  // edge 0-1 is a border edge of the square: 2 faces
  fin2.vertices.push_back({0.25, 0, -1});
  fin2.triangles.push_back({0, 1, Index(fin2.vertices.size() - 1)});
  const auto t2 = analyze_topology(fin2);
  EXPECT_EQ(t2.non_manifold_edges, 1u);
  EXPECT_FALSE(t2.is_manifold());
  EXPECT_FALSE(t2.components[0].genus.has_value());
}

TEST(Topology, total_genus_sums_handles_and_cross_caps_over_components) {
  // A torus (1 handle), a Moebius strip (1 cross-cap) and a disc, side by side.
  TriangleMesh m = fixtures::torus();
  for (const auto& part : {fixtures::moebius(40, 4), fixtures::square(3)}) {
    const auto offset = static_cast<Index>(m.vertices.size());
    for (const auto& p : part.vertices) m.vertices.push_back(Point3(p.x() + 10 * offset, p.y(), p.z()));
    for (const auto& t : part.triangles) m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  const auto t = analyze_topology(m);
  ASSERT_EQ(t.components.size(), 3u);
  EXPECT_EQ(topology::total_genus(t), 2);
  EXPECT_EQ(topology::total_genus(analyze_topology(fixtures::square(3))), 0);
  // Unset when a component is no manifold (its genus is undefined).
  auto fin = fixtures::square(2);
  for (double z : {1.0, -1.0}) {
    fin.vertices.push_back({0.25, 0, z});
    fin.triangles.push_back({0, 1, Index(fin.vertices.size() - 1)});
  }
  EXPECT_FALSE(topology::total_genus(analyze_topology(fin)).has_value());
}

TEST(Topology, two_disks_touching_at_a_vertex_make_it_non_manifold) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const auto t = analyze_topology(m);
  EXPECT_EQ(t.non_manifold_vertices, 1u);
  EXPECT_EQ(t.non_manifold_edges, 0u);
  EXPECT_EQ(t.components.size(), 2u);
  EXPECT_EQ(t.euler_characteristic, 1);  // 5 - 6 + 2
}

TEST(Topology, polygon_soup_is_welded_before_counting) {
  const auto welded = analyze_topology(fixtures::as_soup(fixtures::open_cylinder(16, 4)));
  EXPECT_EQ(welded.euler_characteristic, 0);
  EXPECT_EQ(welded.boundary_loops.size(), 2u);
  EXPECT_EQ(welded.welded_vertices, 3u * 2u * 16u * 4u - 16u * 5u);
}

TEST(Topology, disjoint_triangles_are_separate_components) {
  TriangleMesh soup;
  for (int i = 0; i < 5; ++i) {
    const auto b = static_cast<Index>(soup.vertices.size());
    soup.vertices.insert(soup.vertices.end(), {{double(i), 0, 0}, {i + 0.5, 0, 0}, {double(i), 1, 0}});
    soup.triangles.push_back({b, Index(b + 1), Index(b + 2)});
  }
  const auto t = analyze_topology(soup);
  EXPECT_EQ(t.components.size(), 5u);
  EXPECT_EQ(t.boundary_loops.size(), 5u);
  EXPECT_EQ(t.euler_characteristic, 5);
}

TEST(Topology, degenerate_and_duplicate_faces_are_counted) {
  auto m = fixtures::square(2);
  m.triangles.push_back({0, 0, 1});                  // repeated vertex: ignored
  m.vertices.push_back({0.5, 0, 0});                 // on the edge 0-1: zero-area face
  m.triangles.push_back({0, 1, Index(m.vertices.size() - 1)});
  m.triangles.push_back(m.triangles[0]);             // duplicate
  const auto t = analyze_topology(m);
  EXPECT_EQ(t.degenerate_faces, 2u);
  EXPECT_EQ(t.duplicate_faces, 1u);
}

TEST(Topology, out_of_range_index_is_reported) {
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 1, 7}};
  try {
    analyze_topology(m);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "face 1 has vertex index 7, but the mesh has 3 vertices");
  }
}

// boundary_loops gives analyze_topology's loops (same vertices, up to the walking direction,
// and lengths) without the rest of the analysis: on an annulus, a Moebius band, a square with
// a degenerate face added, and a closed torus (none).
TEST(BoundaryLoops, are_the_loops_analyze_topology_traces) {
  auto with_degenerate = fixtures::square(5);
  with_degenerate.triangles.push_back({0, 0, 1});  // a repeated vertex: ignored by both
  for (const auto& m : {fixtures::open_cylinder(24, 6), fixtures::moebius(40, 4), with_degenerate, fixtures::torus()}) {
    const auto expected = analyze_topology(m, {.weld_identical_vertices = false}).boundary_loops;
    const auto loops = topology::boundary_loops(m);
    ASSERT_EQ(loops.size(), expected.size());
    for (std::size_t i = 0; i < loops.size(); ++i) {
      auto a = loops[i].vertices, b = expected[i].vertices;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      EXPECT_EQ(a, b);
      EXPECT_DOUBLE_EQ(loops[i].length, expected[i].length);
      EXPECT_FALSE(loops[i].is_oriented);
      EXPECT_EQ(loops[i].component, -1);
    }
  }
  TriangleMesh bad;
  bad.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  bad.triangles = {{0, 1, 5}};
  EXPECT_THROW(topology::boundary_loops(bad), InvalidInput);
}
