// Exact evaluation of rational B-spline curves (the basis from bspline_basis.h, the quotient rule).
#include "nurbs_curve.h"
#include "bspline_basis.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <array>
#include <string>

namespace envcrust::surfaces {

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

CurveJet RationalBSplineCurve::evaluate(double t) const {
  t = std::clamp(t, first_parameter(), last_parameter());
  const int span = find_knot_span(knots_, degree_, static_cast<int>(control_points_.size()), t);
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
