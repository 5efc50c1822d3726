// Tests of detect_boundary on the built-in surfaces at 10k and 50k points and with noise:
// loop counts, Hausdorff distance to the exact boundary, conormal directions, flag rates;
// frames, spacing, options and input checks.
#include "support.h"

#include "envcrust/errors.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <tuple>

namespace envcrust {
namespace {

void print(const std::string& label, const test::Run& run) {
  const test::Score& s = run.score;
  std::cout << label << ": loops " << s.detected_loops << "/" << s.true_loops << " dropped "
            << s.dropped << ", hausdorff " << s.worst_hausdorff << " s, conormal c.c_true > 0.7 "
            << s.good_conormal_fraction << " (min " << s.min_conormal_dot << "), offset "
            << s.mean_offset << " s, recall " << s.recall << ", false positives "
            << s.false_positive << " (" << s.false_positive_count << ")\n";
  for (const auto& w : run.detection.warnings) std::cout << "  " << w << "\n";
}

// (surface, points, noise as a fraction of the bbox diagonal)
using Case = std::tuple<std::string, std::size_t, double>;

class DetectOnSurface : public ::testing::TestWithParam<Case> {};

// Measured with the defaults (seed 11), worst over the 8 surfaces; see the printed lines:
//   10k clean: all loop counts right, Hausdorff <= 3.12 s, recall >= 0.98, false pos <= 0.06%
//   50k clean: all loop counts right, Hausdorff <= 3.93 s (the hemisphere; the trefoil ribbon,
//              once 4.2 s with a stretch of one loop cut off by the closing chord, reads 2.82
//              s; since the ordering's tree takes only links whose conormals agree, 2026-12-04:
//              moebius 3.51 -> 2.59 s, unknot ribbon 2.80 -> 3.65 s, square 2.29 -> 2.37 s),
//              recall >= 0.98, false pos <= 0.07%
//   10k noisy (sigma 0.25% diag): all right, Hausdorff <= 3.12 s, recall >= 0.94, fp <= 0.31%
//   mean offset from the true boundary: -0.49..-0.61 s clean, -0.69..-0.82 s noisy (on the
//   band's centre line, before the fit: about -0.8 s clean)
//   sphere and torus: 0 loops at 10k, 50k and noisy (up to 16 short void chains dropped).
TEST_P(DetectOnSurface, MatchesExactBoundary) {
  const auto& [name, count, noise] = GetParam();
  const test::Run run = test::run_detection(name, count, noise);
  print(name + " " + std::to_string(count / 1000) + "k" + (noise > 0 ? " noisy" : ""), run);
  const test::Score& s = run.score;
  EXPECT_EQ(s.detected_loops, s.true_loops);
  if (s.true_loops == 0) {
    EXPECT_LT(s.false_positive, 1e-4);
    return;
  }
  EXPECT_LT(s.worst_hausdorff, 4.0);
  EXPECT_GT(s.good_conormal_fraction, 0.98);
  EXPECT_GT(s.recall, noise > 0 ? 0.9 : 0.95);
  EXPECT_LT(s.false_positive, noise > 0 ? 0.004 : 0.001);
  // The curve lies on the outermost samples, inside the true boundary, which no sample
  // reaches: by about half a spacing, more with noise (the fit's allowance for it).
  EXPECT_LT(s.mean_offset, 0.0);
  EXPECT_GT(s.mean_offset, noise > 0 ? -1.0 : -0.7);
}

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  for (const char* name : {"cylinder", "hemisphere", "moebius", "trefoil-ribbon", "unknot-ribbon",
                           "square", "saddle", "paraboloid", "sphere", "torus"}) {
    cases.emplace_back(name, 10000, 0.0);
    cases.emplace_back(name, 50000, 0.0);
    cases.emplace_back(name, 10000, 0.0025);
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Builtins, DetectOnSurface, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string label = std::get<0>(info.param) + "_" +
                                               std::to_string(std::get<1>(info.param) / 1000) +
                                               "k" + (std::get<2>(info.param) > 0 ? "_noisy" : "");
                           for (char& c : label) c = c == '-' ? '_' : c;
                           return label;
                         });

TEST(DetectBoundary, OutwardOffsetMovesCurvesOnTheBoundary) {
  for (const char* name : {"cylinder", "saddle", "trefoil-ribbon"}) {
    boundary::BoundaryOptions options;
    options.outward_offset = 0.8;
    const test::Run plain = test::run_detection(name, 10000, 0.0);
    const test::Run moved = test::run_detection(name, 10000, 0.0, 11, options);
    print(std::string(name) + " 10k offset 0.8", moved);
    EXPECT_LT(std::abs(moved.score.mean_offset), 0.4) << name;
    EXPECT_NEAR(moved.score.mean_offset - plain.score.mean_offset, 0.8, 0.05) << name;
  }
}

// Off, the curves stay on the centre line of the flagged band, about 0.8 spacings inside the
// true boundary; on (the default), they move out to the band's outermost samples. With noise
// they keep an allowance for it and move less.
TEST(DetectBoundary, FitToOuterSamplesMovesCurvesOutToTheRimSamples) {
  for (const double noise : {0.0, 0.0025}) {
    boundary::BoundaryOptions off;
    off.fit_to_outer_samples = false;
    const test::Run centre = test::run_detection("cylinder", 10000, noise, 11, off);
    const test::Run fitted = test::run_detection("cylinder", 10000, noise);
    print(std::string("cylinder 10k centre line") + (noise > 0 ? " noisy" : ""), centre);
    print(std::string("cylinder 10k fitted") + (noise > 0 ? " noisy" : ""), fitted);
    EXPECT_LT(centre.score.mean_offset, -0.7) << noise;
    EXPECT_GT(fitted.score.mean_offset - centre.score.mean_offset, noise > 0 ? 0.03 : 0.15) << noise;
    EXPECT_EQ(fitted.score.detected_loops, 2u);
  }
}

TEST(DetectBoundary, FramesAreOrthonormalAndSpacingHonoured) {
  boundary::BoundaryOptions options;
  options.curve_spacing = 0.01;
  const test::Run run = test::run_detection("moebius", 10000, 0.0, 11, options);
  ASSERT_EQ(run.detection.curves.size(), 1u);
  const BoundaryCurve& curve = run.detection.curves[0];
  const std::size_t m = curve.vertices.size();
  for (std::size_t i = 0; i < m; ++i) {
    const BoundaryVertex& v = curve.vertices[i];
    EXPECT_NEAR(v.tangent.squared_length(), 1.0, 1e-9);
    EXPECT_NEAR(v.normal.squared_length(), 1.0, 1e-9);
    EXPECT_NEAR(v.conormal.squared_length(), 1.0, 1e-9);
    EXPECT_NEAR(CGAL::scalar_product(v.tangent, v.normal), 0.0, 1e-9);
    EXPECT_NEAR(CGAL::scalar_product(v.tangent, v.conormal), 0.0, 1e-9);
    EXPECT_NEAR(CGAL::scalar_product(v.normal, v.conormal), 0.0, 1e-9);
    const double step = std::sqrt(
        CGAL::squared_distance(v.position, curve.vertices[(i + 1) % m].position));
    EXPECT_LE(step, 0.01 * 1.0001);
    // Normal lines are propagated continuously along the loop.
    EXPECT_GT(CGAL::scalar_product(v.normal, curve.vertices[(i + 1) % m].normal), 0.5);
  }
  // The Moebius boundary is ~ 2 * 2 pi long: about 1260 vertices at 0.01.
  EXPECT_GT(m, 1200u);
}

TEST(DetectBoundary, DeterministicAndFlagsMatchCurves) {
  const test::Run a = test::run_detection("square", 10000, 0.001);
  const test::Run b = test::run_detection("square", 10000, 0.001);
  EXPECT_EQ(a.detection.is_boundary_point, b.detection.is_boundary_point);
  ASSERT_EQ(a.detection.curves.size(), b.detection.curves.size());
  for (std::size_t c = 0; c < a.detection.curves.size(); ++c) {
    EXPECT_EQ(a.detection.curves[c].polyline(), b.detection.curves[c].polyline());
  }
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    EXPECT_EQ(a.detection.is_boundary_point[i], a.detection.conormals[i] != Vector3(0, 0, 0));
  }
}

// A point file's stages share one neighbour search: a table wider than the detection's 32
// (the first 32 of each row count) gives the same curves; a table of other points or too
// narrow is refused.
TEST(DetectBoundary, FromASharedNeighbourTableAsFromItsOwnSearch) {
  const test::Run a = test::run_detection("trefoil-ribbon", 6000, 0.0);
  const auto lines = normals::estimate_normal_lines(a.samples.points);
  const NeighbourTable wide(a.samples.points, 40);
  const auto b = boundary::detect_boundary(a.samples.points, lines, wide);
  EXPECT_EQ(a.detection.curves.size(), 2u);
  EXPECT_EQ(a.detection.is_boundary_point, b.is_boundary_point);
  ASSERT_EQ(a.detection.curves.size(), b.curves.size());
  for (std::size_t c = 0; c < b.curves.size(); ++c) EXPECT_EQ(a.detection.curves[c].polyline(), b.curves[c].polyline());
  try {
    (void)boundary::detect_boundary(a.samples.points, lines, NeighbourTable(a.samples.points, 24));
    FAIL() << "a table of 24 neighbours accepted";
  } catch (const InvalidOptions& e) {
    EXPECT_EQ(std::string(e.what()), "boundary detection: a neighbour table of 6000 rows of 24 for 6000 points and "
                                     "32 neighbours");
  }
}

void expect_options_error(const boundary::BoundaryOptions& options, const std::string& message) {
  const std::vector<Point3> points(40, Point3(0, 0, 0));
  const std::vector<Vector3> normals(40, Vector3(0, 0, 1));
  try {
    (void)boundary::detect_boundary(points, normals, options);
    ADD_FAILURE() << "no error for " << message;
  } catch (const InvalidOptions& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(DetectBoundary, RejectsBadOptions) {
  boundary::BoundaryOptions o;
  o.neighbors = 4;
  expect_options_error(o, "boundary detection: neighbors must be >= 8 (got 4)");
  o = {};
  o.gap_threshold_deg = 400;
  expect_options_error(o, "boundary detection: gap_threshold_deg must be in (0, 360) (got 400)");
  o = {};
  o.weak_gap_threshold_deg = 120;
  expect_options_error(
      o, "boundary detection: weak_gap_threshold_deg must be in (0, gap_threshold_deg] (got 120)");
  o = {};
  o.link_distance = 0;
  expect_options_error(o, "boundary detection: link_distance must be > 0 (got 0)");
  o = {};
  o.link_min_conormal_dot = 1;
  expect_options_error(o, "boundary detection: link_min_conormal_dot must be in [-1, 1) (got 1)");
  o = {};
  o.smoothing_half_window = -1;
  expect_options_error(o, "boundary detection: smoothing_half_window must be >= 0 (got -1)");
  o = {};
  o.curve_spacing = -0.5;
  expect_options_error(o, "boundary detection: curve_spacing must be > 0 (got -0.5)");
  o = {};
  o.outward_offset = 7;
  expect_options_error(o, "boundary detection: outward_offset must be in [-5, 5] (got 7)");
  o = {};
  o.max_sampled_beyond = 1.5;
  expect_options_error(o, "boundary detection: max_sampled_beyond must be in [0, 1] (got 1.5)");
}

TEST(DetectBoundary, RejectsBadInput) {
  std::vector<Point3> points;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) points.emplace_back(i, j, 0);
  std::vector<Vector3> normals(points.size(), Vector3(0, 0, 2));
  EXPECT_THROW((void)boundary::detect_boundary(points, {}), InvalidInput);
  normals[5] = Vector3(0, 0, 0);
  try {
    (void)boundary::detect_boundary(points, normals);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "normal line 5 is zero or not finite");
  }
  normals[5] = Vector3(0, 0, 1);
  points.resize(20);
  normals.resize(20);
  EXPECT_THROW((void)boundary::detect_boundary(points, normals), DegenerateInput);
}

TEST(DetectBoundary, GridSquareHasOneLoop) {
  // A regular grid: every edge point has a 180-degree gap, every interior point none.
  std::vector<Point3> points;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 60; ++j) points.emplace_back(i * 0.1, j * 0.1, 0);
  const std::vector<Vector3> normals(points.size(), Vector3(0, 0, 1));
  const auto result = boundary::detect_boundary(points, normals);
  ASSERT_EQ(result.curves.size(), 1u);
  for (const BoundaryVertex& v : result.curves[0].vertices) {
    const double x = v.position.x(), y = v.position.y();
    // Within ~1.5 s of the square's edge (corners are rounded by the smoothing).
    const double d = std::min({x, y, 6 - x, 6 - y});
    EXPECT_LT(d, 1.5 * result.spacing + 0.05);
  }
}

}  // namespace
}  // namespace envcrust

namespace envcrust {
namespace {

// A unit square sampled at random (seed 5, 12k points) with a round hole of radius 0.15 and an
// unsampled slot 0.04 x 0.4 (about 3 spacings wide): a sampling gap, not a hole.
std::vector<Point3> square_with_hole_and_slot() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point3> out;
  while (out.size() < 12000) {
    const double x = u(rng), y = u(rng);
    if (std::hypot(x - 0.3, y - 0.5) < 0.15) continue;
    if (x > 0.68 && x < 0.72 && y > 0.3 && y < 0.7) continue;
    out.emplace_back(x, y, 0.0);
  }
  return out;
}

TEST(DetectBoundary, MinLoopWidthDropsNarrowSamplingGapsAndKeepsHoles) {
  const auto points = square_with_hole_and_slot();
  const std::vector<Vector3> normals(points.size(), Vector3(0, 0, 1));
  const auto all = boundary::detect_boundary(points, normals);
  boundary::BoundaryOptions o;
  o.min_loop_width = 7.0;
  const auto wide = boundary::detect_boundary(points, normals, o);
  std::cout << "loops: " << all.curves.size() << " without, " << wide.curves.size() << " with min_loop_width 7\n";
  EXPECT_GT(all.curves.size(), 2u);     // the slot's edges come out as loops too
  EXPECT_EQ(wide.curves.size(), 2u);    // the square's outline and the round hole
  EXPECT_EQ(wide.dropped_loops, all.dropped_loops + (all.curves.size() - 2));
  // loop_widths reports the measure the option compares with: the kept loops are at least
  // 7 spacings wide, and exactly the loops below 7 went.
  ASSERT_EQ(all.loop_widths.size(), all.curves.size());
  ASSERT_EQ(wide.loop_widths.size(), wide.curves.size());
  for (const double w : wide.loop_widths) EXPECT_GE(w, 7.0);
  const auto narrow = std::count_if(all.loop_widths.begin(), all.loop_widths.end(), [](double w) { return w < 7.0; });
  EXPECT_EQ(static_cast<std::size_t>(narrow), all.curves.size() - wide.curves.size());
}


// A unit square sampled at random (seed 7, 12k points) with a lens-shaped hole, |y - 0.5| <
// 0.03 (1 - ((x - 0.5) / 0.25)^2): its tips are too thin for the angle-gap test, so its two
// sides are flagged as two open arcs (the bunny's base slots look like this).
TEST(DetectBoundary, LensHoleWithUnflaggedTipsIsOneLoop) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point3> points;
  while (points.size() < 12000) {
    const double x = u(rng), y = u(rng), t = (x - 0.5) / 0.25;
    if (std::abs(t) < 1 && std::abs(y - 0.5) < 0.03 * (1 - t * t)) continue;
    points.emplace_back(x, y, 0.0);
  }
  const std::vector<Vector3> normals(points.size(), Vector3(0, 0, 1));
  const auto result = boundary::detect_boundary(points, normals);
  ASSERT_EQ(result.curves.size(), 2u);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find(": 2 open arcs joined into one loop across gaps of up to "), std::string::npos)
      << result.warnings[0];
  // One curve is the lens: inside the square's margin, spanning most of its length.
  std::size_t lenses = 0;
  for (const BoundaryCurve& c : result.curves) {
    double xmin = 1, xmax = 0, ymin = 1, ymax = 0;
    for (const BoundaryVertex& v : c.vertices) {
      xmin = std::min(xmin, v.position.x()), xmax = std::max(xmax, v.position.x());
      ymin = std::min(ymin, v.position.y()), ymax = std::max(ymax, v.position.y());
    }
    if (xmin > 0.2 && xmax < 0.8 && ymin > 0.4 && ymax < 0.6) {
      ++lenses;
      EXPECT_GT(xmax - xmin, 0.3);
    }
  }
  EXPECT_EQ(lenses, 1u);
}


// A unit square sampled at random (seed 9, 8k points) with a round hole of radius 0.1 at
// (0.7, 0.5) and, at (0.3, 0.5), a disc of radius 0.1 sampled 10 times more densely (the
// lion head scan has such patches). The angle-gap test flags the dense patch's rim too (its
// nearest neighbours lie on the dense side); the sparse samples around it tell it from a
// hole: as a step in the density (drop_density_steps), or, by default, once its loop is
// made, as a loop beyond which the sheet goes on (max_sampled_beyond).
TEST(DetectBoundary, DensePatchRimIsNoBoundaryButAHoleIs) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point3> points;
  while (points.size() < 8000) {
    const double x = u(rng), y = u(rng);
    if (std::hypot(x - 0.7, y - 0.5) < 0.1) continue;
    if (std::hypot(x - 0.3, y - 0.5) < 0.1) {
      for (int k = 0; k < 10; ++k) {
        const double r = 0.1 * std::sqrt(u(rng)), a = 2 * M_PI * u(rng);
        points.emplace_back(0.3 + r * std::cos(a), 0.5 + r * std::sin(a), 0.0);
      }
      continue;
    }
    points.emplace_back(x, y, 0.0);
  }
  const std::vector<Vector3> normals(points.size(), Vector3(0, 0, 1));
  auto centre_x = [](const BoundaryCurve& c) {
    double x = 0;
    for (const BoundaryVertex& v : c.vertices) x += v.position.x();
    return x / static_cast<double>(c.vertices.size());
  };
  boundary::BoundaryOptions steps;
  steps.drop_density_steps = true;
  const auto stepped = boundary::detect_boundary(points, normals, steps);
  ASSERT_EQ(stepped.curves.size(), 2u);
  for (const BoundaryCurve& c : stepped.curves) EXPECT_FALSE(std::abs(centre_x(c) - 0.3) < 0.05);
  for (const auto& w : stepped.warnings) EXPECT_EQ(w.find(") dropped: its conormals point out of it"), std::string::npos) << w;

  boundary::BoundaryOptions keep_all;
  keep_all.max_sampled_beyond = 1.0;
  const auto all = boundary::detect_boundary(points, normals, keep_all);
  // Outline, hole and the dense patch's rim, each with the fraction the option compares with.
  ASSERT_EQ(all.curves.size(), 3u);
  ASSERT_EQ(all.sampled_beyond.size(), 3u);
  std::size_t patch = 3, hole = 3, outline = 3;
  for (std::size_t c = 0; c < 3; ++c) {
    double xmin = 1;
    for (const BoundaryVertex& v : all.curves[c].vertices) xmin = std::min(xmin, v.position.x());
    if (xmin < 0.1) outline = c;
    else if (centre_x(all.curves[c]) < 0.5) patch = c;
    else hole = c;
  }
  ASSERT_TRUE(patch < 3 && hole < 3 && outline < 3);
  std::cout << "sampled beyond: outline " << all.sampled_beyond[outline] << ", hole " << all.sampled_beyond[hole]
            << ", dense patch " << all.sampled_beyond[patch] << "\n";
  EXPECT_LT(all.sampled_beyond[outline], 0.05);
  EXPECT_LT(all.sampled_beyond[hole], 0.05);
  EXPECT_GT(all.sampled_beyond[patch], 0.5);

  const auto result = boundary::detect_boundary(points, normals);
  ASSERT_EQ(result.curves.size(), 2u);
  EXPECT_EQ(result.dropped_loops, all.dropped_loops + 1);
  for (const BoundaryCurve& c : result.curves) EXPECT_FALSE(std::abs(centre_x(c) - 0.3) < 0.05);
  const auto dropped = std::find_if(result.warnings.begin(), result.warnings.end(), [](const std::string& w) {
    return w.find(") dropped: its conormals point out of it, but beyond ") != std::string::npos;
  });
  ASSERT_NE(dropped, result.warnings.end());
  EXPECT_NE(dropped->find("% of it the surface goes on (the rim of a densely sampled patch, not a boundary)"), std::string::npos) << *dropped;
}

// How far a point of the plane z = 0 lies outside a closed curve in it: 0 inside, else its
// distance to the curve.
double outside_of(const Polyline& curve, const Point3& p) {
  double winding = 0.0, nearest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < curve.size(); ++k) {
    const Point3& a = curve[k];
    const Point3& b = curve[(k + 1) % curve.size()];
    winding += std::atan2((a.x() - p.x()) * (b.y() - p.y()) - (a.y() - p.y()) * (b.x() - p.x()),
                          (a.x() - p.x()) * (b.x() - p.x()) + (a.y() - p.y()) * (b.y() - p.y()));
    nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(Kernel::Segment_3(a, b), p)));
  }
  return std::abs(winding) > M_PI ? 0.0 : nearest;
}

// A unit square sampled at random (seed 9, 12k points) with a shallow bay in its right edge
// (no samples within 0.1 of (1.082, 0.5): 0.018 deep, about 1.5 spacings, and 0.11 wide, too
// open for an inlet) but for two samples on the edge across its mouth, as random samples
// leave them. With take_in_samples_beyond the curve passes outside every sample away from
// the corners, the two included, and not beyond them.
TEST(DetectBoundary, CurvePassesOutsideEverySample) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point3> points;
  while (points.size() < 12000) {
    const double x = u(rng), y = u(rng);
    if (std::hypot(x - 1.082, y - 0.5) >= 0.1) points.emplace_back(x, y, 0.0);
  }
  points.emplace_back(0.999, 0.48, 0.0);
  points.emplace_back(0.999, 0.52, 0.0);
  const std::vector<Vector3> normals(points.size(), Vector3(0, 0, 1));
  boundary::BoundaryOptions options;
  options.take_in_samples_beyond = true;
  const auto result = boundary::detect_boundary(points, normals, options);
  ASSERT_EQ(result.curves.size(), 1u);
  const Polyline curve = result.curves[0].polyline();
  // Away from the corners, which the curve rounds (it turns there, and a conormal is no
  // direction to move along).
  double worst = 0.0;
  for (const Point3& p : points)
    if (std::min(p.x(), 1 - p.x()) > 0.1 || std::min(p.y(), 1 - p.y()) > 0.1) worst = std::max(worst, outside_of(curve, p));
  const double across_mouth = std::max(outside_of(curve, points[12000]), outside_of(curve, points[12001]));
  double beyond_edge = 0.0;
  for (const Point3& p : curve) beyond_edge = std::max(beyond_edge, p.x() - 0.999);
  std::cout << "samples outside the curve: at most " << worst / result.spacing << " spacings (the two across the bay's mouth "
            << across_mouth / result.spacing << "); curve beyond them " << beyond_edge / result.spacing << "\n";
  // Measured: 0.21, 0.31 and 0.25 spacings; without the option (the default) the two across
  // the mouth lie 0.92 spacings outside the curve, and samples elsewhere up to 0.98.
  EXPECT_LT(across_mouth, 0.4 * result.spacing);
  EXPECT_LT(worst, 0.4 * result.spacing);
  EXPECT_LT(beyond_edge, 0.5 * result.spacing);
  const auto plain = boundary::detect_boundary(points, normals);
  ASSERT_EQ(plain.curves.size(), 1u);
  const Polyline plain_curve = plain.curves[0].polyline();
  EXPECT_GT(std::max(outside_of(plain_curve, points[12000]), outside_of(plain_curve, points[12001])),
            0.6 * plain.spacing);
}


// A strip eight sample spacings wide and 60 times longer: the bands of its two long rims lie
// within the linking distance of each other, and the ordering's spanning tree took short
// cuts across the strip (between facing rims, whose conormals are opposite) instead of going
// round its ends: the loop left out the last 2 and 14 units of a 100-long strip (length 172
// of 200). Only links between agreeing conormals enter the tree now, as they join the band.
TEST(DetectBoundary, NarrowStripIsOneLoopRoundItsEnds) {
  constexpr double kLength = 20.0, kWidth = 0.32;
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> along(0.0, kLength), across(0.0, kWidth);
  std::vector<Point3> points;
  for (int i = 0; i < 4000; ++i) points.emplace_back(along(rng), across(rng), 0.0);
  const std::vector<Vector3> normals(points.size(), Vector3(0, 0, 1));
  const auto d = boundary::detect_boundary(points, normals);
  ASSERT_EQ(d.curves.size(), 1u);
  const double s = d.spacing;
  // Every vertex lies near the rectangle's rim, and every stretch of the rim near a vertex.
  auto rim_distance = [&](const Point3& p) {
    const double inside = std::min({p.x(), kLength - p.x(), p.y(), kWidth - p.y()});
    return std::abs(inside);
  };
  double farthest_vertex = 0.0;
  for (const auto& v : d.curves[0].vertices) farthest_vertex = std::max(farthest_vertex, rim_distance(v.position));
  EXPECT_LT(farthest_vertex, 4.0 * s);  // as the built-in surfaces' Hausdorff bound
  const Polyline curve = d.curves[0].polyline();
  double farthest_rim = 0.0;
  for (double t = 0.0; t <= kLength; t += 0.05)
    for (const Point3& rim : {Point3(t, 0, 0), Point3(t, kWidth, 0)}) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const Point3& c : curve) nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(rim, c)));
      farthest_rim = std::max(farthest_rim, nearest);
    }
  EXPECT_LT(farthest_rim, 4.0 * s);
}

}  // namespace
}  // namespace envcrust

namespace envcrust {
namespace {

// A cone of height 1 sampled at random by area (3,000 points on its side), with its base disc
// sampled too when `closed`. Near the tip the side is a tube a few spacings round: the
// neighbours wrap round it, and their projection on the tangent plane leaves a gap the
// angle-gap test flags; on about 4 in 10 such clouds the flagged tip made a loop of its own.
std::vector<Point3> thin_cone(double radius, unsigned seed, bool closed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point3> out;
  for (int i = 0; i < 3000; ++i) {
    const double z = 1.0 - std::sqrt(u(rng));  // the density along z follows the radius
    const double r = radius * (1.0 - z), a = 2.0 * std::numbers::pi * u(rng);
    out.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
  // The base's share of the area: pi r^2 against pi r sqrt(r^2 + 1).
  const int base = closed ? static_cast<int>(3000 * radius / std::hypot(radius, 1.0)) : 0;
  for (int i = 0; i < base; ++i) {
    const double r = radius * std::sqrt(u(rng)), a = 2.0 * std::numbers::pi * u(rng);
    out.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
  }
  return out;
}

constexpr double kConeRadii[] = {0.03, 0.05};
constexpr unsigned kConeSeeds = 8;

TEST(DetectBoundary, ThinClosedConesHaveNoLoopAtTheirTips) {
  std::size_t loops = 0, dropped_groups = 0;
  for (const double radius : kConeRadii) {
    for (unsigned seed = 1; seed <= kConeSeeds; ++seed) {
      const auto points = thin_cone(radius, seed, true);
      const auto found = boundary::detect_boundary(points, normals::estimate_normal_lines(points));
      loops += found.curves.size();
      dropped_groups += std::count_if(found.warnings.begin(), found.warnings.end(), [](const std::string& w) {
        return w.find("boundary candidates dropped: their neighbourhoods are no sheet") != std::string::npos;
      });
    }
  }
  EXPECT_EQ(loops, 0u);
  EXPECT_GT(dropped_groups, 0u);
}

TEST(DetectBoundary, ThinOpenConesKeepTheirRimAndNoLoopAtTheirTips) {
  for (const double radius : kConeRadii) {
    for (unsigned seed = 1; seed <= kConeSeeds; ++seed) {
      const auto points = thin_cone(radius, seed, false);
      const auto found = boundary::detect_boundary(points, normals::estimate_normal_lines(points));
      ASSERT_EQ(found.curves.size(), 1u) << "radius " << radius << ", seed " << seed;
      double highest = 0.0;
      for (const auto& v : found.curves.front().vertices) highest = std::max(highest, v.position.z());
      EXPECT_LT(highest, 0.05) << "radius " << radius << ", seed " << seed;  // the rim, at z 0
    }
  }
}

}  // namespace
}  // namespace envcrust
