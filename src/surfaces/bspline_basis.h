// B-spline basis functions with their first two derivatives, for curves and surfaces.
#pragma once

#include <array>
#include <vector>

namespace envcrust::surfaces {

/// Highest degree the NURBS evaluators accept.
inline constexpr int max_bspline_degree = 8;
inline constexpr std::size_t max_basis_order = max_bspline_degree + 1;
inline constexpr int max_derivative = 2;

/// ders[j][k]: the k-th derivative of N_{span-degree+j, degree} at t (k <= 2).
using BasisDerivatives = std::array<std::array<double, max_derivative + 1>, max_basis_order>;

/// The span index i with knots[i] <= t < knots[i+1] among the `count` control points' spans;
/// the last parameter belongs to the last non-empty span.
int find_knot_span(const std::vector<double>& knots, int degree, int count, double t);

/// Basis functions N_{span-p..span, p} and their first two derivatives at t (degree <= 8).
BasisDerivatives basis_derivatives(int span, double t, int degree, const std::vector<double>& knots);

}  // namespace envcrust::surfaces
