// B-spline basis functions and their derivatives (Piegl & Tiller, algorithms A2.1 and A2.3),
// shared by the NURBS curve and the NURBS surface.
#include "bspline_basis.h"

#include <algorithm>

namespace envcrust::surfaces {

namespace {

using Row = std::array<double, max_basis_order>;

}  // namespace

int find_knot_span(const std::vector<double>& knots, int degree, int count, double t) {
  const int n = count - 1;
  // The last parameter belongs to the last non-empty span (curves are closed at their end).
  if (t >= knots[static_cast<std::size_t>(n) + 1]) {
    int span = n;
    while (span > degree && knots[static_cast<std::size_t>(span)] >= t) --span;
    return span;
  }
  const auto first = knots.begin() + degree;
  const auto last = knots.begin() + n + 1;
  // upper_bound gives the first knot > t; the span starts at the knot before it.
  return static_cast<int>(std::upper_bound(first, last, t) - knots.begin()) - 1;
}

/// Basis functions N_{span-p..span, p} and their first two derivatives at t.
BasisDerivatives basis_derivatives(int span, double t, int degree, const std::vector<double>& knots) {
  const auto p = static_cast<std::size_t>(degree);
  std::array<Row, max_basis_order> ndu{};
  Row left{}, right{};
  ndu[0][0] = 1.0;
  for (std::size_t j = 1; j <= p; ++j) {
    left[j] = t - knots[static_cast<std::size_t>(span) + 1 - j];
    right[j] = knots[static_cast<std::size_t>(span) + j] - t;
    double saved = 0.0;
    for (std::size_t r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }

  BasisDerivatives ders{};
  for (std::size_t j = 0; j <= p; ++j) ders[j][0] = ndu[j][p];
  const int n = std::min(max_derivative, degree);
  std::array<Row, 2> a{};
  for (int r = 0; r <= degree; ++r) {
    std::size_t s1 = 0, s2 = 1;
    a[0].fill(0.0);
    a[1].fill(0.0);
    a[0][0] = 1.0;
    for (int k = 1; k <= n; ++k) {
      double d = 0.0;
      const int rk = r - k;
      const int pk = degree - k;
      const auto upk = static_cast<std::size_t>(pk);
      if (r >= k) {
        const auto urk = static_cast<std::size_t>(rk);
        a[s2][0] = a[s1][0] / ndu[upk + 1][urk];
        d = a[s2][0] * ndu[urk][upk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : degree - r;
      for (int j = j1; j <= j2; ++j) {
        const auto uj = static_cast<std::size_t>(j);
        const auto urkj = static_cast<std::size_t>(rk + j);
        a[s2][uj] = (a[s1][uj] - a[s1][uj - 1]) / ndu[upk + 1][urkj];
        d += a[s2][uj] * ndu[urkj][upk];
      }
      if (r <= pk) {
        const auto ur = static_cast<std::size_t>(r);
        const auto uk = static_cast<std::size_t>(k);
        a[s2][uk] = -a[s1][uk - 1] / ndu[upk + 1][ur];
        d += a[s2][uk] * ndu[ur][upk];
      }
      ders[static_cast<std::size_t>(r)][static_cast<std::size_t>(k)] = d;
      std::swap(s1, s2);
    }
  }
  double factor = degree;
  for (int k = 1; k <= n; ++k) {
    for (std::size_t j = 0; j <= p; ++j) ders[j][static_cast<std::size_t>(k)] *= factor;
    factor *= degree - k;
  }
  return ders;
}

}  // namespace envcrust::surfaces
