// Z[t] arithmetic, normal form, printing, and the Bareiss determinant.
#include "bareiss.h"
#include "polynomial.h"

#include <gtest/gtest.h>

namespace envcrust::knots::detail {
namespace {

Polynomial poly(std::vector<BigInt> coeffs) { return Polynomial(std::move(coeffs)); }

TEST(Polynomial, ProductOfOneMinusTAndOnePlusTIsOneMinusTSquared) {
  EXPECT_EQ(poly({1, -1}) * poly({1, 1}), poly({1, 0, -1}));
}

TEST(Polynomial, ExactDivisionUndoesMultiplication) {
  const Polynomial a = poly({3, -2, 0, 5});
  const Polynomial b = poly({-1, 4, 7});
  EXPECT_EQ(exact_divide(a * b, b), a);
  EXPECT_THROW(exact_divide(a * b + Polynomial(BigInt(1)), b), std::logic_error);
}

TEST(Polynomial, NormalFormDropsPowersOfTAndMakesTheConstantTermPositive) {
  EXPECT_EQ(normalize_unit(poly({0, 0, -1, 1, -1})), poly({1, -1, 1}));
  EXPECT_EQ(normalize_unit(poly({0, -1})), poly({1}));
}

TEST(Polynomial, PrintsHighestDegreeFirst) {
  EXPECT_EQ(to_string(poly({1, -3, 1})), "t^2 - 3t + 1");
  EXPECT_EQ(to_string(poly({1, -1, 1})), "t^2 - t + 1");
  EXPECT_EQ(to_string(poly({1})), "1");
  EXPECT_EQ(to_string(Polynomial()), "0");
  EXPECT_EQ(to_string(poly({0, -1})), "-t");
  EXPECT_EQ(to_string(poly({0, 1, 0, 2})), "2t^3 + t");
}

TEST(Polynomial, EvaluatesAtMinusOne) {
  EXPECT_EQ(poly({1, -3, 1}).evaluate(-1), 5);
}

TEST(Bareiss, EmptyMatrixHasDeterminantOne) {
  EXPECT_EQ(determinant({}), poly({1}));
}

TEST(Bareiss, TwoByTwoDeterminant) {
  // Trefoil minor: [[1 - t, t], [-1, 1 - t]] has determinant t^2 - t + 1.
  const PolynomialMatrix m = {{poly({1, -1}), poly({0, 1})}, {poly({-1}), poly({1, -1})}};
  EXPECT_EQ(determinant(m), poly({1, -1, 1}));
}

TEST(Bareiss, ZeroPivotIsSwappedAwayWithASignChange) {
  const PolynomialMatrix m = {{Polynomial(), poly({0, 1}), poly({2})},
                              {poly({1}), poly({3}), poly({0, 0, 1})},
                              {poly({4}), poly({1, 1}), poly({5})}};
  // Cofactor expansion along the first row: -t (5 - 4 t^2) + 2 (1 + t - 12).
  EXPECT_EQ(determinant(m), poly({-22, -3, 0, 4}));
}

TEST(Bareiss, SingularMatrixHasDeterminantZero) {
  const PolynomialMatrix m = {{poly({1, 1}), poly({2})}, {poly({1, 1}), poly({2})}};
  EXPECT_TRUE(determinant(m).is_zero());
}

TEST(Bareiss, UnitPivotEliminationAgreesWithBareissUpToUnits) {
  // A 5 x 5 Alexander-like matrix: 1 - t, t and -1 scattered with coinciding entries.
  const Polynomial a = poly({1, -1});
  const Polynomial b = poly({0, 1});
  const Polynomial c = poly({-1});
  const Polynomial z;
  const PolynomialMatrix m = {{a, b, z, c, z},
                              {z, a + c, b, z, z},
                              {c, z, a, z, b},
                              {b, z, c, a, z},
                              {z, c, z, b, a + b}};
  const Polynomial exact = determinant(m);
  ASSERT_FALSE(exact.is_zero());
  EXPECT_EQ(normalize_unit(determinant_up_to_units(m)), normalize_unit(exact));
}

TEST(Bareiss, UnitPivotEliminationOfASingularMatrixGivesZero) {
  const PolynomialMatrix m = {{poly({0, 1}), poly({2})}, {poly({0, 1}), poly({2})}};
  EXPECT_TRUE(determinant_up_to_units(m).is_zero());
}

}  // namespace
}  // namespace envcrust::knots::detail
