// Exact determinants of square matrices over Z[t]: fraction-free (Bareiss) and unit-pivot elimination.
#pragma once

#include "polynomial.h"

#include <vector>

namespace envcrust::knots::detail {

/// A dense square matrix of polynomials, row-major: m[row][column].
using PolynomialMatrix = std::vector<std::vector<Polynomial>>;

/// det(m), exact. The empty (0 x 0) matrix has determinant 1.
Polynomial determinant(PolynomialMatrix m);

/// det(m) up to a unit +-t^k, much faster on sparse matrices such as Alexander matrices:
/// pivots that are units of Z[t, 1/t] (entries +-t^k) are eliminated first, fewest fill-ins
/// first, and only what remains goes through determinant().
Polynomial determinant_up_to_units(PolynomialMatrix m);

}  // namespace envcrust::knots::detail
