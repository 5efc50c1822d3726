// The rational B-spline evaluator and the NURBS cylinder built on it.
#include "nurbs_curve.h"  // private header of the module, tested directly

#include "envcrust/errors.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {
namespace {

RationalBSplineCurve circle() {
  const double h = std::numbers::sqrt2 / 2;
  return RationalBSplineCurve(2,
                              {{1, 0, 0},
                               {1, 1, 0},
                               {0, 1, 0},
                               {-1, 1, 0},
                               {-1, 0, 0},
                               {-1, -1, 0},
                               {0, -1, 0},
                               {1, -1, 0},
                               {1, 0, 0}},
                              {1, h, 1, h, 1, h, 1, h, 1},
                              {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1});
}

TEST(NurbsCurve, circle_points_lie_on_the_unit_circle) {
  const RationalBSplineCurve c = circle();
  for (int i = 0; i <= 1000; ++i) {
    const CurveJet jet = c.evaluate(i / 1000.0);
    EXPECT_NEAR(jet.position.norm(), 1.0, 1e-14);
    // Differentiating |C|^2 = 1: C.C' = 0 and C.C'' + |C'|^2 = 0.
    EXPECT_NEAR(jet.position.dot(jet.d1), 0.0, 1e-12);
    EXPECT_NEAR(jet.position.dot(jet.d2) + jet.d1.squaredNorm(), 0.0, 1e-11);
  }
}

TEST(NurbsCurve, interpolates_the_even_control_points_at_the_knots) {
  const RationalBSplineCurve c = circle();
  EXPECT_NEAR((c.evaluate(0.0).position - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((c.evaluate(0.25).position - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((c.evaluate(0.5).position - Eigen::Vector3d(-1, 0, 0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((c.evaluate(1.0).position - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-15);
  // The quarter arcs have speed 4 sqrt(2) at their ends: tangent continuity at the knots.
  EXPECT_NEAR(c.evaluate(0.25).d1.norm(), 4 * std::numbers::sqrt2, 1e-12);
  EXPECT_NEAR(c.evaluate(0.0).d1.norm(), 4 * std::numbers::sqrt2, 1e-12);
}

TEST(NurbsCurve, derivatives_match_central_differences) {
  const RationalBSplineCurve c = circle();
  const double h = 1e-6;
  for (double t : {0.05, 0.2, 0.3, 0.6, 0.9}) {
    const CurveJet jet = c.evaluate(t);
    EXPECT_NEAR(
        (jet.d1 - (c.evaluate(t + h).position - c.evaluate(t - h).position) / (2 * h)).norm(), 0.0,
        1e-6);
    EXPECT_NEAR((jet.d2 - (c.evaluate(t + h).d1 - c.evaluate(t - h).d1) / (2 * h)).norm(), 0.0,
                1e-5);
  }
}

TEST(NurbsCurve, rejects_inconsistent_sizes) {
  EXPECT_THROW(RationalBSplineCurve(2, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {1, 1, 1}, {0, 0, 1, 1}),
               InvalidInput);
  EXPECT_THROW(RationalBSplineCurve(1, {{0, 0, 0}, {1, 0, 0}}, {1, 0}, {0, 0, 1, 1}), InvalidInput);
}

TEST(NurbsCylinder, normals_and_curvatures_are_exact) {
  const auto cylinder = make_builtin("cylinder-nurbs");
  for (int i = 0; i <= 200; ++i) {
    const SurfacePoint p = cylinder->point_at(i / 200.0, -1 + i / 100.0);
    EXPECT_NEAR(std::hypot(p.position.x(), p.position.y()), 1.0, 1e-14);
    EXPECT_NEAR(std::abs(p.normal.x() * p.position.x() + p.normal.y() * p.position.y()), 1.0,
                1e-14);
    EXPECT_NEAR(p.normal.z(), 0.0, 1e-15);
    EXPECT_NEAR(std::abs(p.k1), 1.0, 1e-12);
    EXPECT_NEAR(p.k2, 0.0, 1e-12);
  }
}

}  // namespace
}  // namespace envcrust::surfaces
