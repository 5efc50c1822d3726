// Boundary loops: count, spacing, orthonormal frames with outward conormals, corners, linking.
#include "linking.h"

#include "envcrust/errors.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

namespace envcrust::surfaces {
namespace {

double distance(const Point3& a, const Point3& b) {
  return std::sqrt(CGAL::squared_distance(a, b));
}

TEST(BoundaryCurves, every_builtin_has_its_expected_number_of_loops_and_orthonormal_frames) {
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    const double spacing = 0.05;
    const auto curves = boundary_curves(*surface, spacing);
    ASSERT_EQ(curves.size(), static_cast<std::size_t>(surface->expected_topology().boundary_loops))
        << name;
    for (const BoundaryCurve& curve : curves) {
      ASSERT_GE(curve.vertices.size(), 3u) << name;
      for (std::size_t i = 0; i < curve.vertices.size(); ++i) {
        const BoundaryVertex& b = curve.vertices[i];
        EXPECT_NEAR(b.tangent.squared_length(), 1.0, 1e-12) << name;
        EXPECT_NEAR(b.normal.squared_length(), 1.0, 1e-12) << name;
        EXPECT_NEAR(b.conormal.squared_length(), 1.0, 1e-12) << name;
        EXPECT_NEAR(b.conormal * b.tangent, 0.0, 1e-12) << name;
        EXPECT_NEAR(b.conormal * b.normal, 0.0, 1e-12) << name;
        EXPECT_NEAR(b.tangent * b.normal, 0.0, 1e-12) << name;
        const Point3& next = curve.vertices[(i + 1) % curve.vertices.size()].position;
        EXPECT_LE(distance(b.position, next), spacing * (1 + 1e-12)) << name;
        EXPECT_GT(distance(b.position, next), 0.5 * spacing) << name;
      }
    }
  }
}

TEST(BoundaryCurves, conormals_point_away_from_the_surface) {
  // Stepping back along c stays close to the surface; stepping forward leaves it.
  const double step = 0.1;
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    const PointSet dense = sample_surface(*surface, {30000, 0.0, false, 2});
    const auto nearest = [&](const Point3& q) {
      double best = CGAL::squared_distance(dense.points.front(), q);
      for (const Point3& p : dense.points) best = std::min(best, CGAL::squared_distance(p, q));
      return std::sqrt(best);
    };
    for (const BoundaryCurve& curve : boundary_curves(*surface, 0.3)) {
      for (const BoundaryVertex& b : curve.vertices) {
        const double behind = nearest(b.position - step * b.conormal);
        const double ahead = nearest(b.position + step * b.conormal);
        EXPECT_LT(behind, 0.5 * ahead) << name;
        EXPECT_GT(ahead, 0.9 * step) << name;
      }
    }
  }
}

TEST(BoundaryCurves, cylinder_top_conormal_is_up_and_bottom_down) {
  for (const char* name : {"cylinder", "cylinder-nurbs"}) {
    const auto curves = boundary_curves(*make_builtin(name), 0.1);
    ASSERT_EQ(curves.size(), 2u);
    for (const BoundaryCurve& curve : curves) {
      for (const BoundaryVertex& b : curve.vertices) {
        EXPECT_NEAR(b.conormal.z(), b.position.z() > 0 ? 1.0 : -1.0, 1e-12) << name;
        EXPECT_NEAR(std::abs(b.position.z()), 1.0, 1e-15) << name;
      }
    }
  }
}

TEST(BoundaryCurves, hemisphere_conormal_points_down) {
  const auto curves = boundary_curves(*make_builtin("hemisphere"), 0.1);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_EQ(curves[0].vertices.size(), 63u);  // ceil(2 pi / 0.1)
  for (const BoundaryVertex& b : curves[0].vertices) {
    EXPECT_NEAR(b.conormal.z(), -1.0, 1e-12);
    EXPECT_NEAR(b.position.z(), 0.0, 1e-15);
  }
}

TEST(BoundaryCurves, revolution_rims_sit_where_the_profiles_end) {
  const auto paraboloid = boundary_curves(*make_builtin("paraboloid"), 0.1);
  ASSERT_EQ(paraboloid.size(), 1u);
  for (const BoundaryVertex& b : paraboloid[0].vertices) {
    EXPECT_NEAR(b.position.x(), 4.0, 1e-12);
    EXPECT_NEAR(std::hypot(b.position.y(), b.position.z()), 2.0, 1e-12);
  }
  const auto cusp = boundary_curves(*make_builtin("cusp"), 0.1);
  ASSERT_EQ(cusp.size(), 1u);
  for (const BoundaryVertex& b : cusp[0].vertices) {
    EXPECT_NEAR(b.position.y(), 1.0, 1e-12);
    EXPECT_NEAR(std::hypot(b.position.x(), b.position.z()), 1.0, 1e-12);
  }
}

TEST(BoundaryCurves, square_has_four_flagged_corners_with_both_conormals) {
  const auto curves = boundary_curves(*make_builtin("square"), 0.25);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_EQ(curves[0].vertices.size(), 32u);
  int corners = 0;
  for (const BoundaryVertex& b : curves[0].vertices) {
    if (!b.is_corner) continue;
    ++corners;
    EXPECT_NEAR(std::abs(b.position.x()), 1.0, 0.0);
    EXPECT_NEAR(std::abs(b.position.y()), 1.0, 0.0);
    // The two conormals are the outward axis directions of the edges meeting there.
    EXPECT_NEAR(b.conormal * b.conormal_next, 0.0, 1e-15);
    const Vector3 sum = b.conormal + b.conormal_next;
    EXPECT_NEAR(sum.x(), b.position.x(), 1e-15);
    EXPECT_NEAR(sum.y(), b.position.y(), 1e-15);
  }
  EXPECT_EQ(corners, 4);
}

TEST(BoundaryCurves, moebius_boundary_is_one_loop_twice_as_long_as_an_edge) {
  const auto curves = boundary_curves(*make_builtin("moebius"), 0.02);
  ASSERT_EQ(curves.size(), 1u);
  double length = 0;
  const auto& vs = curves[0].vertices;
  for (std::size_t i = 0; i < vs.size(); ++i) {
    length += distance(vs[i].position, vs[(i + 1) % vs.size()].position);
  }
  // Each long edge (v = +-0.4) is about as long as a circle of radius 1, so the loop is ~4 pi.
  EXPECT_NEAR(length, 4 * std::numbers::pi, 0.3);
  EXPECT_LT(distance(vs.back().position, vs.front().position), 0.02);
}

TEST(BoundaryCurves, linking_numbers_match_the_expected_topology) {
  for (const char* name : {"trefoil-ribbon", "unknot-ribbon", "cylinder", "horn"}) {
    const auto surface = make_builtin(name);
    const auto curves = boundary_curves(*surface, 0.02);
    ASSERT_EQ(curves.size(), 2u);
    EXPECT_EQ(std::abs(testing::linking_number(curves[0].polyline(), curves[1].polyline())),
              surface->expected_topology().abs_linking_number)
        << name;
  }
}

TEST(BoundaryCurves, rejects_non_positive_spacing) {
  EXPECT_THROW((void)boundary_curves(*make_builtin("square"), 0.0), InvalidOptions);
}

}  // namespace
}  // namespace envcrust::surfaces
