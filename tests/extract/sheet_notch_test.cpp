// close_border_notches on a grid square whose rim lies on its boundary curve: a notch cut into
// the rim is closed back to the curve with the topology kept; a notch too wide is left.
#include "envcrust/topology.h"

#include "sheet_projection.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace envcrust;
using namespace envcrust::extract;

namespace {

// A 40 x 40 grid of 0.05 cells over [0, 2]^2 in z = 0 without the cells whose centre lies
// within `radius` of (1, 2) (a half-disc notch in the top edge).
TaggedMesh notched_square(double radius) {
  constexpr int n = 40;
  constexpr double h = 0.05;
  auto id = [](int i, int j) { return static_cast<Index>(j * (n + 1) + i); };
  TaggedMesh t;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) t.mesh.vertices.emplace_back(i * h, j * h, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (std::hypot((i + 0.5) * h - 1.0, (j + 0.5) * h - 2.0) < radius) continue;
      t.mesh.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.mesh.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      t.face_dot.push_back(1.0);
      t.face_dot.push_back(1.0);
    }
  return t;
}

// The square's outline as a boundary curve, counter-clockwise, every 0.02.
envelope::SurfaceSamples square_boundary() {
  envelope::SurfaceSamples s;
  BoundaryCurve c;
  const double corners[4][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  for (int k = 0; k < 4; ++k) {
    const double* a = corners[k];
    const double* b = corners[(k + 1) % 4];
    const Vector3 t((b[0] - a[0]) / 2, (b[1] - a[1]) / 2, 0);
    for (int q = 0; q < 100; ++q) {
      BoundaryVertex v;
      v.position = Point3(a[0] + (b[0] - a[0]) * q / 100.0, a[1] + (b[1] - a[1]) * q / 100.0, 0);
      v.tangent = t;
      v.normal = Vector3(0, 0, 1);
      v.conormal = Vector3(t.y(), -t.x(), 0);
      v.is_corner = q == 0;
      v.conormal_next = v.conormal;
      c.vertices.push_back(v);
    }
  }
  s.boundary.push_back(c);
  return s;
}

double farthest_border_vertex_from_square_outline(const TriangleMesh& m) {
  double worst = 0.0;
  for (const auto& loop : topology::boundary_loops(m))
    for (Index v : loop.vertices) {
      const Point3& p = m.vertices[v];
      const double d = std::min({std::abs(p.x()), std::abs(p.x() - 2), std::abs(p.y()), std::abs(p.y() - 2)});
      worst = std::max(worst, d);
    }
  return worst;
}

TEST(SheetNotches, ANotchInTheRimIsClosedBackToTheCurve) {
  TaggedMesh t = notched_square(0.3);
  const auto before = topology::analyze_topology(t.mesh);
  ASSERT_EQ(before.boundary_loops.size(), 1u);
  ASSERT_GT(farthest_border_vertex_from_square_outline(t.mesh), 0.25);
  const std::size_t closed = close_border_notches(t, square_boundary(), 0.01, 0.1, 1.0);
  EXPECT_EQ(closed, 1u);
  const auto after = topology::analyze_topology(t.mesh);
  EXPECT_EQ(after.euler_characteristic, 1);
  EXPECT_EQ(after.boundary_loops.size(), 1u);
  EXPECT_EQ(after.misoriented_edges, 0u);
  EXPECT_TRUE(after.is_manifold());
  EXPECT_LT(farthest_border_vertex_from_square_outline(t.mesh), 1e-9);  // the whole border on the curve
  // The patch lies in the plane of the square (faired between the notch and the curve).
  for (const Point3& p : t.mesh.vertices) EXPECT_NEAR(p.z(), 0.0, 1e-6);
}

TEST(SheetNotches, ANotchWiderThanAllowedStays) {
  TaggedMesh t = notched_square(0.3);
  const std::size_t faces = t.mesh.triangles.size();
  EXPECT_EQ(close_border_notches(t, square_boundary(), 0.01, 0.1, 0.4), 0u);  // the notch spans 0.6
  EXPECT_EQ(close_border_notches(t, square_boundary(), 0.01, 0.5, 1.0), 0u);  // and reaches 0.3 in
  EXPECT_EQ(t.mesh.triangles.size(), faces);
}

// The border steps back along the curve beside the notch (a vertex two before it moved past
// the last one on the curve, as a cut and its disc can leave it): which way the border runs
// is read over several vertices either side, so the notch is still closed.
TEST(SheetNotches, ABorderSteppingBackBesideTheNotchIsStillClosed) {
  TaggedMesh t = notched_square(0.3);
  // The top edge's vertices on the border left of the notch: the last one on the curve (u),
  // and the one two before it, moved just past u.
  const auto loops = topology::boundary_loops(t.mesh);
  ASSERT_EQ(loops.size(), 1u);
  double last_x = -1.0;
  for (const Index v : loops[0].vertices) {
    const Point3& p = t.mesh.vertices[v];
    if (p.y() == 2.0 && p.x() < 1.0) last_x = std::max(last_x, p.x());
  }
  ASSERT_GT(last_x, 0.5);
  Point3* moved = nullptr;
  for (Point3& p : t.mesh.vertices)
    if (p.y() == 2.0 && std::abs(p.x() - (last_x - 0.1)) < 1e-9) moved = &p;
  ASSERT_NE(moved, nullptr);
  *moved = Point3(last_x + 0.01, 2.0, 0.0);
  EXPECT_EQ(close_border_notches(t, square_boundary(), 0.01, 0.1, 1.0), 1u);
  const auto after = topology::analyze_topology(t.mesh);
  EXPECT_EQ(after.euler_characteristic, 1);
  EXPECT_EQ(after.boundary_loops.size(), 1u);
  EXPECT_LT(farthest_border_vertex_from_square_outline(t.mesh), 1e-9);
}

}  // namespace
