// Tests of the closed-curve utilities of detection: switchbacks removed before framing.
#include "boundary_detail.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envcrust {
namespace {

using boundary::detail::remove_switchbacks;

Polyline circle(std::size_t n, double radius) {
  Polyline out;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2 * std::acos(-1.0) * static_cast<double>(k) / static_cast<double>(n);
    out.emplace_back(radius * std::cos(a), radius * std::sin(a), 0.0);
  }
  return out;
}

// Every vertex's turn: the cosine between its incoming and outgoing edges.
double smallest_turn_cosine(const Polyline& p) {
  double lowest = 1.0;
  const std::size_t m = p.size();
  for (std::size_t i = 0; i < m; ++i) {
    const Vector3 in = p[i] - p[(i + m - 1) % m], out = p[(i + 1) % m] - p[i];
    lowest = std::min(lowest, (in * out) / std::sqrt(in.squared_length() * out.squared_length()));
  }
  return lowest;
}

TEST(RemoveSwitchbacks, keeps_a_smooth_loop_as_it_is) {
  const Polyline c = circle(64, 1.0);
  EXPECT_EQ(remove_switchbacks(c), c);
}

TEST(RemoveSwitchbacks, drops_the_vertices_of_a_fold_and_nothing_else) {
  // A detected rim after the outer fit: the curve runs on, steps back by most of a spacing and
  // runs on again (measured on an unknot-ribbon point file: the fold flipped the conormal).
  Polyline c = circle(64, 1.0);
  const Point3 ahead = c[11] + 0.8 * (c[12] - c[11]);
  const Point3 back = c[11] + 0.3 * (c[12] - c[11]);
  c.insert(c.begin() + 12, {ahead, back});
  ASSERT_LT(smallest_turn_cosine(c), -0.9);
  const Polyline cleaned = remove_switchbacks(c);
  EXPECT_GE(smallest_turn_cosine(cleaned), 0.0);
  EXPECT_GE(cleaned.size(), 64u);
  EXPECT_LE(cleaned.size(), 65u);
  for (const Point3& p : circle(64, 1.0))
    EXPECT_NE(std::find(cleaned.begin(), cleaned.end(), p), cleaned.end()) << "lost a vertex of the circle";
}

TEST(RemoveSwitchbacks, leaves_at_least_a_triangle) {
  const Polyline zigzag{{0, 0, 0}, {1, 0, 0}, {0.1, 0, 0}, {0.9, 0.01, 0}};
  EXPECT_EQ(remove_switchbacks(zigzag).size(), 3u);
}

}  // namespace
}  // namespace envcrust
