// Linking numbers of Hopf, torus and ribbon-boundary links and of unlinked circles.
#include "curves.h"
#include "envcrust/errors.h"
#include "envcrust/knots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

namespace envcrust::knots {
namespace {

using test::sample;

Polyline circle_xy(int n) {
  return sample([](double t) { return Point3(std::cos(t), std::sin(t), 0); }, n);
}

Polyline circle_xz_through_origin(int n) {
  return sample([](double t) { return Point3(1 + std::cos(t), 0, std::sin(t)); }, n);
}

TEST(LinkingNumber, HopfLinkHasLinkingNumberOfMagnitudeOne) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Polyline a = test::randomly_rotated(circle_xy(200), seed);
    const Polyline b = test::randomly_rotated(circle_xz_through_origin(150), seed);
    EXPECT_EQ(std::abs(linking_number(a, b, {.seed = seed})), 1);
  }
}

TEST(LinkingNumber, HopfLinkSignFollowsTheRightHandRule) {
  // b passes downwards (-z) through the disc of a, which runs counterclockwise seen from +z.
  EXPECT_EQ(linking_number(circle_xy(200), circle_xz_through_origin(150)), -1);
}

TEST(LinkingNumber, ReversingOneLoopFlipsTheSign) {
  const Polyline a = circle_xy(200);
  const Polyline b = circle_xz_through_origin(150);
  const int lk = linking_number(a, b);
  EXPECT_EQ(linking_number(a, test::reversed(b)), -lk);
  EXPECT_EQ(linking_number(test::reversed(a), b), -lk);
}

TEST(LinkingNumber, IsSymmetricInItsArguments) {
  const Polyline a = circle_xy(200);
  const Polyline b = circle_xz_through_origin(150);
  EXPECT_EQ(linking_number(a, b), linking_number(b, a));
}

TEST(LinkingNumber, FarApartCirclesHaveLinkingNumberZero) {
  const Polyline a = circle_xy(100);
  const Polyline b = test::translated(circle_xz_through_origin(100), Vector3(10, 3, 1));
  EXPECT_EQ(linking_number(a, b), 0);
}

TEST(LinkingNumber, TorusLinkTwoFourHasLinkingNumberTwo) {
  const Polyline a = sample([](double t) { return test::torus_curve(1, 2, t); }, 300);
  const Polyline b =
      sample([](double t) { return test::torus_curve(1, 2, t, std::numbers::pi); }, 300);
  EXPECT_EQ(std::abs(linking_number(a, b)), 2);
}

TEST(LinkingNumber, TrefoilRibbonBoundariesLinkThreeTimes) {
  const Polyline a = sample(test::trefoil, 600);
  const Polyline b = test::translated(a, Vector3(0, 0, 0.5));
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_EQ(std::abs(linking_number(a, b, {.seed = seed})), 3);
  }
}

TEST(LinkingNumber, TouchingLoopsHaveNoGenericProjection) {
  // The square passes through (1, 0, 0), a vertex of the circle.
  const Polyline b = {Point3(1, 0, 0), Point3(2, 0, 1), Point3(3, 0, 0), Point3(2, 0, -1)};
  EXPECT_THROW(linking_number(circle_xy(100), b), NumericalFailure);
}

TEST(LinkingNumber, ShortLoopIsRejected) {
  try {
    linking_number(circle_xy(10), {Point3(0, 0, 0), Point3(1, 0, 0)});
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "a closed polyline needs at least 3 points (got 2)");
  }
}

}  // namespace
}  // namespace envcrust::knots
