// Tests of estimate_normal_lines and average_spacing on the built-in surfaces (10k seeded
// points, with and without noise) and on small hand-made inputs.
#include "angle_stats.h"

#include "envcrust/errors.h"
#include "envcrust/normals.h"
#include "envcrust/surfaces.h"

#include <CGAL/pca_estimate_normals.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

namespace envcrust {
namespace {

PointSet sample(const std::string& name, std::size_t count, double noise, std::uint64_t seed = 7) {
  const auto surface = surfaces::make_builtin(name);
  surfaces::SampleOptions options;
  options.count = count;
  options.noise_rel_diag = noise;
  options.with_normals = true;
  options.seed = seed;
  return surfaces::sample_surface(*surface, options);
}

// Measurement behind the defaults (printed, asserted loosely): mean / p95 / max degrees.
TEST(EstimateNormalLines, MethodComparison) {
  struct Config {
    const char* label;
    normals::NormalOptions options;
  };
  const Config configs[] = {
      {"pca k16", {normals::NormalMethod::Pca, 16, 2}},
      {"pca k24", {normals::NormalMethod::Pca, 24, 2}},
      {"pca k32", {normals::NormalMethod::Pca, 32, 2}},
      {"jet k18", {normals::NormalMethod::Jet, 18, 2}},
  };
  for (const char* name : {"sphere", "cylinder", "moebius", "trefoil-ribbon", "saddle"}) {
    for (const double noise : {0.0, 0.0025}) {
      const PointSet ps = sample(name, 10000, noise);
      for (const Config& config : configs) {
        const auto s = test::line_errors(normals::estimate_normal_lines(ps.points, config.options),
                                         ps.normals);
        std::cout << name << " noise " << noise << " " << config.label << ": mean " << s.mean
                  << " p95 " << s.p95 << " max " << s.max << "\n";
        EXPECT_LT(s.mean, noise > 0 ? 15.0 : 5.0) << name << " " << config.label;
      }
    }
  }
}

TEST(EstimateNormalLines, DefaultsWithinAFewDegrees) {
  for (const char* name : {"sphere", "cylinder", "moebius", "trefoil-ribbon"}) {
    const PointSet ps = sample(name, 10000, 0.0);
    const auto n = normals::estimate_normal_lines(ps.points);
    ASSERT_EQ(n.size(), ps.size());
    for (const Vector3& v : n) ASSERT_NEAR(v.squared_length(), 1.0, 1e-9);
    const auto s = test::line_errors(n, ps.normals);
    std::cout << name << " default: mean " << s.mean << " p95 " << s.p95 << " max " << s.max << "\n";
    EXPECT_LT(s.mean, 1.0) << name;
    EXPECT_LT(s.p95, 2.0) << name;
  }
}

TEST(EstimateNormalLines, DefaultsUnderNoise) {
  for (const char* name : {"sphere", "cylinder", "moebius", "trefoil-ribbon"}) {
    const PointSet ps = sample(name, 10000, 0.0025);
    const auto s = test::line_errors(normals::estimate_normal_lines(ps.points), ps.normals);
    std::cout << name << " noisy default: mean " << s.mean << " p95 " << s.p95 << " max " << s.max << "\n";
    EXPECT_LT(s.mean, 8.0) << name;
    EXPECT_LT(s.p95, 16.0) << name;
  }
}

TEST(EstimateNormalLines, DeterministicAcrossCalls) {
  const PointSet ps = sample("saddle", 3000, 0.001);
  for (const auto method : {normals::NormalMethod::Pca, normals::NormalMethod::Jet}) {
    const normals::NormalOptions options{method, 18, 2};
    const auto a = normals::estimate_normal_lines(ps.points, options);
    const auto b = normals::estimate_normal_lines(ps.points, options);
    ASSERT_EQ(a, b);
  }
}

TEST(EstimateNormalLines, PlaneGivesZ) {
  std::vector<Point3> pts;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) pts.emplace_back(i * 0.1, j * 0.1 + 0.01 * i, 0.0);
  for (const auto method : {normals::NormalMethod::Pca, normals::NormalMethod::Jet}) {
    for (const Vector3& n : normals::estimate_normal_lines(pts, {method, 16, 2})) {
      EXPECT_NEAR(std::abs(n.z()), 1.0, 1e-9);
    }
  }
}

TEST(EstimateNormalLines, SmallInputUsesAllPoints) {
  const std::vector<Point3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.01}, {0.5, 0.2, 0}};
  const auto n = normals::estimate_normal_lines(pts);
  ASSERT_EQ(n.size(), pts.size());
  for (const Vector3& v : n) EXPECT_GT(std::abs(v.z()), 0.99);
}

TEST(EstimateNormalLines, RejectsBadOptionsAndInput) {
  const std::vector<Point3> pts{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  try {
    (void)normals::estimate_normal_lines(pts, {normals::NormalMethod::Pca, 3, 2});
    FAIL();
  } catch (const InvalidOptions& e) {
    EXPECT_EQ(std::string(e.what()), "normal estimation: neighbors must be >= 6 (got 3)");
  }
  EXPECT_THROW((void)normals::estimate_normal_lines(pts, {normals::NormalMethod::Jet, 18, 0}),
               InvalidOptions);
  EXPECT_THROW((void)normals::estimate_normal_lines({{0, 0, 0}, {1, 0, 0}}), DegenerateInput);
  std::vector<Point3> bad = pts;
  bad[2] = Point3(0, std::nan(""), 0);
  try {
    (void)normals::estimate_normal_lines(bad);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()), "point 2 has a non-finite coordinate");
  }
}

// CGAL's convention: the sum of the distances to the k nearest other points divided by k + 1
// (the point itself counts as a neighbour at distance 0), averaged over the cloud.
TEST(AverageSpacing, MatchesBruteForce) {
  const PointSet ps = sample("saddle", 400, 0.0);
  for (const int k : {2, 6, 10}) {
    double total = 0;
    for (const Point3& p : ps.points) {
      std::vector<double> d;
      for (const Point3& q : ps.points) d.push_back(std::sqrt(CGAL::squared_distance(p, q)));
      std::sort(d.begin(), d.end());
      for (int j = 0; j <= k; ++j) total += d[static_cast<std::size_t>(j)] / (k + 1);
    }
    EXPECT_NEAR(normals::average_spacing(ps.points, k), total / 400, 1e-12) << k;
  }
}

// The shared neighbour search changes nothing: PCA over a table's rows gives the normals
// CGAL's pca_estimate_normals gives over its own tree (same points, same plane fit), and the
// spacing from a table is CGAL's.
TEST(EstimateNormalLines, FromANeighbourTableAsCgalsPca) {
  const PointSet ps = sample("trefoil-ribbon", 3000, 0.0025);
  using PointNormal = std::pair<Point3, Vector3>;
  std::vector<PointNormal> data;
  for (const Point3& p : ps.points) data.emplace_back(p, Vector3(0, 0, 0));
  CGAL::pca_estimate_normals<CGAL::Sequential_tag>(
      data, 24,
      CGAL::parameters::point_map(CGAL::First_of_pair_property_map<PointNormal>())
          .normal_map(CGAL::Second_of_pair_property_map<PointNormal>()));
  const NeighbourTable table(ps.points, 32);  // a wider table: the first 24 of each row count
  const auto lines = normals::estimate_normal_lines(ps.points, table);
  ASSERT_EQ(lines.size(), ps.points.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Vector3 n = data[i].second / std::sqrt(data[i].second.squared_length());
    if (std::abs(std::abs(n * lines[i]) - 1.0) > 1e-9) ++differ;
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_NEAR(normals::average_spacing(ps.points, table, 6), normals::average_spacing(ps.points, 6), 1e-12);
  EXPECT_THROW((void)normals::estimate_normal_lines(ps.points, NeighbourTable(ps.points, 20)), InvalidOptions);
  EXPECT_THROW((void)normals::average_spacing(ps.points, NeighbourTable(ps.points, 5), 6), InvalidOptions);
}

TEST(AverageSpacing, ScalesWithDensity) {
  const PointSet a = sample("sphere", 10000, 0.0);
  const PointSet b = sample("sphere", 40000, 0.0);
  const double ratio = normals::average_spacing(a.points) / normals::average_spacing(b.points);
  EXPECT_NEAR(ratio, 2.0, 0.1);
  EXPECT_THROW((void)normals::average_spacing(a.points, 1), InvalidOptions);
  EXPECT_THROW((void)normals::average_spacing({{0, 0, 0}, {1, 0, 0}}), DegenerateInput);
}

}  // namespace
}  // namespace envcrust
