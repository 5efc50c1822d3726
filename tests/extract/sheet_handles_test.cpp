// cut_local_handles on a plane with a handle built here: the balls around the handle are not
// discs and go; the plane far from it stays; a plane without a handle (but with a small hole
// of its own) is left as it was. fill_with_patch closes the holes such a cut leaves.
#include "envcrust/topology.h"

#include "sheet_mesh.h"

#include <gtest/gtest.h>

#include <numbers>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>

using namespace envcrust;
using namespace envcrust::extract;

namespace {

Index grid_id(int i, int j) { return static_cast<Index>(j * 61 + i); }

// A 60 x 60 grid of 0.1 cells over [0, 6]^2 in z = 0, without the cells where `skip(i, j)`.
template <class Skip>
TaggedMesh grid_plane(Skip skip) {
  constexpr int n = 60;
  constexpr double h = 0.1;
  TaggedMesh t;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) t.mesh.vertices.emplace_back(i * h, j * h, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (skip(i, j)) continue;
      t.mesh.triangles.push_back({grid_id(i, j), grid_id(i + 1, j), grid_id(i + 1, j + 1)});
      t.mesh.triangles.push_back({grid_id(i, j), grid_id(i + 1, j + 1), grid_id(i, j + 1)});
    }
  return t;
}

// The grid plane with the 4 x 4-cell squares at cells [18, 22) x [28, 32) and [38, 42) x
// [28, 32) cut out; with `handle`, a tube of 16 rings joins the two square holes' rims over
// the plane (the rims' vertices reused).
TaggedMesh plane_with_holes(bool handle) {
  TaggedMesh t =
      grid_plane([](int i, int j) { return j >= 28 && j < 32 && ((i >= 18 && i < 22) || (i >= 38 && i < 42)); });
  const auto id = grid_id;
  if (handle) {
    // The rim of the square hole starting at cell (i0, 28), counter-clockwise: 16 vertices.
    auto rim = [&](int i0) {
      std::vector<Index> r;
      for (int k = 0; k < 4; ++k) r.push_back(id(i0 + k, 28));
      for (int k = 0; k < 4; ++k) r.push_back(id(i0 + 4, 28 + k));
      for (int k = 0; k < 4; ++k) r.push_back(id(i0 + 4 - k, 32));
      for (int k = 0; k < 4; ++k) r.push_back(id(i0, 32 - k));
      return r;
    };
    const std::vector<Index> a = rim(18), b = rim(38);
    constexpr int rings = 16;
    std::vector<std::vector<Index>> ring(rings + 1);
    ring[0] = a;
    ring[rings] = b;
    for (int r = 1; r < rings; ++r) {
      const double s = static_cast<double>(r) / rings;
      for (std::size_t k = 0; k < a.size(); ++k) {
        const Point3 p = t.mesh.vertices[a[k]], q = t.mesh.vertices[b[k]];
        ring[r].push_back(static_cast<Index>(t.mesh.vertices.size()));
        t.mesh.vertices.emplace_back(p.x() + s * (q.x() - p.x()), p.y() + s * (q.y() - p.y()),
                                     1.5 * std::sin(3.141592653589793 * s));
      }
    }
    for (int r = 0; r < rings; ++r)
      for (std::size_t k = 0; k < a.size(); ++k) {
        const std::size_t k1 = (k + 1) % a.size();
        t.mesh.triangles.push_back({ring[r][k], ring[r + 1][k], ring[r + 1][k1]});
        t.mesh.triangles.push_back({ring[r][k], ring[r + 1][k1], ring[r][k1]});
      }
  }
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

// The grid plane with one 2 x 2-cell hole at cells [29, 31) x [29, 31) and a finger on its rim:
// a square tube of 8 rings 0.1 apart rising to z 0.7, capped by a fan to an apex at z 0.8.
// A disc, like a toe: thinner than the balls below, but shorter than twice their radius.
TaggedMesh plane_with_a_finger() {
  constexpr double h = 0.1;
  TaggedMesh t = grid_plane([](int i, int j) { return i >= 29 && i < 31 && j >= 29 && j < 31; });
  const auto id = grid_id;
  const std::vector<Index> rim = {id(29, 29), id(30, 29), id(31, 29), id(31, 30),
                                  id(31, 31), id(30, 31), id(29, 31), id(29, 30)};
  std::vector<Index> below = rim;
  for (int r = 1; r <= 7; ++r) {
    std::vector<Index> ring;
    for (const Index v : rim) {
      ring.push_back(static_cast<Index>(t.mesh.vertices.size()));
      const Point3 p = t.mesh.vertices[v];
      t.mesh.vertices.emplace_back(p.x(), p.y(), r * h);
    }
    for (std::size_t k = 0; k < rim.size(); ++k) {
      const std::size_t k1 = (k + 1) % rim.size();
      t.mesh.triangles.push_back({below[k], below[k1], ring[k1]});
      t.mesh.triangles.push_back({below[k], ring[k1], ring[k]});
    }
    below = ring;
  }
  const auto apex = static_cast<Index>(t.mesh.vertices.size());
  t.mesh.vertices.emplace_back(3.0, 3.0, 0.8);
  for (std::size_t k = 0; k < rim.size(); ++k) t.mesh.triangles.push_back({below[k], below[(k + 1) % rim.size()], apex});
  t.face_dot.assign(t.mesh.triangles.size(), -1.0);
  return t;
}

}  // namespace

TEST(CutLocalHandles, the_test_mesh_has_one_handle) {
  const auto t = topology::analyze_topology(plane_with_holes(true).mesh);
  ASSERT_TRUE(t.is_manifold());
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, -1);  // genus 1, one border loop (the plane's rim)
  EXPECT_EQ(t.boundary_loops.size(), 1u);
}

TEST(CutLocalHandles, removes_the_balls_around_the_handle_and_keeps_the_plane) {
  TaggedMesh m = plane_with_holes(true);
  const std::size_t before = m.mesh.triangles.size();
  const HandleCutStats stats = cut_local_handles(m, 0.8);
  EXPECT_GT(stats.balls, 0u);
  EXPECT_EQ(m.face_dot.size(), m.mesh.triangles.size());
  const auto t = topology::analyze_topology(m.mesh);
  EXPECT_TRUE(t.is_manifold());
  for (const auto& c : t.components) {
    ASSERT_TRUE(c.genus.has_value());
    EXPECT_EQ(*c.genus, 0) << c.faces;
  }
  // Only faces near the handle go: the plane's corners stay, and most of the plane.
  EXPECT_LT(before - m.mesh.triangles.size(), before / 2);
  std::size_t near_corner = 0;
  for (const auto& f : m.mesh.triangles) near_corner += m.mesh.vertices[f[0]].x() < 1.0 && m.mesh.vertices[f[0]].y() < 1.0;
  EXPECT_EQ(near_corner, 200u);  // the 10 x 10 cells of [0, 1]^2, two triangles each
}

TEST(CutLocalHandles, keeps_a_plane_whose_small_holes_lie_inside_the_balls) {
  TaggedMesh m = plane_with_holes(false);
  const TaggedMesh original = m;
  const HandleCutStats stats = cut_local_handles(m, 0.8);  // each 0.4-wide hole fits in a ball
  EXPECT_EQ(stats.balls, 0u);
  EXPECT_EQ(stats.faces_removed, 0u);
  EXPECT_EQ(m.mesh.triangles, original.mesh.triangles);
}

// Balls of radius 0.5 around the finger's side wrap around it (its girth is 0.8): annuli. The
// balls of radius 1.5 take in the fingertip and are discs, so nothing is removed.
TEST(CutLocalHandles, keeps_a_finger_thinner_than_the_balls) {
  TaggedMesh m = plane_with_a_finger();
  const auto t = topology::analyze_topology(m.mesh);
  ASSERT_TRUE(t.is_manifold());
  ASSERT_EQ(t.euler_characteristic, 1);  // a disc: the plane, its hole closed by the finger
  const TaggedMesh original = m;
  const HandleCutStats stats = cut_local_handles(m, 0.5);
  EXPECT_EQ(stats.balls, 0u);
  EXPECT_EQ(m.mesh.triangles, original.mesh.triangles);
}

namespace {

std::vector<Point3> plane_rim_points() {
  std::vector<Point3> rim;
  for (int k = 0; k <= 60; ++k) {
    const double t = 0.1 * k;
    rim.insert(rim.end(), {Point3(t, 0, 0), Point3(t, 6, 0), Point3(0, t, 0), Point3(6, t, 0)});
  }
  return rim;
}

double total_area(const TriangleMesh& m) {
  double area = 0;
  for (const auto& f : m.triangles)
    area += std::sqrt(Kernel::Triangle_3(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]).squared_area());
  return area;
}

}  // namespace

// A 1 x 1 hole in the plane: the patch is flat, covers the hole exactly, and its new vertices
// sit inside the hole with edges about as long as the rim's.
TEST(FillWithPatch, closes_a_square_hole_with_a_flat_disc_of_even_triangles) {
  TaggedMesh m = grid_plane([](int i, int j) { return i >= 25 && i < 35 && j >= 25 && j < 35; });
  m.face_dot.assign(m.mesh.triangles.size(), -1.0);
  const std::size_t grid_vertices = m.mesh.vertices.size();
  EXPECT_EQ(fill_loops_away_from_boundary(m, plane_rim_points(), 0.05, HoleFill::Patch), 1u);
  EXPECT_EQ(m.face_dot.size(), m.mesh.triangles.size());
  const auto t = topology::analyze_topology(m.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);  // the plane's rim only
  EXPECT_NEAR(total_area(m.mesh), 36.0, 1e-9);
  ASSERT_GT(m.mesh.vertices.size(), grid_vertices + 20);  // refined, not just the rim's 40
  double longest = 0;
  for (std::size_t v = grid_vertices; v < m.mesh.vertices.size(); ++v) {
    const Point3& p = m.mesh.vertices[v];
    EXPECT_NEAR(p.z(), 0.0, 1e-9);
    EXPECT_TRUE(p.x() > 2.5 && p.x() < 3.5 && p.y() > 2.5 && p.y() < 3.5) << p;
  }
  for (const auto& f : m.mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (f[k] >= grid_vertices || f[(k + 1) % 3] >= grid_vertices)
        longest = std::max(longest, std::sqrt(CGAL::squared_distance(m.mesh.vertices[f[k]], m.mesh.vertices[f[(k + 1) % 3]])));
  EXPECT_LT(longest, 0.3);  // rim edges are 0.1
}

// After the handle is cut out, the holes the cut left (away from the plane's rim, the one
// boundary curve) are closed: the plane is one disc again.
TEST(FillWithPatch, closes_the_holes_a_handle_cut_leaves) {
  TaggedMesh m = plane_with_holes(true);
  ASSERT_GT(cut_local_handles(m, 0.8).balls, 0u);
  const auto cut = topology::analyze_topology(m.mesh);
  ASSERT_GT(cut.boundary_loops.size(), 1u);
  EXPECT_EQ(fill_loops_away_from_boundary(m, plane_rim_points(), 0.05, HoleFill::Patch),
            cut.boundary_loops.size() - 1);
  const auto t = topology::analyze_topology(m.mesh);
  EXPECT_TRUE(t.is_manifold());
  ASSERT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
}

// A loop through one vertex twice (two holes touching there) is no disc's rim: refused.
TEST(FillWithPatch, refuses_a_loop_that_passes_a_vertex_twice) {
  TaggedMesh m = grid_plane([](int, int) { return false; });
  m.face_dot.assign(m.mesh.triangles.size(), -1.0);
  const TaggedMesh original = m;
  const std::vector<Index> loop = {grid_id(10, 10), grid_id(11, 10), grid_id(11, 11), grid_id(10, 10),
                                   grid_id(9, 10), grid_id(9, 9)};
  EXPECT_FALSE(fill_with_patch(m, loop));
  EXPECT_EQ(m.mesh.triangles, original.mesh.triangles);
  EXPECT_EQ(m.mesh.vertices.size(), original.mesh.vertices.size());
}

namespace {

// The most faces any vertex of `mesh` has.
int largest_valence(const TriangleMesh& mesh) {
  std::vector<int> faces_at(mesh.vertices.size(), 0);
  for (const auto& f : mesh.triangles)
    for (Index v : f) ++faces_at[v];
  return *std::max_element(faces_at.begin(), faces_at.end());
}

// The grid plane whole again: one manifold disc of its full area, and no vertex with more
// than a dozen faces (a fan from one point over a hole has as many as the hole's border).
void expect_the_whole_plane_with_no_fan(const TriangleMesh& mesh) {
  const auto t = topology::analyze_topology(mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_NEAR(total_area(mesh), 36.0, 1e-9);
  EXPECT_LE(largest_valence(mesh), 12);
}

}  // namespace

// Two 0.5 x 0.5 holes whose corners touch at one vertex: the border passes that vertex twice.
// Each is closed with its own flat disc (no fan from one point over both): the plane is one
// manifold disc again, of its full area, and no vertex takes more than a dozen faces.
TEST(FillWithPatch, closes_holes_that_touch_at_a_vertex_each_with_its_own_disc) {
  TaggedMesh m = grid_plane([](int i, int j) {
    return (i >= 20 && i < 25 && j >= 20 && j < 25) || (i >= 25 && i < 30 && j >= 25 && j < 30);
  });
  m.face_dot.assign(m.mesh.triangles.size(), -1.0);
  const std::size_t filled = fill_loops_away_from_boundary(m, plane_rim_points(), 0.05, HoleFill::Patch);
  EXPECT_GE(filled, 1u);
  expect_the_whole_plane_with_no_fan(m.mesh);
}

// The same two holes walked as one loop through their common vertex (as a cut's border can
// come): fill_hole closes each of its two cycles with a disc of its own.
TEST(FillHole, closes_a_loop_through_one_vertex_twice_cycle_by_cycle) {
  TaggedMesh m = grid_plane([](int i, int j) {
    return (i >= 20 && i < 25 && j >= 20 && j < 25) || (i >= 25 && i < 30 && j >= 25 && j < 30);
  });
  m.face_dot.assign(m.mesh.triangles.size(), -1.0);
  std::vector<Index> loop;
  auto walk = [&](int i0, int j0, int di, int dj, int steps) {
    for (int s = 0; s < steps; ++s) loop.push_back(grid_id(i0 + s * di, j0 + s * dj));
  };
  walk(20, 20, 1, 0, 5);   // the first hole's bottom, then its right side up to (25, 25)
  walk(25, 20, 0, 1, 5);
  walk(25, 25, 1, 0, 5);   // round the second hole back to (25, 25)
  walk(30, 25, 0, 1, 5);
  walk(30, 30, -1, 0, 5);
  walk(25, 30, 0, -1, 5);
  walk(25, 25, -1, 0, 5);  // the first hole's top and left side
  walk(20, 25, 0, -1, 5);
  ASSERT_EQ(loop.size(), 40u);
  fill_hole(m, loop, edges_among(m.mesh, {loop}));
  expect_the_whole_plane_with_no_fan(m.mesh);
}

// A long wavy loop alone (a crown: 400 vertices round a unit circle, up and down 0.3 twelve
// times), as long cut holes come, once as it is (CGAL's triangulation) and once with every
// chord between two of its vertices taken by the sheet already (no triangulation of the
// loop's own vertices can be used: the rings shrunk from the loop close it): each time a
// disc whose only border is the loop, with no vertex of high valence (a fan from the centre
// had 400) and within the loop's reach (fairing overshoots the waves a little).
TEST(FillWithPatch, closes_a_long_wavy_loop_with_an_even_disc_also_when_every_chord_is_taken) {
  constexpr int n = 400;
  TaggedMesh crown;
  std::vector<Index> loop;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    loop.push_back(static_cast<Index>(i));
    crown.mesh.vertices.emplace_back(std::cos(a), std::sin(a), 0.3 * std::sin(12 * a));
  }
  std::unordered_set<std::uint64_t> every_chord;
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j)
      if (i != 0 || j != n - 1) every_chord.insert(edge_key(static_cast<Index>(i), static_cast<Index>(j)));
  for (const bool taken : {false, true}) {
    TaggedMesh m = crown;
    ASSERT_TRUE(fill_with_patch(m, loop, taken ? every_chord : std::unordered_set<std::uint64_t>{}));
    EXPECT_EQ(m.face_dot.size(), m.mesh.triangles.size());
    const auto t = topology::analyze_topology(m.mesh);
    EXPECT_TRUE(t.is_manifold()) << taken;
    EXPECT_EQ(t.euler_characteristic, 1) << taken;
    ASSERT_EQ(t.boundary_loops.size(), 1u) << taken;
    EXPECT_EQ(t.boundary_loops[0].vertices.size(), static_cast<std::size_t>(n));
    for (const auto& f : m.mesh.triangles) {
      if (!taken) continue;
      for (int k = 0; k < 3; ++k)
        EXPECT_FALSE(f[k] < n && f[(k + 1) % 3] < n && every_chord.count(edge_key(f[k], f[(k + 1) % 3])));
    }
    EXPECT_LE(largest_valence(m.mesh), 16) << taken;
    for (const Point3& p : m.mesh.vertices) {
      EXPECT_LE(std::hypot(p.x(), p.y()), 1.0 + 1e-9) << taken;
      EXPECT_LE(std::abs(p.z()), 0.6) << taken;
    }
  }
}

// A piece that a cut separated from the rest has only loops away from the boundary curves:
// closing them would make a closed shell, so it goes; the plane, whose rim runs along the
// boundary curve, stays. Without boundary curves (a closed surface) nothing is dropped.
TEST(DropPiecesAwayFromBoundary, drops_a_floating_piece_and_keeps_the_plane) {
  TaggedMesh m = grid_plane([](int, int) { return false; });
  const std::size_t plane_faces = m.mesh.triangles.size();
  // A 1 x 1 square of two triangles 5 above the plane: its loop is 5 from the rim.
  const auto base = static_cast<Index>(m.mesh.vertices.size());
  for (const auto& p : {Point3(2, 2, 5), Point3(3, 2, 5), Point3(3, 3, 5), Point3(2, 3, 5)}) m.mesh.vertices.push_back(p);
  m.mesh.triangles.push_back({base, base + 1, base + 2});
  m.mesh.triangles.push_back({base, base + 2, base + 3});
  m.face_dot.assign(m.mesh.triangles.size(), -1.0);
  TaggedMesh closed_surface = m;
  EXPECT_EQ(drop_pieces_away_from_boundary(closed_surface, {}, 0.05), 0u);
  EXPECT_EQ(closed_surface.mesh.triangles.size(), plane_faces + 2);
  EXPECT_EQ(drop_pieces_away_from_boundary(m, plane_rim_points(), 0.05), 1u);
  EXPECT_EQ(m.mesh.triangles.size(), plane_faces);
  EXPECT_EQ(m.face_dot.size(), plane_faces);
  for (const auto& f : m.mesh.triangles) EXPECT_EQ(m.mesh.vertices[f[0]].z(), 0.0);
}
