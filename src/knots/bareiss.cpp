// Fraction-free Gaussian elimination over Z[t] with row pivoting on zero pivots.
#include "bareiss.h"

#include <cstddef>
#include <utility>

namespace envcrust::knots::detail {

Polynomial determinant(PolynomialMatrix m) {
  const std::size_t n = m.size();
  if (n == 0) {
    return Polynomial(BigInt(1));
  }
  bool negate = false;
  Polynomial previous_pivot(BigInt(1));
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (m[k][k].is_zero()) {
      // Prefer the lowest-degree nonzero pivot: it keeps later entries small.
      std::size_t best = n;
      for (std::size_t i = k + 1; i < n; ++i) {
        if (!m[i][k].is_zero() && (best == n || m[i][k].degree() < m[best][k].degree())) {
          best = i;
        }
      }
      if (best == n) {
        return {};
      }
      std::swap(m[k], m[best]);
      negate = !negate;
    }
    const Polynomial& pivot = m[k][k];
    for (std::size_t i = k + 1; i < n; ++i) {
      for (std::size_t j = k + 1; j < n; ++j) {
        // Bareiss' identity guarantees the division below is exact in Z[t].
        Polynomial numerator = m[i][j] * pivot - m[i][k] * m[k][j];
        m[i][j] = exact_divide(numerator, previous_pivot);
      }
      m[i][k] = Polynomial();
    }
    previous_pivot = m[k][k];
  }
  Polynomial det = std::move(m[n - 1][n - 1]);
  return negate ? -det : det;
}

}  // namespace envcrust::knots::detail
