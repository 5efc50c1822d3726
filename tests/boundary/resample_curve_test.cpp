// Tests of resample_curve: spacing, corners kept, frames orthonormal and consistent.
#include "envcrust/boundary.h"
#include "envcrust/errors.h"
#include "envcrust/normals.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envcrust {
namespace {

void check(const BoundaryCurve& curve, double spacing) {
  const std::size_t m = curve.vertices.size();
  for (std::size_t i = 0; i < m; ++i) {
    const BoundaryVertex& v = curve.vertices[i];
    const BoundaryVertex& w = curve.vertices[(i + 1) % m];
    EXPECT_LE(std::sqrt(CGAL::squared_distance(v.position, w.position)), spacing * (1 + 1e-9));
    EXPECT_NEAR(v.tangent.squared_length(), 1.0, 1e-9);
    EXPECT_NEAR(CGAL::scalar_product(v.tangent, v.normal), 0.0, 1e-9);
    EXPECT_NEAR(CGAL::scalar_product(v.tangent, v.conormal), 0.0, 1e-9);
    EXPECT_NEAR(CGAL::scalar_product(v.normal, v.conormal), 0.0, 1e-9);
  }
}

TEST(ResampleCurve, SquareKeepsCornersAndConormals) {
  const auto square = surfaces::make_builtin("square");
  const BoundaryCurve coarse = surfaces::boundary_curves(*square, 0.5)[0];
  const BoundaryCurve fine = boundary::resample_curve(coarse, 0.03);
  check(fine, 0.03);
  int corners = 0;
  for (const BoundaryVertex& v : fine.vertices) {
    if (v.is_corner) {
      ++corners;
      continue;
    }
    // Edge points: conormal is the edge's outward axis.
    const double x = v.position.x(), y = v.position.y();
    if (std::abs(std::abs(x) - 1) < 1e-12) {
      EXPECT_NEAR(v.conormal.x(), x, 1e-9);
    }
    if (std::abs(std::abs(y) - 1) < 1e-12) {
      EXPECT_NEAR(v.conormal.y(), y, 1e-9);
    }
  }
  EXPECT_EQ(corners, 4);
  // 8 / 0.03 -> 67 intervals per side, rounded up per side.
  EXPECT_EQ(fine.vertices.size(), 4u * 67u);
}

TEST(ResampleCurve, MoebiusFramesStayConsistent) {
  const auto moebius = surfaces::make_builtin("moebius");
  const BoundaryCurve exact = surfaces::boundary_curves(*moebius, 0.05)[0];
  const BoundaryCurve fine = boundary::resample_curve(exact, 0.01);
  check(fine, 0.01);
  const BoundaryCurve dense = surfaces::boundary_curves(*moebius, 0.002)[0];
  for (const BoundaryVertex& v : fine.vertices) {
    double best = 1e9;
    const BoundaryVertex* nearest = nullptr;
    for (const BoundaryVertex& e : dense.vertices) {
      const double d = CGAL::squared_distance(e.position, v.position);
      if (d < best) {
        best = d;
        nearest = &e;
      }
    }
    EXPECT_GT(CGAL::scalar_product(v.conormal, nearest->conormal), 0.99);
    EXPECT_GT(std::abs(CGAL::scalar_product(v.normal, nearest->normal)), 0.99);
  }
}

TEST(ResampleCurve, Rejects) {
  const auto square = surfaces::make_builtin("square");
  const BoundaryCurve curve = surfaces::boundary_curves(*square, 0.5)[0];
  try {
    (void)boundary::resample_curve(curve, 0);
    FAIL();
  } catch (const InvalidOptions& e) {
    EXPECT_EQ(std::string(e.what()), "resample_curve: max_spacing must be > 0 (got 0)");
  }
  EXPECT_THROW((void)boundary::resample_curve(BoundaryCurve{}, 0.1), InvalidInput);
}

}  // namespace
}  // namespace envcrust
