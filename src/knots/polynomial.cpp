// Arithmetic, normalisation and printing of integer polynomials in Z[t].
#include "polynomial.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace envcrust::knots::detail {

Polynomial::Polynomial(BigInt c) {
  coeffs_.push_back(std::move(c));
  trim();
}

Polynomial::Polynomial(std::vector<BigInt> coeffs) : coeffs_(std::move(coeffs)) { trim(); }

Polynomial Polynomial::monomial(BigInt c, int k) {
  std::vector<BigInt> coeffs(static_cast<std::size_t>(k) + 1);
  coeffs.back() = std::move(c);
  return Polynomial(std::move(coeffs));
}

BigInt Polynomial::coeff(int k) const {
  if (k < 0 || k > degree()) {
    return 0;
  }
  return coeffs_[static_cast<std::size_t>(k)];
}

void Polynomial::trim() {
  while (!coeffs_.empty() && coeffs_.back() == 0) {
    coeffs_.pop_back();
  }
}

Polynomial& Polynomial::operator+=(const Polynomial& other) {
  if (other.coeffs_.size() > coeffs_.size()) {
    coeffs_.resize(other.coeffs_.size());
  }
  for (std::size_t k = 0; k < other.coeffs_.size(); ++k) {
    coeffs_[k] += other.coeffs_[k];
  }
  trim();
  return *this;
}

Polynomial& Polynomial::operator-=(const Polynomial& other) {
  if (other.coeffs_.size() > coeffs_.size()) {
    coeffs_.resize(other.coeffs_.size());
  }
  for (std::size_t k = 0; k < other.coeffs_.size(); ++k) {
    coeffs_[k] -= other.coeffs_[k];
  }
  trim();
  return *this;
}

Polynomial operator-(Polynomial a) {
  for (auto& c : a.coeffs_) {
    c = -c;
  }
  return a;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  if (a.is_zero() || b.is_zero()) {
    return {};
  }
  std::vector<BigInt> out(a.coeffs_.size() + b.coeffs_.size() - 1);
  for (std::size_t i = 0; i < a.coeffs_.size(); ++i) {
    if (a.coeffs_[i] == 0) {
      continue;
    }
    for (std::size_t j = 0; j < b.coeffs_.size(); ++j) {
      out[i + j] += a.coeffs_[i] * b.coeffs_[j];
    }
  }
  return Polynomial(std::move(out));
}

BigInt Polynomial::evaluate(const BigInt& t) const {
  BigInt value = 0;
  for (auto it = coeffs_.rbegin(); it != coeffs_.rend(); ++it) {
    value = value * t + *it;
  }
  return value;
}

Polynomial exact_divide(const Polynomial& a, const Polynomial& b) {
  if (b.is_zero()) {
    throw std::logic_error("polynomial division by zero");
  }
  if (a.is_zero()) {
    return {};
  }
  const int db = b.degree();
  if (a.degree() < db) {
    throw std::logic_error("polynomial division is not exact");
  }
  std::vector<BigInt> rest = a.coeffs();
  std::vector<BigInt> quotient(static_cast<std::size_t>(a.degree() - db) + 1);
  const BigInt& lead = b.coeffs().back();
  // Long division from the top: exactness in Z[t] makes every step's quotient an integer.
  for (int k = a.degree() - db; k >= 0; --k) {
    BigInt& top = rest[static_cast<std::size_t>(k + db)];
    if (top == 0) {
      continue;
    }
    BigInt q;
    BigInt r;
    boost::multiprecision::divide_qr(top, lead, q, r);
    if (r != 0) {
      throw std::logic_error("polynomial division is not exact");
    }
    for (int j = 0; j <= db; ++j) {
      rest[static_cast<std::size_t>(k + j)] -= q * b.coeffs()[static_cast<std::size_t>(j)];
    }
    quotient[static_cast<std::size_t>(k)] = std::move(q);
  }
  for (const auto& c : rest) {
    if (c != 0) {
      throw std::logic_error("polynomial division is not exact");
    }
  }
  return Polynomial(std::move(quotient));
}

Polynomial normalize_unit(const Polynomial& p) {
  if (p.is_zero()) {
    return p;
  }
  std::size_t low = 0;
  while (p.coeffs()[low] == 0) {
    ++low;
  }
  std::vector<BigInt> shifted(p.coeffs().begin() + static_cast<std::ptrdiff_t>(low), p.coeffs().end());
  if (shifted.front() < 0) {
    for (auto& c : shifted) {
      c = -c;
    }
  }
  return Polynomial(std::move(shifted));
}

namespace {

// Hand-rolled because GCC 12 reports a false -Wrestrict inside cpp_int::str().
std::string decimal(BigInt magnitude) {
  std::string digits;
  const BigInt ten = 10;
  do {
    BigInt quotient;
    BigInt remainder;
    boost::multiprecision::divide_qr(magnitude, ten, quotient, remainder);
    digits += static_cast<char>('0' + remainder.convert_to<int>());
    magnitude = std::move(quotient);
  } while (magnitude != 0);
  return {digits.rbegin(), digits.rend()};
}

}  // namespace

std::string to_string(const Polynomial& p) {
  if (p.is_zero()) {
    return "0";
  }
  std::string out;
  for (int k = p.degree(); k >= 0; --k) {
    const BigInt& c = p.coeffs()[static_cast<std::size_t>(k)];
    if (c == 0) {
      continue;
    }
    const bool negative = c < 0;
    const BigInt magnitude = negative ? BigInt(-c) : c;
    if (out.empty()) {
      out += negative ? "-" : "";
    } else {
      out += negative ? " - " : " + ";
    }
    if (magnitude != 1 || k == 0) {
      out += decimal(magnitude);
    }
    if (k >= 1) {
      out += "t";
    }
    if (k >= 2) {
      out += '^';
      out += std::to_string(k);
    }
  }
  return out;
}

}  // namespace envcrust::knots::detail
