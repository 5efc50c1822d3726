// Tessellations have the surfaces' exact topology and meet the chord-error bound.
#include "mesh_topology.h"

#include "envcrust/errors.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envcrust::surfaces {
namespace {

using testing::mesh_topology;

TEST(Tessellation, every_builtin_has_its_expected_topology_on_a_coarse_grid) {
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    TessellationOptions options;
    options.nu = 24;
    options.nv = 6;
    const auto topology = mesh_topology(tessellate(*surface, options));
    const ExpectedTopology expected = surface->expected_topology();
    EXPECT_EQ(topology.euler_characteristic, expected.euler_characteristic) << name;
    EXPECT_EQ(topology.boundary_loops, static_cast<std::size_t>(expected.boundary_loops)) << name;
    EXPECT_EQ(topology.degenerate_triangles, 0u) << name;
    EXPECT_EQ(topology.non_manifold_edges, 0u) << name;
    if (expected.is_orientable) {
      EXPECT_TRUE(topology.consistently_oriented) << name;
    }
  }
}

TEST(Tessellation, closed_surfaces_and_the_hemisphere_wind_outward) {
  // Signed volume of the closed ones (4/3 pi for the unit sphere), and every hemisphere face
  // turned away from the centre: the renderer's front colour is the outside.
  for (const char* name : {"sphere", "torus"}) {
    const auto mesh = tessellate(*make_builtin(name));
    double volume = 0;
    for (const auto& t : mesh.triangles) {
      const Vector3 a = mesh.vertices[t[0]] - CGAL::ORIGIN, b = mesh.vertices[t[1]] - CGAL::ORIGIN,
                    c = mesh.vertices[t[2]] - CGAL::ORIGIN;
      volume += a * CGAL::cross_product(b, c) / 6;
    }
    EXPECT_GT(volume, 0) << name;
  }
  const auto half = tessellate(*make_builtin("hemisphere"));
  for (const auto& t : half.triangles) {
    const Point3 &a = half.vertices[t[0]], &b = half.vertices[t[1]], &c = half.vertices[t[2]];
    ASSERT_GT(CGAL::cross_product(b - a, c - a) * (CGAL::centroid(a, b, c) - CGAL::ORIGIN), 0);
  }
}

TEST(Tessellation, moebius_has_one_boundary_loop_and_cannot_be_oriented) {
  TessellationOptions options;
  options.nu = 40;
  options.nv = 5;
  const auto topology = mesh_topology(tessellate(*make_builtin("moebius"), options));
  EXPECT_EQ(topology.euler_characteristic, 0);
  EXPECT_EQ(topology.boundary_loops, 1u);
  EXPECT_EQ(topology.boundary_edges, 80u);  // twice the length of either long edge
  EXPECT_FALSE(topology.consistently_oriented);
}

TEST(Tessellation, sphere_collapses_each_pole_to_one_vertex) {
  TessellationOptions options;
  options.nu = 16;
  options.nv = 8;
  const TriangleMesh mesh = tessellate(*make_builtin("sphere"), options);
  EXPECT_EQ(mesh.vertices.size(), 16u * 7u + 2u);
  EXPECT_EQ(mesh.triangles.size(), 2u * 16u * 8u - 2u * 16u);
  EXPECT_EQ(mesh_topology(mesh).euler_characteristic, 2);
}

TEST(Tessellation, cylinder_welds_the_seam) {
  TessellationOptions options;
  options.nu = 32;
  options.nv = 8;
  const TriangleMesh mesh = tessellate(*make_builtin("cylinder-nurbs"), options);
  EXPECT_EQ(mesh.vertices.size(), 32u * 9u);
  const auto topology = mesh_topology(mesh);
  EXPECT_EQ(topology.euler_characteristic, 0);
  EXPECT_EQ(topology.boundary_loops, 2u);
  EXPECT_EQ(topology.boundary_edges, 64u);
}

TEST(Tessellation, default_sphere_meets_the_chord_error_bound) {
  const double rel = 1e-3;
  TessellationOptions options;
  options.max_error_rel_diag = rel;
  const TriangleMesh mesh = tessellate(*make_builtin("sphere"), options);
  const double tol = rel * std::sqrt(12.0);
  double worst_edge = 0;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Point3 mid = CGAL::midpoint(mesh.vertices[t[static_cast<std::size_t>(k)]],
                                        mesh.vertices[t[static_cast<std::size_t>((k + 1) % 3)]]);
      worst_edge = std::max(worst_edge, 1 - std::sqrt((mid - CGAL::ORIGIN).squared_length()));
    }
  }
  EXPECT_LE(worst_edge, tol);
  EXPECT_GT(worst_edge, 0.2 * tol);  // not absurdly over-refined
  EXPECT_EQ(mesh_topology(mesh).euler_characteristic, 2);
}

TEST(Tessellation, default_bound_keeps_every_builtin_under_the_triangle_budget) {
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    const TriangleMesh mesh = tessellate(*surface);
    EXPECT_LE(mesh.triangles.size(), 500000u) << name;
    const auto topology = mesh_topology(mesh);
    EXPECT_EQ(topology.euler_characteristic, surface->expected_topology().euler_characteristic)
        << name;
  }
}

TEST(Tessellation, cusp_apex_is_resolved_by_refinement) {
  TessellationOptions options;
  options.max_error_rel_diag = 1e-4;
  const TriangleMesh mesh = tessellate(*make_builtin("cusp"), options);
  // Profile y = r^(3/2): a chord from the apex to the first ring deviates by 4/27 h^(3/2).
  double first_ring = 1;
  for (const Point3& p : mesh.vertices) {
    const double r = std::hypot(p.x(), p.z());
    if (r > 1e-12) first_ring = std::min(first_ring, r);
  }
  const double diag = bbox_diagonal(*make_builtin("cusp"));
  EXPECT_LE(4.0 / 27.0 * std::pow(first_ring, 1.5), 1e-4 * diag);
}

TEST(Tessellation, rejects_grids_too_coarse_to_weld) {
  TessellationOptions options;
  options.nu = 2;
  options.nv = 4;
  EXPECT_THROW((void)tessellate(*make_builtin("torus"), options), InvalidOptions);
  options.nu = 8;
  options.nv = 0;
  EXPECT_THROW((void)tessellate(*make_builtin("square"), options), InvalidOptions);
}

}  // namespace
}  // namespace envcrust::surfaces
