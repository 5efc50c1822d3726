// Angle statistics between estimated and exact normal lines (sign ignored), in degrees.
#pragma once

#include "envcrust/types.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace envcrust::test {

struct AngleStats {
  double mean = 0, p95 = 0, max = 0;
};

/// Angle between two lines, degrees in [0, 90].
inline double line_angle_deg(const Vector3& a, const Vector3& b) {
  const double c = std::abs(CGAL::scalar_product(a, b)) /
                   std::sqrt(a.squared_length() * b.squared_length());
  return std::acos(std::min(1.0, c)) * 180.0 / std::numbers::pi;
}

inline AngleStats angle_stats(std::vector<double> deg) {
  AngleStats s;
  if (deg.empty()) return s;
  for (const double d : deg) s.mean += d;
  s.mean /= static_cast<double>(deg.size());
  std::sort(deg.begin(), deg.end());
  s.p95 = deg[static_cast<std::size_t>(0.95 * static_cast<double>(deg.size() - 1))];
  s.max = deg.back();
  return s;
}

inline AngleStats line_errors(const std::vector<Vector3>& estimated,
                              const std::vector<Vector3>& exact) {
  std::vector<double> deg;
  deg.reserve(estimated.size());
  for (std::size_t i = 0; i < estimated.size(); ++i) {
    deg.push_back(line_angle_deg(estimated[i], exact[i]));
  }
  return angle_stats(std::move(deg));
}

}  // namespace envcrust::test
