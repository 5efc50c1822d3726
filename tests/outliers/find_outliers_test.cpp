// Tests of find_outliers: no sample of a built-in surface is flagged (clean or noisy), points
// moved off the surface or set apart beyond its rim are, and close sheets keep their points.
#include "fixtures/surface_samples.h"

#include "envcrust/errors.h"
#include "envcrust/normals.h"
#include "envcrust/outliers.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace envcrust {
namespace {

std::size_t flagged(const outliers::OutlierReport& r, std::size_t first, std::size_t last) {
  std::size_t n = 0;
  for (std::size_t i = first; i < last; ++i) n += r.is_outlier[i] != 0;
  return n;
}

std::vector<Point3> few_points_of(const std::vector<Point3>& points, std::size_t n) {
  return {points.begin(), points.begin() + static_cast<std::ptrdiff_t>(n)};
}

TEST(FindOutliers, NoSampleOfABuiltInSurfaceIsFlagged) {
  for (const auto& name : surfaces::builtin_names()) {
    for (const std::size_t count : {1000u, 10000u}) {
      for (const double noise : {0.0, 0.0025}) {
        const auto points = fixtures::builtin_samples(name, count, noise, 11).points;
        const auto report = outliers::find_outliers(points);
        EXPECT_EQ(report.count(), 0u) << name << " " << count << " noise " << noise;
      }
    }
  }
}

// Every 500th sample moved along its normal (alternating sides) by 4 average spacings, or 12
// noise sigmas where that is more: all 20 are flagged as off their neighbours' plane, and no
// other sample is. (Measured: at 2 spacings 18-20 of 20 on clean samples; nearer the noise
// they read as noise. Every 50th sample moved makes a sparse second layer, not strays.)
TEST(FindOutliers, SamplesMovedOffTheSurfaceAreFlagged) {
  for (const std::string name : {"cylinder", "trefoil-ribbon", "sphere"}) {
    for (const double noise : {0.0, 0.0025}) {
      envelope::SurfaceSamples set = fixtures::builtin_samples(name, 10000, noise, 5);
      const double spacing = normals::average_spacing(set.points);
      const double sigma = noise * surfaces::bbox_diagonal(*surfaces::make_builtin(name));
      const double offset = std::max(4.0 * spacing, 12.0 * sigma);
      std::vector<char> moved(set.points.size(), 0);
      for (std::size_t i = 0; i < set.points.size(); i += 500) {
        const double side = (i / 500) % 2 == 0 ? 1.0 : -1.0;
        set.points[i] = set.points[i] + side * offset * set.normals[i];
        moved[i] = 1;
      }
      const auto report = outliers::find_outliers(set.points);
      std::size_t hits = 0, false_alarms = 0;
      for (std::size_t i = 0; i < set.points.size(); ++i) {
        if (!report.is_outlier[i]) continue;
        (moved[i] ? hits : false_alarms) += 1;
      }
      EXPECT_EQ(hits, 20u) << name << " noise " << noise;
      EXPECT_EQ(false_alarms, 0u) << name << " noise " << noise;
      EXPECT_EQ(report.off_plane, hits + false_alarms) << name;
    }
  }
}

// Specks in the plane of the square, 10 spacings beyond its rim and far from each other, are
// isolated (their neighbours' plane is theirs too).
TEST(FindOutliers, LoneSamplesBeyondTheRimAreIsolated) {
  std::vector<Point3> points = fixtures::builtin_samples("square", 10000, 0.0, 3).points;  // [-1, 1]^2 in z = 0
  const double spacing = normals::average_spacing(points);
  const std::size_t first = points.size();
  for (int i = 0; i < 8; ++i) points.emplace_back(-0.8 + 0.2 * i, 1.0 + 10.0 * spacing, 0.0);
  const auto report = outliers::find_outliers(points);
  EXPECT_EQ(flagged(report, first, points.size()), 8u);
  EXPECT_EQ(report.isolated, 8u);
  EXPECT_EQ(report.count(), 8u);
}

// Two samplings of the square a third of a spacing apart (a thin plate) read as one noisy sheet:
// nothing is flagged.
TEST(FindOutliers, CloseSheetsKeepTheirPoints) {
  std::vector<Point3> points = fixtures::builtin_samples("square", 5000, 0.0, 3).points;
  const double spacing = normals::average_spacing(points);
  for (const auto& p : fixtures::builtin_samples("square", 5000, 0.0, 4).points) points.emplace_back(p.x(), p.y(), spacing / 3.0);
  EXPECT_EQ(outliers::find_outliers(points).count(), 0u);
}

// A point file's stages share one neighbour search (32 for the boundary): the outliers read
// the first 16 of each row and find what their own search finds; a table of other points
// is refused.
TEST(FindOutliers, FromASharedNeighbourTableAsFromItsOwnSearch) {
  std::vector<Point3> points = fixtures::builtin_samples("square", 5000, 0.0, 3).points;
  const double spacing = normals::average_spacing(points);
  for (int i = 0; i < 8; ++i) points.emplace_back(-0.8 + 0.2 * i, 1.0 + 10.0 * spacing, 0.0);
  for (int i = 0; i < 8; ++i) points.emplace_back(-0.7 + 0.2 * i, 0.0, 3.0 * spacing);
  const auto own = outliers::find_outliers(points);
  const auto shared = outliers::find_outliers(points, NeighbourTable(points, 32));
  EXPECT_EQ(own.count(), 16u);
  EXPECT_EQ(own.is_outlier, shared.is_outlier);
  EXPECT_EQ(own.isolated, shared.isolated);
  try {
    (void)outliers::find_outliers(points, NeighbourTable(few_points_of(points, 100), 32));
    FAIL() << "a table of other points accepted";
  } catch (const InvalidOptions& e) {
    EXPECT_EQ(std::string(e.what()), "find_outliers: a neighbour table of 100 rows of 32 for 5016 points and 16 neighbours");
  }
}

TEST(FindOutliers, FewPointsAreNeverFlaggedAndBadOptionsAreRefused) {
  std::vector<Point3> few;
  for (int i = 0; i < 16; ++i) few.emplace_back(i % 4, i / 4, i == 5 ? 100.0 : 0.0);
  const auto report = outliers::find_outliers(few);
  EXPECT_EQ(report.is_outlier.size(), few.size());
  EXPECT_EQ(report.count(), 0u);
  outliers::OutlierOptions bad;
  bad.neighbors = 3;
  try {
    outliers::find_outliers(few, bad);
    FAIL() << "neighbors 3 accepted";
  } catch (const InvalidOptions& e) {
    EXPECT_EQ(std::string(e.what()), "OutlierOptions::neighbors out of range: 3.000000");
  }
  bad = {};
  bad.isolated_rel_spacing = 1.0;
  EXPECT_THROW(outliers::find_outliers(few, bad), InvalidOptions);
}

}  // namespace
}  // namespace envcrust
