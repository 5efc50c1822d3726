// Integer polynomials in one variable t (exact, arbitrary-precision coefficients) for the Alexander polynomial.
#pragma once

#include <boost/multiprecision/cpp_int.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace envcrust::knots::detail {

using BigInt = boost::multiprecision::cpp_int;

/// A polynomial in Z[t]; coeffs[k] multiplies t^k. Always trimmed: no trailing zero
/// coefficients, so the zero polynomial has no coefficients at all.
class Polynomial {
 public:
  Polynomial() = default;
  /// The constant polynomial c.
  explicit Polynomial(BigInt c);
  /// From coefficients of t^0, t^1, ... (trailing zeros are trimmed).
  explicit Polynomial(std::vector<BigInt> coeffs);
  /// c * t^k.
  static Polynomial monomial(BigInt c, int k);

  [[nodiscard]] bool is_zero() const { return coeffs_.empty(); }
  /// Degree; -1 for the zero polynomial.
  [[nodiscard]] int degree() const { return static_cast<int>(coeffs_.size()) - 1; }
  [[nodiscard]] const std::vector<BigInt>& coeffs() const { return coeffs_; }
  /// Coefficient of t^k (0 beyond the degree).
  [[nodiscard]] BigInt coeff(int k) const;

  Polynomial& operator+=(const Polynomial& other);
  Polynomial& operator-=(const Polynomial& other);
  friend Polynomial operator+(Polynomial a, const Polynomial& b) { return a += b; }
  friend Polynomial operator-(Polynomial a, const Polynomial& b) { return a -= b; }
  friend Polynomial operator-(Polynomial a);
  friend Polynomial operator*(const Polynomial& a, const Polynomial& b);
  friend bool operator==(const Polynomial& a, const Polynomial& b) = default;

  /// Value at an integer point.
  [[nodiscard]] BigInt evaluate(const BigInt& t) const;

 private:
  void trim();
  std::vector<BigInt> coeffs_;
};

/// Exact quotient a / b in Z[t]. @throws std::logic_error if b is zero or does not divide a.
Polynomial exact_divide(const Polynomial& a, const Polynomial& b);

/// The representative of p up to units +-t^k of Z[t, 1/t]: lowest-degree term moved to t^0
/// and a positive constant term. Zero stays zero.
Polynomial normalize_unit(const Polynomial& p);

/// Human-readable form, highest degree first: "t^2 - 3t + 1", "1", "-t", "0".
std::string to_string(const Polynomial& p);

}  // namespace envcrust::knots::detail
