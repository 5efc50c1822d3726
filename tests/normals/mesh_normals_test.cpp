// Tests of mesh_vertex_normal_lines: exact on a tessellated sphere, sign-free on a Moebius
// band, index checks.
#include "angle_stats.h"

#include "envcrust/errors.h"
#include "envcrust/normals.h"
#include "envcrust/surfaces.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <boost/iterator/counting_iterator.hpp>

#include <gtest/gtest.h>

#include <iostream>

namespace envcrust {
namespace {

// Area weighting is first-order accurate on irregular vertex stars: the error shrinks
// linearly with the grid step and is largest on the ring next to a pole, where the grid's
// slivers meet. Measured (radians): default tessellation (14k vertices) mean 6.4e-4, p95
// 2.1e-3, max 6.2e-3 (pole ring); 720 x 360 grid (258k vertices) mean 4.7e-5, p95 1.6e-4,
// max 1.5e-3 (pole ring).
TEST(MeshVertexNormalLines, SphereIsExact) {
  const auto sphere = surfaces::make_builtin("sphere");
  surfaces::TessellationOptions fine;
  fine.nu = 720;
  fine.nv = 360;
  for (const auto& options : {surfaces::TessellationOptions{}, fine}) {
    const TriangleMesh mesh = surfaces::tessellate(*sphere, options);
    const auto n = normals::mesh_vertex_normal_lines(mesh);
    ASSERT_EQ(n.size(), mesh.vertices.size());
    std::vector<double> err;
    double max_off_pole = 0;
    int outward = 0;
    for (std::size_t v = 0; v < n.size(); ++v) {
      const Vector3 exact = mesh.vertices[v] - CGAL::ORIGIN;
      const double rad = test::line_angle_deg(n[v], exact) * std::numbers::pi / 180;
      err.push_back(rad);
      if (std::abs(mesh.vertices[v].z()) < 0.999) max_off_pole = std::max(max_off_pole, rad);
      if (CGAL::scalar_product(n[v], exact) > 0) ++outward;
    }
    const auto s = test::angle_stats(err);
    std::cout << "sphere mesh (" << mesh.vertices.size() << " vertices): mean " << s.mean
              << " p95 " << s.p95 << " max " << s.max << " rad, max off the pole caps "
              << max_off_pole << "\n";
    EXPECT_LT(s.mean, 1e-3);
    if (options.nu) {
      EXPECT_LT(max_off_pole, 1e-3);
      EXPECT_LT(s.max, 2e-3);
    } else {
      EXPECT_LT(s.max, 1e-2);
    }
    // A consistently oriented mesh gets consistently signed normals.
    EXPECT_TRUE(outward == 0 || outward == static_cast<int>(n.size()));
  }
}

// Exact normal lines at the vertices by inverting the parametrization: u = atan2(y, x),
// v = (r - 1) cos(u/2) + z sin(u/2). Measured (degrees): default tessellation (4200 vertices)
// mean 0.63, p95 3.2, max 5.2; 400 x 40 grid (16400 vertices) mean 0.02, p95 0.15, max 0.71.
// The largest errors sit on boundary vertices (one-sided stars) of the coarse grid.
TEST(MeshVertexNormalLines, MoebiusIsNonOrientableButWorks) {
  const auto moebius = surfaces::make_builtin("moebius");
  surfaces::TessellationOptions grid;
  grid.nu = 400;
  grid.nv = 40;
  for (const auto& options : {surfaces::TessellationOptions{}, grid}) {
    const TriangleMesh mesh = surfaces::tessellate(*moebius, options);
    const auto n = normals::mesh_vertex_normal_lines(mesh);
    std::vector<double> err;
    for (std::size_t v = 0; v < n.size(); ++v) {
      ASSERT_NEAR(n[v].squared_length(), 1.0, 1e-9);
      const Point3& p = mesh.vertices[v];
      const double r = std::hypot(p.x(), p.y());
      const double pu = std::atan2(p.y(), p.x());  // u, or u - 2 pi (then v -> -v)
      const double w = (r - 1) * std::cos(pu / 2) + p.z() * std::sin(pu / 2);
      const auto exact = moebius->point_at(pu < 0 ? pu + 2 * std::numbers::pi : pu,
                                           pu < 0 ? -w : w);
      ASSERT_LT(CGAL::squared_distance(exact.position, p), 1e-12);
      err.push_back(test::line_angle_deg(n[v], exact.normal));
    }
    const auto s = test::angle_stats(err);
    std::cout << "moebius mesh (" << n.size() << " vertices): mean " << s.mean << " p95 "
              << s.p95 << " max " << s.max << " degrees\n";
    EXPECT_LT(s.mean, options.nu ? 0.05 : 1.0);
    EXPECT_LT(s.max, options.nu ? 1.0 : 6.0);
  }
}

TEST(MeshVertexNormalLines, IsolatedVertexAndBadIndex) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
  mesh.triangles = {{0, 1, 2}};
  const auto n = normals::mesh_vertex_normal_lines(mesh);
  EXPECT_EQ(n[0], Vector3(0, 0, 1));
  EXPECT_EQ(n[3], Vector3(0, 0, 0));
  mesh.triangles.push_back({0, 1, 7});
  try {
    (void)normals::mesh_vertex_normal_lines(mesh);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "face 1 has vertex index 7, but the mesh has 4 vertices");
  }
}

TEST(MeshVertexNormalLines, FlippedFacesDoNotCancel) {
  // A fold-free fan whose faces disagree in orientation: summed normals would cancel.
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 3, 2}, {0, 3, 4}, {0, 1, 4}};
  const auto n = normals::mesh_vertex_normal_lines(mesh);
  EXPECT_NEAR(std::abs(n[0].z()), 1.0, 1e-12);
}

}  // namespace
}  // namespace envcrust
