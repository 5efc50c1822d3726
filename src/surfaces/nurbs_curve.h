// A rational B-spline (NURBS) curve evaluated exactly, with first and second derivatives.
#pragma once

#include "bspline_basis.h"

#include <Eigen/Core>
#include <vector>

namespace envcrust::surfaces {

/// Position and first two derivatives of a curve at one parameter.
struct CurveJet {
  Eigen::Vector3d position, d1, d2;
};

/// A NURBS curve of any degree: control points with weights and a clamped knot vector.
class RationalBSplineCurve {
 public:
  static constexpr int max_degree = max_bspline_degree;

  /// @throws InvalidInput when the degree is outside [1, max_degree], the sizes do not satisfy
  /// knots = points + degree + 1, a weight is not positive or the knots decrease.
  RationalBSplineCurve(int degree, std::vector<Eigen::Vector3d> control_points,
                       std::vector<double> weights, std::vector<double> knots);

  [[nodiscard]] double first_parameter() const { return knots_[degree_]; }
  [[nodiscard]] double last_parameter() const { return knots_[knots_.size() - degree_ - 1]; }

  /// C, C', C'' at t (clamped to the parameter range), by the basis-function derivatives in
  /// homogeneous coordinates and the quotient rule.
  [[nodiscard]] CurveJet evaluate(double t) const;

 private:
  int degree_;
  std::vector<Eigen::Vector3d> control_points_;
  std::vector<double> weights_;
  std::vector<double> knots_;
};

}  // namespace envcrust::surfaces
