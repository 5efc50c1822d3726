// Exact evaluation of rational B-spline curves (Piegl & Tiller, algorithms A2.1 and A2.3).
#include "nurbs_curve.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <array>
#include <string>

namespace envcrust::surfaces {

namespace {

constexpr int max_derivative = 2;

// Fixed-size scratch (no allocation per evaluation); the constructor enforces the bound.
constexpr std::size_t max_order = RationalBSplineCurve::max_degree + 1;
using Row = std::array<double, max_order>;
using BasisDerivatives = std::array<std::array<double, max_derivative + 1>, max_order>;

/// Basis functions N_{span-p..span, p} and their first two derivatives at t.
BasisDerivatives basis_derivatives(int span, double t, int degree,
                                   const std::vector<double>& knots) {
  const auto p = static_cast<std::size_t>(degree);
  std::array<Row, max_order> ndu{};
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

}  // namespace

RationalBSplineCurve::RationalBSplineCurve(int degree, std::vector<Eigen::Vector3d> control_points,
                                           std::vector<double> weights, std::vector<double> knots)
    : degree_(degree),
      control_points_(std::move(control_points)),
      weights_(std::move(weights)),
      knots_(std::move(knots)) {
  if (degree_ < 1 || degree_ > max_degree ||
      control_points_.size() < static_cast<std::size_t>(degree_) + 1 ||
      weights_.size() != control_points_.size() ||
      knots_.size() != control_points_.size() + static_cast<std::size_t>(degree_) + 1) {
    throw InvalidInput(
        "NURBS curve: need 1 <= degree <= 8, degree + 1 <= control points = weights (got " +
        std::to_string(control_points_.size()) + " points, " + std::to_string(weights_.size()) +
        " weights) and knots = points + degree + 1 (got " + std::to_string(knots_.size()) + ")");
  }
  if (std::any_of(weights_.begin(), weights_.end(), [](double w) { return !(w > 0); })) {
    throw InvalidInput("NURBS curve: weights must be > 0");
  }
  if (!std::is_sorted(knots_.begin(), knots_.end())) {
    throw InvalidInput("NURBS curve: knots must be non-decreasing");
  }
}

int RationalBSplineCurve::find_span(double t) const {
  const int n = static_cast<int>(control_points_.size()) - 1;
  // The last parameter belongs to the last non-empty span (curves are closed at their end).
  if (t >= knots_[static_cast<std::size_t>(n) + 1]) {
    int span = n;
    while (span > degree_ && knots_[static_cast<std::size_t>(span)] >= t) --span;
    return span;
  }
  const auto first = knots_.begin() + degree_;
  const auto last = knots_.begin() + n + 1;
  // upper_bound gives the first knot > t; the span starts at the knot before it.
  return static_cast<int>(std::upper_bound(first, last, t) - knots_.begin()) - 1;
}

CurveJet RationalBSplineCurve::evaluate(double t) const {
  t = std::clamp(t, first_parameter(), last_parameter());
  const int span = find_span(t);
  const auto ders = basis_derivatives(span, t, degree_, knots_);

  // Homogeneous numerator A = sum N w P and denominator w = sum N w, with derivatives.
  std::array<Eigen::Vector3d, max_derivative + 1> a;
  std::array<double, max_derivative + 1> w{};
  for (auto& v : a) v.setZero();
  for (int j = 0; j <= degree_; ++j) {
    const auto index = static_cast<std::size_t>(span - degree_ + j);
    const auto& basis = ders[static_cast<std::size_t>(j)];
    for (std::size_t k = 0; k <= max_derivative; ++k) {
      a[k] += basis[k] * weights_[index] * control_points_[index];
      w[k] += basis[k] * weights_[index];
    }
  }
  CurveJet jet;
  jet.position = a[0] / w[0];
  jet.d1 = (a[1] - w[1] * jet.position) / w[0];
  jet.d2 = (a[2] - 2 * w[1] * jet.d1 - w[2] * jet.position) / w[0];
  return jet;
}

}  // namespace envcrust::surfaces
