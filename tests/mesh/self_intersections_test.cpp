// self_intersections: faces that pass through each other are found, faces that only share
// vertices or an edge are not, whatever the case (no shared vertex, one, two), and
// coincident copies of a vertex count as one.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace envcrust;

namespace {

TriangleMesh two_triangles(std::array<Point3, 3> a, std::array<Point3, 3> b) {
  TriangleMesh m;
  for (const auto& p : a) m.vertices.push_back(p);
  for (const auto& p : b) m.vertices.push_back(p);
  m.triangles = {{0, 1, 2}, {3, 4, 5}};  // no shared index: welding decides what is shared
  return m;
}

// A closed octahedron-like sphere: 8 x 8 grid of latitude and longitude, poles shared.
TriangleMesh uv_sphere(int rings, int segments) {
  TriangleMesh m;
  m.vertices.emplace_back(0, 0, 1);
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double theta = std::numbers::pi * i / rings, phi = 2 * std::numbers::pi * j / segments;
      m.vertices.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  m.vertices.emplace_back(0, 0, -1);
  const auto south = static_cast<Index>(m.vertices.size() - 1);
  auto at = [&](int i, int j) { return static_cast<Index>(1 + (i - 1) * segments + (j % segments)); };
  for (int j = 0; j < segments; ++j) {
    m.triangles.push_back({0, at(1, j), at(1, j + 1)});
    m.triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
    for (int i = 1; i + 1 < rings; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return m;
}

}  // namespace

TEST(SelfIntersections, a_closed_sphere_has_none) {
  const auto s = mesh::self_intersections(uv_sphere(12, 16));
  EXPECT_EQ(s.face_pairs, 0u);
  EXPECT_EQ(s.faces, 0u);
  EXPECT_TRUE(s.examples.empty());
}

TEST(SelfIntersections, crossing_triangles_without_a_shared_vertex) {
  const Point3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  // Pierces the first through (0.5, 0.5, 0).
  const auto crossing = mesh::self_intersections(two_triangles({a, b, c}, {Point3(0.5, 0.5, -1), Point3(0.5, 0.5, 1), Point3(3, 3, 0.5)}));
  EXPECT_EQ(crossing.face_pairs, 1u);
  EXPECT_EQ(crossing.faces, 2u);
  ASSERT_EQ(crossing.examples.size(), 1u);
  // Above it, apart.
  EXPECT_EQ(mesh::self_intersections(two_triangles({a, b, c}, {Point3(0, 0, 1), Point3(2, 0, 1), Point3(0, 2, 1)})).face_pairs, 0u);
}

TEST(SelfIntersections, triangles_sharing_an_edge_meet_only_when_folded_flat_onto_each_other) {
  const Point3 s(0, 0, 0), t(1, 0, 0);
  // The same plane, the same side of the edge: they overlap.
  EXPECT_EQ(mesh::self_intersections(two_triangles({s, t, Point3(0.5, 1, 0)}, {t, s, Point3(0.2, 0.5, 0)})).face_pairs, 1u);
  // The same plane, opposite sides: a flat strip.
  EXPECT_EQ(mesh::self_intersections(two_triangles({s, t, Point3(0.5, 1, 0)}, {t, s, Point3(0.5, -1, 0)})).face_pairs, 0u);
  // A sharp fold, not flat: they meet only along the edge.
  EXPECT_EQ(mesh::self_intersections(two_triangles({s, t, Point3(0.5, 1, 0)}, {t, s, Point3(0.5, 1, 0.001)})).face_pairs, 0u);
}

TEST(SelfIntersections, triangles_sharing_a_vertex_meet_when_one_passes_through_the_other) {
  const Point3 s(0, 0, 0);
  const std::array<Point3, 3> flat = {s, Point3(2, 0, 0), Point3(0, 2, 0)};
  // From s down through the flat one's interior and out above it.
  EXPECT_EQ(mesh::self_intersections(two_triangles(flat, {s, Point3(1, 0.5, -1), Point3(0.5, 1, 1)})).face_pairs, 1u);
  // From s away from it: only the vertex is shared.
  EXPECT_EQ(mesh::self_intersections(two_triangles(flat, {s, Point3(-1, 0, 1), Point3(0, -1, 1)})).face_pairs, 0u);
  // The same plane, its sector inside the flat one's: it lies on it.
  EXPECT_EQ(mesh::self_intersections(two_triangles(flat, {s, Point3(1, 0.2, 0), Point3(0.2, 1, 0)})).face_pairs, 1u);
}

TEST(SelfIntersections, degenerate_and_repeated_faces_are_left_out) {
  TriangleMesh m = two_triangles({Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)},
                                 {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)});  // the same face twice
  EXPECT_EQ(mesh::self_intersections(m).face_pairs, 0u);
  m.vertices.emplace_back(0.2, 0.2, -1);
  m.vertices.emplace_back(0.2, 0.2, 1);
  m.vertices.emplace_back(0.2, 0.2, 2);
  m.triangles.push_back({6, 7, 8});  // collinear: a segment through the face, left out
  EXPECT_EQ(mesh::self_intersections(m).face_pairs, 0u);
}

// With face flags only the pairs with a flagged face are looked for, each once.
TEST(SelfIntersections, a_recheck_looks_at_the_flagged_faces_only) {
  TriangleMesh m = two_triangles({Point3(0, 0, 0), Point3(2, 0, 0), Point3(0, 2, 0)},
                                 {Point3(0.5, 0.5, -1), Point3(0.5, 0.5, 1), Point3(3, 3, 0.5)});
  m.vertices.emplace_back(10, 10, 10);
  m.vertices.emplace_back(11, 10, 10);
  m.vertices.emplace_back(10, 11, 10);
  m.triangles.push_back({6, 7, 8});  // far from both
  EXPECT_EQ(mesh::self_intersections(m).face_pairs, 1u);
  const std::vector<char> first = {1, 0, 0}, both = {1, 1, 0}, far = {0, 0, 1};
  EXPECT_EQ(mesh::self_intersections(m, 8, &first).face_pairs, 1u);
  EXPECT_EQ(mesh::self_intersections(m, 8, &both).face_pairs, 1u);
  EXPECT_EQ(mesh::self_intersections(m, 8, &far).face_pairs, 0u);
  const std::vector<char> wrong = {1, 0};
  EXPECT_THROW((void)mesh::self_intersections(m, 8, &wrong), InvalidInput);
}

// The flagged search prefilters the other faces on a grid sized by the flagged ones: a big
// face spanning many cells of a fine grid, and small faces against a coarse one, are still
// all found.
TEST(SelfIntersections, a_recheck_finds_every_pair_whatever_the_face_sizes) {
  TriangleMesh m = uv_sphere(40, 60);  // small faces
  const std::size_t sphere_faces = m.triangles.size();
  const auto first = static_cast<Index>(m.vertices.size());
  m.vertices.emplace_back(-3, -3, 0.3);
  m.vertices.emplace_back(3, -3, 0.3);
  m.vertices.emplace_back(0, 3, 0.3);
  m.triangles.push_back({first, first + 1, first + 2});  // one big face across the sphere
  const std::size_t all = mesh::self_intersections(m).face_pairs;
  ASSERT_GE(all, 60u);  // at least once around the circle where the plane cuts the sphere
  std::vector<char> big(m.triangles.size(), 0), small(m.triangles.size(), 0);
  big.back() = 1;
  for (std::size_t f = 0; f < sphere_faces; ++f) small[f] = 1;
  EXPECT_EQ(mesh::self_intersections(m, 8, &big).face_pairs, all);
  EXPECT_EQ(mesh::self_intersections(m, 8, &small).face_pairs, all);
  // Only the faces above the plane: the pairs of the ring's upper half.
  std::vector<char> upper(m.triangles.size(), 0);
  std::size_t upper_faces = 0;
  for (std::size_t f = 0; f < sphere_faces; ++f) {
    bool above = true;
    for (const Index v : m.triangles[f]) above = above && m.vertices[v].z() > 0.3;
    upper[f] = above ? 1 : 0;
    upper_faces += upper[f];
  }
  ASSERT_GT(upper_faces, 0u);
  EXPECT_EQ(mesh::self_intersections(m, 8, &upper).face_pairs, 0u);  // none of them reaches the plane
}

// Faces lying exactly in one plane (a flat region of a result, or of a CAD mesh) are decided
// by separating planes in interval arithmetic: the answers must be those of the exact
// triangle test, touching and overlapping included.
TEST(SelfIntersections, triangles_in_one_plane_read_as_the_exact_test_reads_them) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(0, 6);
  // z = 0, and a tilted plane z = x + 2 y that integer coordinates keep exact.
  for (const bool tilted : {false, true}) {
    int meeting = 0, apart = 0;
    for (int trial = 0; trial < 400; ++trial) {
      std::array<Point3, 6> corners;
      for (auto& p : corners) {
        const double x = coordinate(random), y = coordinate(random);
        p = Point3(x, y, tilted ? x + 2 * y : 0.0);
      }
      const Kernel::Triangle_3 a(corners[0], corners[1], corners[2]), b(corners[3], corners[4], corners[5]);
      if (a.is_degenerate() || b.is_degenerate()) continue;
      bool shares = false;  // a common corner is a shared vertex once welded: another case
      for (int i = 0; i < 3; ++i)
        for (int j = 3; j < 6; ++j) shares = shares || corners[i] == corners[j];
      if (shares) continue;
      const bool expected = CGAL::do_intersect(a, b);
      (expected ? meeting : apart) += 1;
      const auto found = mesh::self_intersections(
          two_triangles({corners[0], corners[1], corners[2]}, {corners[3], corners[4], corners[5]}));
      ASSERT_EQ(found.face_pairs, expected ? 1u : 0u)
          << "trial " << trial << (tilted ? " (tilted plane)" : " (z = 0)");
    }
    // Both outcomes occur often enough to mean something (touching corners and edges included).
    EXPECT_GT(meeting, 50);
    EXPECT_GT(apart, 50);
  }
}

TEST(SelfIntersections, a_flat_grid_has_none_and_a_flap_folded_onto_it_is_found) {
  TriangleMesh grid;
  constexpr int n = 60;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) grid.vertices.emplace_back(i, j, 0);
  auto at = [](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      grid.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      grid.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  EXPECT_EQ(mesh::self_intersections(grid).face_pairs, 0u);
  // A flap hinged on the border edge (0,0)-(1,0) and folded flat back over the grid's first
  // two faces: it overlaps both (it shares the edge with the first, a vertex with the second).
  grid.vertices.emplace_back(0.5, 0.6, 0);
  grid.triangles.push_back({at(1, 0), at(0, 0), static_cast<Index>(grid.vertices.size() - 1)});
  const auto folded = mesh::self_intersections(grid);
  EXPECT_EQ(folded.face_pairs, 2u);
  EXPECT_EQ(folded.faces, 3u);
}
