// Delta-move simplification: how far curves shrink, and that it never changes the knot.
#include "curves.h"
#include "envcrust/knots.h"
#include "simplify.h"

#include <gtest/gtest.h>

#include <cmath>

namespace envcrust::knots::detail {
namespace {

using test::sample;

TEST(Simplify, FineCircleShrinksToThreeVertices) {
  const Polyline circle = sample([](double t) { return Point3(std::cos(t), std::sin(t), 0); }, 1000);
  EXPECT_EQ(simplify_loops({circle}).front().size(), 3U);
}

TEST(Simplify, FineTrefoilShrinksToAFewDozenVerticesAndStaysATrefoil) {
  const std::vector<Polyline> simplified = simplify_loops({sample(test::trefoil, 2000)});
  EXPECT_LE(simplified.front().size(), 36U);
  EXPECT_EQ(identify_knot(simplified.front()).type, KnotType::Trefoil);
}

// Its time is measured by envcrust_bench (bench/bench_main.cpp), not asserted here.
TEST(Simplify, RotatedTwoThousandVertexTrefoilShrinksAndStaysATrefoil) {
  const Polyline curve = test::randomly_rotated(sample(test::trefoil, 2000), 3);
  const std::vector<Polyline> simplified = simplify_loops({curve});
  EXPECT_LE(simplified.front().size(), 36U);
  EXPECT_EQ(identify_knot(simplified.front()).type, KnotType::Trefoil);
}

TEST(Simplify, LoopsAreSimplifiedWithoutPassingThroughEachOther) {
  const Polyline a = sample([](double t) { return Point3(std::cos(t), std::sin(t), 0); }, 400);
  const Polyline b = sample([](double t) { return Point3(1 + std::cos(t), 0, std::sin(t)); }, 400);
  const std::vector<Polyline> simplified = simplify_loops({a, b});
  ASSERT_EQ(simplified.size(), 2U);
  EXPECT_LT(simplified[0].size(), 20U);
  EXPECT_LT(simplified[1].size(), 20U);
  EXPECT_EQ(std::abs(linking_number(simplified[0], simplified[1])), 1);
}

TEST(Simplify, CollinearVerticesAreDropped) {
  Polyline square;
  for (int k = 0; k < 10; ++k) {
    square.emplace_back(k, 0, 0);
  }
  for (int k = 0; k < 10; ++k) {
    square.emplace_back(10, k, 0);
  }
  for (int k = 0; k < 10; ++k) {
    square.emplace_back(10 - k, 10, 0);
  }
  for (int k = 0; k < 10; ++k) {
    square.emplace_back(0, 10 - k, 0);
  }
  EXPECT_EQ(simplify_loops({square}).front().size(), 3U);
}

}  // namespace
}  // namespace envcrust::knots::detail
