// simplify: a mesh comes down to about the vertex count asked, with its topology, keeping its
// tips where a uniform coarsening would cut them.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/remesh.h"
#include "envcrust/topology.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace envcrust;

namespace {

// Distance of p from the fixture torus (R = 1, r = 0.4).
double off_torus(const Point3& p) {
  const double ring = std::hypot(p.x(), p.y()) - 1.0;
  return std::abs(std::hypot(ring, p.z()) - 0.4);
}

void expect_same_topology(const TriangleMesh& a, const TriangleMesh& b) {
  const auto ta = topology::analyze_topology(a), tb = topology::analyze_topology(b);
  EXPECT_TRUE(tb.is_manifold());
  EXPECT_EQ(tb.euler_characteristic, ta.euler_characteristic);
  EXPECT_EQ(tb.boundary_loops.size(), ta.boundary_loops.size());
  EXPECT_EQ(tb.components.size(), ta.components.size());
  EXPECT_EQ(tb.is_orientable, ta.is_orientable);
}

}  // namespace

TEST(Simplify, brings_a_torus_to_the_count_asked_on_its_surface) {
  const TriangleMesh torus = fixtures::torus(200, 80);  // 16,000 vertices
  const auto r = remesh::simplify(torus, {.target_vertices = 1600});
  ASSERT_TRUE(r.stats.is_simplified) << (r.warnings.empty() ? "" : r.warnings[0]);
  EXPECT_EQ(r.stats.vertices_before, 16000u);
  EXPECT_EQ(r.stats.vertices_after, r.mesh.vertices.size());
  EXPECT_GT(r.mesh.vertices.size(), 1400u);
  EXPECT_LT(r.mesh.vertices.size(), 1800u);
  expect_same_topology(torus, r.mesh);
  double farthest = 0;
  for (const auto& t : r.mesh.triangles) {
    const Point3 &a = r.mesh.vertices[t[0]], &b = r.mesh.vertices[t[1]], &c = r.mesh.vertices[t[2]];
    farthest = std::max({farthest, off_torus(a), off_torus(CGAL::centroid(a, b, c))});
  }
  // Edges of about 0.1 on a tube of radius 0.4: chords sag by 0.1^2 / (8 * 0.4) = 0.003.
  EXPECT_LT(farthest, 0.01);
}

// A thin spike on a flat square: the quadric error of collapsing its tip is its height, so
// the tip stays while the flat part goes. (Edges of one length at this count, about 0.05, are
// longer than the spike is wide.)
TEST(Simplify, keeps_a_thin_spike_that_uniform_edges_would_cut) {
  constexpr double height = 0.3, width = 0.03;
  const TriangleMesh spiked = fixtures::grid_mesh(80, 80, [](double u, double v) {
    const double r2 = (u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5);
    return Point3(u, v, height * std::exp(-r2 / (width * width)));
  }, fixtures::Glue::None);
  const auto r = remesh::simplify(spiked, {.target_vertices = 400});
  ASSERT_TRUE(r.stats.is_simplified);
  EXPECT_LT(r.mesh.vertices.size(), 500u);
  expect_same_topology(spiked, r.mesh);
  double top = 0;
  for (const Point3& p : r.mesh.vertices) top = std::max(top, p.z());
  EXPECT_GT(top, 0.95 * height);
  // The border stays on the square's border.
  const auto t = topology::analyze_topology(r.mesh);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  for (const Index v : t.boundary_loops[0].vertices) {
    const Point3& p = t.points[v];
    EXPECT_LT(std::min({std::abs(p.x()), std::abs(1 - p.x()), std::abs(p.y()), std::abs(1 - p.y())}), 1e-12) << p;
  }
}

TEST(Simplify, keeps_a_moebius_band_non_orientable) {
  const TriangleMesh band = fixtures::moebius(400, 40);  // 16,000 vertices
  const auto r = remesh::simplify(band, {.target_vertices = 1500});
  ASSERT_TRUE(r.stats.is_simplified) << (r.warnings.empty() ? "" : r.warnings[0]);
  expect_same_topology(band, r.mesh);
  EXPECT_FALSE(topology::analyze_topology(r.mesh).is_orientable);
  // The seam keeps its 2 x 41 vertices; the rest comes down to the count.
  EXPECT_LT(r.mesh.vertices.size(), 1800u);
}

// Two tubes one inside the other, 0.01 apart: the outer one's coarse faces, cut as chords
// across its curve, would pass through the inner one (a first run crosses at about 300 pairs
// of faces at this count). The crossing places are held at the input's resolution instead.
TEST(Simplify, holds_the_input_where_a_coarse_surface_would_pass_through_itself) {
  auto tube = [](double r) {
    return fixtures::grid_mesh(120, 60, [r](double u, double v) {
      const double a = fixtures::kTwoPi * u, b = fixtures::kTwoPi * v;
      return Point3((1 + r * std::cos(b)) * std::cos(a), (1 + r * std::cos(b)) * std::sin(a), r * std::sin(b));
    }, fixtures::Glue::Periodic, fixtures::Glue::Periodic);
  };
  TriangleMesh nested = tube(0.4);
  const TriangleMesh inner = tube(0.39);
  const auto offset = static_cast<Index>(nested.vertices.size());
  nested.vertices.insert(nested.vertices.end(), inner.vertices.begin(), inner.vertices.end());
  for (const auto& t : inner.triangles) nested.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  ASSERT_EQ(mesh::self_intersections(nested, 0).face_pairs, 0u);

  const auto r = remesh::simplify(nested, {.target_vertices = 1000});
  ASSERT_TRUE(r.stats.is_simplified) << (r.warnings.empty() ? "" : r.warnings[0]);
  EXPECT_EQ(mesh::self_intersections(r.mesh, 0).face_pairs, 0u);
  EXPECT_GT(r.stats.vertices_held, 0u);
  EXPECT_LT(r.mesh.vertices.size(), nested.vertices.size());
  expect_same_topology(nested, r.mesh);
}

TEST(Simplify, gives_back_a_mesh_already_coarse_enough) {
  const TriangleMesh torus = fixtures::torus();  // 288 vertices
  const auto r = remesh::simplify(torus, {.target_vertices = 288});
  EXPECT_FALSE(r.stats.is_simplified);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_EQ(r.mesh.vertices, torus.vertices);
  EXPECT_EQ(r.mesh.triangles, torus.triangles);
}

TEST(Simplify, skips_a_mesh_that_is_no_manifold) {
  TriangleMesh m = fixtures::square(10);
  const Index apex = static_cast<Index>(m.vertices.size());
  m.vertices.emplace_back(0.05, 0.05, 1.0);
  m.triangles.push_back({m.triangles[0][0], m.triangles[0][2], apex});  // a third face on a diagonal
  const auto r = remesh::simplify(m, {.target_vertices = 20});
  EXPECT_FALSE(r.stats.is_simplified);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0], "simplification skipped: the mesh is not a manifold (1 non-manifold edges, 0 non-manifold vertices)");
  EXPECT_EQ(r.mesh.triangles.size(), m.triangles.size());
}

TEST(Simplify, refuses_a_target_of_zero) {
  try {
    (void)remesh::simplify(fixtures::square(4), {});
    FAIL() << "no exception";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "SimplifyOptions::target_vertices must be positive (got 0)");
  }
}
