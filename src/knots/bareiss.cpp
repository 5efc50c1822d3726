// Fraction-free Gaussian elimination over Z[t] with row pivoting on zero pivots.
#include "bareiss.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>

namespace envcrust::knots::detail {
namespace {

bool is_unit(const Polynomial& p) {
  if (p.is_zero() || abs(p.coeffs().back()) != 1) {
    return false;
  }
  return std::count_if(p.coeffs().begin(), p.coeffs().end(),
                       [](const BigInt& c) { return c != 0; }) == 1;
}

// Divides the row by the highest power of t dividing all its entries (a unit factor).
void strip_powers_of_t(std::vector<Polynomial>& row, const std::vector<bool>& active) {
  int low = std::numeric_limits<int>::max();
  for (std::size_t j = 0; j < row.size(); ++j) {
    if (active[j] && !row[j].is_zero()) {
      int k = 0;
      while (row[j].coeffs()[static_cast<std::size_t>(k)] == 0) {
        ++k;
      }
      low = std::min(low, k);
    }
  }
  if (low == 0 || low == std::numeric_limits<int>::max()) {
    return;
  }
  for (std::size_t j = 0; j < row.size(); ++j) {
    if (active[j] && !row[j].is_zero()) {
      const auto& c = row[j].coeffs();
      row[j] = Polynomial(std::vector<BigInt>(c.begin() + low, c.end()));
    }
  }
}

}  // namespace

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


Polynomial determinant_up_to_units(PolynomialMatrix m) {
  const std::size_t n = m.size();
  std::vector<bool> row_active(n, true);
  std::vector<bool> column_active(n, true);
  for (std::size_t step = 0; step < n; ++step) {
    std::vector<std::size_t> row_count(n, 0);
    std::vector<std::size_t> column_count(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (row_active[i] && column_active[j] && !m[i][j].is_zero()) {
          ++row_count[i];
          ++column_count[j];
        }
      }
    }
    // Markowitz: the unit pivot whose elimination touches the fewest entries.
    std::size_t pivot_row = n;
    std::size_t pivot_column = n;
    std::size_t best_cost = std::numeric_limits<std::size_t>::max();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (!row_active[i] || !column_active[j] || !is_unit(m[i][j])) {
          continue;
        }
        const std::size_t cost = (row_count[i] - 1) * (column_count[j] - 1);
        if (cost < best_cost) {
          best_cost = cost;
          pivot_row = i;
          pivot_column = j;
        }
      }
    }
    if (pivot_row == n) {
      break;
    }
    // row_i <- u row_i - a row_r clears column k at the price of the unit factor u.
    const Polynomial u = m[pivot_row][pivot_column];
    row_active[pivot_row] = false;
    column_active[pivot_column] = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!row_active[i] || m[i][pivot_column].is_zero()) {
        continue;
      }
      const Polynomial a = m[i][pivot_column];
      for (std::size_t j = 0; j < n; ++j) {
        if (!column_active[j]) {
          continue;
        }
        Polynomial updated = u * m[i][j];
        if (!m[pivot_row][j].is_zero()) {
          updated -= a * m[pivot_row][j];
        }
        m[i][j] = std::move(updated);
      }
      m[i][pivot_column] = Polynomial();
      strip_powers_of_t(m[i], column_active);
    }
  }
  PolynomialMatrix rest;
  for (std::size_t i = 0; i < n; ++i) {
    if (!row_active[i]) {
      continue;
    }
    rest.emplace_back();
    for (std::size_t j = 0; j < n; ++j) {
      if (column_active[j]) {
        rest.back().push_back(std::move(m[i][j]));
      }
    }
  }
  return determinant(std::move(rest));
}

}  // namespace envcrust::knots::detail
