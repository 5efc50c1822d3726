// Areas and bounding-box diagonals against closed forms.
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {
namespace {

constexpr double pi = std::numbers::pi;

void expect_area(const char* name, double exact) {
  EXPECT_NEAR(area(*make_builtin(name)), exact, 1e-6 * exact) << name;
}

TEST(Measures, areas_match_closed_forms) {
  expect_area("cylinder", 4 * pi);
  expect_area("cylinder-nurbs", 4 * pi);
  expect_area("sphere", 4 * pi);
  expect_area("hemisphere", 2 * pi);
  expect_area("square", 4);
  expect_area("torus", 4 * pi * pi * 1.0 * 0.4);
  // 2 pi int_0^2 y sqrt(1 + 4 y^2) dy and 2 pi int_0^1 r sqrt(1 + 4 r^2) dr.
  expect_area("paraboloid", pi / 6 * (std::pow(17.0, 1.5) - 1));
  expect_area("saddle", pi / 6 * (std::pow(5.0, 1.5) - 1));
  // 2 pi int_0^1 r sqrt(1 + 9r/4) dr, with w = 1 + 9r/4.
  const auto antiderivative = [](double w) {
    return 0.4 * std::pow(w, 2.5) - 2.0 / 3 * std::pow(w, 1.5);
  };
  expect_area("cusp", 2 * pi / (2.25 * 2.25) * (antiderivative(3.25) - antiderivative(1.0)));
}

TEST(Measures, ribbon_area_is_width_times_projected_length) {
  // The trefoil's projected speed is sqrt(17 + 8 cos 3s); integrate it finely.
  double length = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) length += std::sqrt(17 + 8 * std::cos(3 * 2 * pi * (i + 0.5) / n));
  length *= 2 * pi / n;
  expect_area("trefoil-ribbon", 0.5 * length);
}

TEST(Measures, bbox_diagonals) {
  EXPECT_NEAR(bbox_diagonal(*make_builtin("cylinder")), std::sqrt(12.0), 1e-12);
  EXPECT_NEAR(bbox_diagonal(*make_builtin("sphere")), std::sqrt(12.0), 1e-12);
  EXPECT_NEAR(bbox_diagonal(*make_builtin("square")), std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(bbox_diagonal(*make_builtin("paraboloid")), std::sqrt(16.0 + 16 + 16), 1e-12);
}

}  // namespace
}  // namespace envcrust::surfaces
