// Knot types read from sampled trefoils, figure-eights, unknots and a (2,5) torus knot.
#include "curves.h"
#include "envcrust/errors.h"
#include "envcrust/knots.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

namespace envcrust::knots {
namespace {

using test::sample;

TEST(IdentifyKnot, TrefoilReadsTrefoilWithDeterminantThreeUnderRandomRotations) {
  const Polyline curve = sample(test::trefoil, 300);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("rotation seed " + std::to_string(seed));
    const KnotReport report = identify_knot(test::randomly_rotated(curve, seed), {.seed = seed});
    EXPECT_EQ(report.type, KnotType::Trefoil);
    EXPECT_EQ(report.alexander, "t^2 - t + 1");
    EXPECT_EQ(report.determinant, 3);
    EXPECT_TRUE(report.projections_agree);
  }
}

TEST(IdentifyKnot, MirroredTrefoilReadsTrefoil) {
  const Polyline curve = test::mirrored(sample(test::trefoil, 300));
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    SCOPED_TRACE("rotation seed " + std::to_string(seed));
    const KnotReport report = identify_knot(test::randomly_rotated(curve, seed), {.seed = seed});
    EXPECT_EQ(report.type, KnotType::Trefoil);
    EXPECT_EQ(report.determinant, 3);
  }
}

TEST(IdentifyKnot, FigureEightReadsFigureEightWithDeterminantFive) {
  const Polyline curve = sample(test::figure_eight, 300);
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    SCOPED_TRACE("rotation seed " + std::to_string(seed));
    const KnotReport report = identify_knot(test::randomly_rotated(curve, seed), {.seed = seed});
    EXPECT_EQ(report.type, KnotType::FigureEight);
    EXPECT_EQ(report.alexander, "t^2 - 3t + 1");
    EXPECT_EQ(report.determinant, 5);
  }
}

TEST(IdentifyKnot, FinelySampledRoundCircleIsUnknot) {
  const Polyline circle = sample([](double t) { return Point3(std::cos(t), std::sin(t), 0); }, 1000);
  const KnotReport report = identify_knot(circle);
  EXPECT_EQ(report.type, KnotType::Unknot);
  EXPECT_EQ(report.alexander, "1");
  EXPECT_EQ(report.determinant, 1);
  EXPECT_EQ(report.crossings, 0);
}

TEST(IdentifyKnot, FinelySampledPlanarEllipseIsUnknot) {
  const Polyline ellipse =
      test::randomly_rotated(sample([](double t) { return Point3(3 * std::cos(t), std::sin(t), 0); },
                                    1000),
                             7);
  EXPECT_EQ(identify_knot(ellipse).type, KnotType::Unknot);
}

TEST(IdentifyKnot, FinelySampledNonPlanarUnknotIsUnknot) {
  const auto curve = [](double t) {
    return Point3(2 * std::sin(t), 2 * std::sin(t) * std::cos(t), std::cos(t));
  };
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE("rotation seed " + std::to_string(seed));
    const KnotReport report =
        identify_knot(test::randomly_rotated(sample(curve, 1000), seed), {.seed = seed});
    EXPECT_EQ(report.type, KnotType::Unknot);
    EXPECT_EQ(report.determinant, 1);
  }
}

TEST(IdentifyKnot, FinelySampledBumpedFigureEightIsUnknot) {
  const KnotReport report = identify_knot(sample(test::bumped_figure_eight, 4000));
  EXPECT_EQ(report.type, KnotType::Unknot);
  EXPECT_EQ(report.alexander, "1");
}

TEST(IdentifyKnot, CoarselySampledBumpedFigureEightMissingTheBumpIsFigureEight) {
  // Vertices half a step either side of t = 5 pi / 6: the bump falls between two of them.
  const int n = 60;
  const double phase = 5 * std::numbers::pi / 6 + 0.5 * test::two_pi / n;
  const KnotReport report = identify_knot(sample(test::bumped_figure_eight, n, phase));
  EXPECT_EQ(report.type, KnotType::FigureEight);
  EXPECT_EQ(report.determinant, 5);
}

TEST(IdentifyKnot, TorusKnotTwoFiveReadsOther) {
  const Polyline curve = sample([](double t) { return test::torus_curve(2, 5, t); }, 400);
  const KnotReport report = identify_knot(curve);
  EXPECT_EQ(report.type, KnotType::Other);
  EXPECT_EQ(report.alexander, "t^4 - t^3 + t^2 - t + 1");
  EXPECT_EQ(report.determinant, 5);
}

TEST(IdentifyKnot, TriangleIsUnknotWithoutProjection) {
  const KnotReport report = identify_knot({Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)});
  EXPECT_EQ(report.type, KnotType::Unknot);
  EXPECT_EQ(report.simplified_vertices, 3U);
}

TEST(IdentifyKnot, ReportsSimplifiedVertexCountAndCrossings) {
  const KnotReport report = identify_knot(sample(test::trefoil, 300));
  EXPECT_GE(report.simplified_vertices, 6U);
  EXPECT_LE(report.simplified_vertices, 36U);
  EXPECT_GE(report.crossings, 3);
}

TEST(IdentifyKnot, KnotTypeNames) {
  EXPECT_EQ(to_string(KnotType::Unknot), "unknot");
  EXPECT_EQ(to_string(KnotType::Trefoil), "trefoil");
  EXPECT_EQ(to_string(KnotType::FigureEight), "figure-eight");
  EXPECT_EQ(to_string(KnotType::Other), "other");
  EXPECT_EQ(to_string(KnotType::Unknown), "unknown");
}

// A random polygon's projections have crossings by the thousand (200 random points in a cube:
// the determinant would take hours); above the limit the curve is not read, at once.
TEST(IdentifyKnot, DiagramsWithMoreCrossingsThanTheLimitAreUnknown) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Polyline tangle;
  for (int i = 0; i < 200; ++i) tangle.emplace_back(unit(rng), unit(rng), unit(rng));
  const KnotReport report = identify_knot(tangle);
  EXPECT_EQ(report.type, KnotType::Unknown);
  EXPECT_GT(report.crossings, 300);
  EXPECT_EQ(report.alexander, "");
  EXPECT_EQ(report.determinant, 0);
  // The trefoil's diagram read under a limit of 3 crossings, and not under 2.
  const Polyline trefoil = sample(test::trefoil, 300);
  EXPECT_EQ(identify_knot(trefoil, {.max_crossings = 1000}).type, KnotType::Trefoil);
  const KnotReport limited = identify_knot(trefoil, {.max_crossings = 2});
  EXPECT_EQ(limited.type, KnotType::Unknown);
  EXPECT_GE(limited.crossings, 3);
  EXPECT_THROW(identify_knot(trefoil, {.max_crossings = -1}), InvalidOptions);
}

TEST(IdentifyKnot, TwoPointsAreRejectedWithTheirCount) {
  try {
    identify_knot({Point3(0, 0, 0), Point3(1, 0, 0)});
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "a closed polyline needs at least 3 points (got 2)");
  }
}

TEST(IdentifyKnot, NonFiniteCoordinateIsRejectedWithItsIndex) {
  Polyline curve = sample(test::trefoil, 10);
  curve[5] = Point3(0, std::numeric_limits<double>::quiet_NaN(), 0);
  try {
    identify_knot(curve);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "polyline point 5 has a non-finite coordinate");
  }
}

TEST(IdentifyKnot, SelfIntersectingCurveHasNoGenericProjection) {
  // A planar lemniscate passes twice through the origin.
  const Polyline curve =
      sample([](double t) { return Point3(std::sin(t), std::sin(t) * std::cos(t), 0); }, 100);
  EXPECT_THROW(identify_knot(curve), NumericalFailure);
}

TEST(IdentifyKnot, ZeroProjectionsAreRejected) {
  EXPECT_THROW(identify_knot(sample(test::trefoil, 30), {.seed = 1, .projections = 0}),
               InvalidOptions);
}

}  // namespace
}  // namespace envcrust::knots
