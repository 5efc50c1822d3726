// A local linking-number helper for the surfaces tests: signed crossings of two closed
// polylines in a generic projection.
#pragma once

#include "envcrust/types.h"

#include <cmath>

namespace envcrust::surfaces::testing {

/// lk(A, B) = half the sum of the signs of the crossings between A and B in one projection.
inline int linking_number(const Polyline& a, const Polyline& b) {
  const Vector3 view = Vector3(0.2113, 0.3761, 0.9022) /
                       std::sqrt(0.2113 * 0.2113 + 0.3761 * 0.3761 + 0.9022 * 0.9022);
  const Vector3 e1 = CGAL::cross_product(view, Vector3(1, 0, 0)) /
                     std::sqrt(CGAL::cross_product(view, Vector3(1, 0, 0)).squared_length());
  const Vector3 e2 = CGAL::cross_product(view, e1);
  const auto project = [&](const Point3& p, double& x, double& y, double& h) {
    const Vector3 v = p - CGAL::ORIGIN;
    x = v * e1;
    y = v * e2;
    h = v * view;
  };
  int twice = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    double ax0, ay0, ah0, ax1, ay1, ah1;
    project(a[i], ax0, ay0, ah0);
    project(a[(i + 1) % a.size()], ax1, ay1, ah1);
    for (std::size_t j = 0; j < b.size(); ++j) {
      double bx0, by0, bh0, bx1, by1, bh1;
      project(b[j], bx0, by0, bh0);
      project(b[(j + 1) % b.size()], bx1, by1, bh1);
      const double dax = ax1 - ax0, day = ay1 - ay0, dbx = bx1 - bx0, dby = by1 - by0;
      const double denom = dax * dby - day * dbx;
      if (denom == 0) continue;
      const double s = ((bx0 - ax0) * dby - (by0 - ay0) * dbx) / denom;
      const double t = ((bx0 - ax0) * day - (by0 - ay0) * dax) / denom;
      if (s < 0 || s >= 1 || t < 0 || t >= 1) continue;
      const double ha = ah0 + s * (ah1 - ah0), hb = bh0 + t * (bh1 - bh0);
      twice += (denom > 0 ? 1 : -1) * (ha > hb ? 1 : -1);
    }
  }
  return twice / 2;
}

}  // namespace envcrust::surfaces::testing
