// Tests of mesh_boundary_curves on tessellated built-ins (cylinder, square, Moebius) and the
// refusal of non-edge-manifold meshes.
#include "envcrust/boundary.h"
#include "envcrust/errors.h"
#include "envcrust/normals.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envcrust {
namespace {

std::vector<BoundaryCurve> mesh_loops(const std::string& name) {
  const auto surface = surfaces::make_builtin(name);
  const TriangleMesh mesh = surfaces::tessellate(*surface);
  return boundary::mesh_boundary_curves(mesh, normals::mesh_vertex_normal_lines(mesh));
}

void expect_orthonormal(const BoundaryVertex& v) {
  EXPECT_NEAR(v.tangent.squared_length(), 1.0, 1e-9);
  EXPECT_NEAR(v.normal.squared_length(), 1.0, 1e-9);
  EXPECT_NEAR(v.conormal.squared_length(), 1.0, 1e-9);
  EXPECT_NEAR(CGAL::scalar_product(v.tangent, v.normal), 0.0, 1e-9);
  EXPECT_NEAR(CGAL::scalar_product(v.tangent, v.conormal), 0.0, 1e-9);
  EXPECT_NEAR(CGAL::scalar_product(v.normal, v.conormal), 0.0, 1e-9);
}

TEST(MeshBoundaryCurves, CylinderHasTwoLoopsWithAxialConormals) {
  const auto loops = mesh_loops("cylinder");
  ASSERT_EQ(loops.size(), 2u);
  for (const BoundaryCurve& loop : loops) {
    ASSERT_GT(loop.vertices.size(), 20u);
    const double z = loop.vertices.front().position.z();
    EXPECT_NEAR(std::abs(z), 1.0, 1e-9);
    for (const BoundaryVertex& v : loop.vertices) {
      expect_orthonormal(v);
      EXPECT_FALSE(v.is_corner);
      EXPECT_NEAR(v.position.z(), z, 1e-9);
      // Outward conormal: +z on the top circle, -z on the bottom one.
      EXPECT_NEAR(v.conormal.z(), z > 0 ? 1.0 : -1.0, 1e-6);
      // Normal line radial.
      const Vector3 radial(v.position.x(), v.position.y(), 0);
      EXPECT_NEAR(std::abs(CGAL::scalar_product(v.normal, radial)) / std::sqrt(radial.squared_length()),
                  1.0, 1e-6);
    }
  }
}

TEST(MeshBoundaryCurves, SquareHasFourCorners) {
  const auto loops = mesh_loops("square");
  ASSERT_EQ(loops.size(), 1u);
  int corners = 0;
  for (const BoundaryVertex& v : loops[0].vertices) {
    expect_orthonormal(v);
    const double x = v.position.x(), y = v.position.y();
    if (v.is_corner) {
      ++corners;
      EXPECT_NEAR(std::abs(x), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(y), 1.0, 1e-12);
      // The two conormals are the outward normals of the two edges meeting here.
      const Vector3 a = v.conormal, b = v.conormal_next;
      EXPECT_NEAR(CGAL::scalar_product(a, b), 0.0, 1e-12);
      EXPECT_NEAR(a.x() + b.x(), x, 1e-12);
      EXPECT_NEAR(a.y() + b.y(), y, 1e-12);
      EXPECT_NEAR(std::abs(CGAL::scalar_product(b, v.normal)), 0.0, 1e-12);
    } else {
      // On an edge: the conormal is the edge's outward normal.
      if (std::abs(std::abs(x) - 1) < 1e-12) {
      EXPECT_NEAR(v.conormal.x(), x, 1e-12);
    }
      if (std::abs(std::abs(y) - 1) < 1e-12) {
      EXPECT_NEAR(v.conormal.y(), y, 1e-12);
    }
    }
    EXPECT_NEAR(std::abs(v.normal.z()), 1.0, 1e-12);
  }
  EXPECT_EQ(corners, 4);
}

TEST(MeshBoundaryCurves, MoebiusHasOneLoopAgreeingWithTheExactBoundary) {
  const auto surface = surfaces::make_builtin("moebius");
  const auto loops = mesh_loops("moebius");
  ASSERT_EQ(loops.size(), 1u);
  const auto exact = surfaces::boundary_curves(*surface, 0.005);
  ASSERT_EQ(exact.size(), 1u);
  int good = 0;
  const auto& vertices = loops[0].vertices;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const BoundaryVertex& v = vertices[i];
    expect_orthonormal(v);
    EXPECT_FALSE(v.is_corner);
    // Normal lines continue along the loop (the boundary of a Moebius band is an annulus'
    // worth of normals: no flip after the double turn).
    EXPECT_GT(CGAL::scalar_product(v.normal, vertices[(i + 1) % vertices.size()].normal), 0.9);
    double best = 1e9;
    const BoundaryVertex* nearest = nullptr;
    for (const BoundaryVertex& e : exact[0].vertices) {
      const double d = CGAL::squared_distance(e.position, v.position);
      if (d < best) {
        best = d;
        nearest = &e;
      }
    }
    if (CGAL::scalar_product(v.conormal, nearest->conormal) > 0.99) ++good;
  }
  EXPECT_EQ(good, static_cast<int>(vertices.size()));
}

TEST(MeshBoundaryCurves, ClosedMeshHasNoLoop) {
  const auto surface = surfaces::make_builtin("sphere");
  const TriangleMesh mesh = surfaces::tessellate(*surface);
  EXPECT_TRUE(boundary::mesh_boundary_curves(mesh, normals::mesh_vertex_normal_lines(mesh)).empty());
}

TEST(MeshBoundaryCurves, RefusesNonManifoldEdge) {
  TriangleMesh mesh;
  for (int i = 0; i < 41; ++i) mesh.vertices.emplace_back(i, (i * 7) % 5, (i * 3) % 4);
  mesh.triangles = {{0, 1, 2}, {12, 40, 3}, {40, 12, 5}, {12, 6, 40}, {1, 3, 4}};
  const std::vector<Vector3> normals(mesh.vertices.size(), Vector3(0, 0, 1));
  try {
    (void)boundary::mesh_boundary_curves(mesh, normals);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "edge (12, 40) has 3 faces: the mesh is not a surface");
  }
}

TEST(MeshBoundaryCurves, RefusesBadIndexAndNormalCount) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  EXPECT_THROW((void)boundary::mesh_boundary_curves(mesh, {}), InvalidInput);
  mesh.triangles.push_back({0, 1, 9});
  const std::vector<Vector3> normals(3, Vector3(0, 0, 1));
  EXPECT_THROW((void)boundary::mesh_boundary_curves(mesh, normals), InvalidInput);
}

TEST(MeshBoundaryCurves, SingleTriangleHasThreeCorners) {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  const auto loops = boundary::mesh_boundary_curves(mesh, normals::mesh_vertex_normal_lines(mesh));
  ASSERT_EQ(loops.size(), 1u);
  ASSERT_EQ(loops[0].vertices.size(), 3u);
  for (const BoundaryVertex& v : loops[0].vertices) {
    EXPECT_TRUE(v.is_corner);
    // Conormals point away from the triangle's centroid.
    const Vector3 away = v.position - Point3(1.0 / 3, 1.0 / 3, 0);
    EXPECT_GT(CGAL::scalar_product(v.conormal, away), 0);
    EXPECT_GT(CGAL::scalar_product(v.conormal_next, away), 0);
  }
}

}  // namespace
}  // namespace envcrust
