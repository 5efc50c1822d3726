// Exact determinant of a square matrix over Z[t] by fraction-free (Bareiss) elimination.
#pragma once

#include "polynomial.h"

#include <vector>

namespace envcrust::knots::detail {

/// A dense square matrix of polynomials, row-major: m[row][column].
using PolynomialMatrix = std::vector<std::vector<Polynomial>>;

/// det(m), exact. The empty (0 x 0) matrix has determinant 1.
Polynomial determinant(PolynomialMatrix m);

}  // namespace envcrust::knots::detail
