// Input and option checks: exact messages for NaN, too few, collinear and coplanar points,
// duplicates merged and reported, options refused with field and value.
#include "support.h"

#include "envcrust/errors.h"

#include <gtest/gtest.h>

#include <limits>

using namespace envcrust;
using namespace envcrust::powercrust;

namespace {

// The message of the exception `run` throws, or "" when it throws none of type E.
template <class E, class F>
std::string message_of(F&& run) {
  try {
    run();
  } catch (const E& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PowerCrustChecks, non_finite_coordinate_names_the_point) {
  auto points = test_support::sphere_rings(6, 8);
  points[12] = Point3(0, std::numeric_limits<double>::quiet_NaN(), 0);
  EXPECT_EQ(message_of<InvalidInput>([&] { (void)power_crust(points); }),
            "point 12 has a non-finite coordinate");
  points[12] = Point3(std::numeric_limits<double>::infinity(), 0, 0);
  EXPECT_EQ(message_of<InvalidInput>([&] { (void)power_crust(points); }),
            "point 12 has a non-finite coordinate");
}

TEST(PowerCrustChecks, four_points_are_too_few) {
  const std::vector<Point3> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}};
  EXPECT_EQ(message_of<DegenerateInput>([&] { (void)power_crust(points); }),
            "need at least 5 distinct points, got 4");
  const std::vector<Point3> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(message_of<DegenerateInput>([&] { (void)power_crust(three); }),
            "need at least 5 distinct points, got 3");
}

TEST(PowerCrustChecks, coplanar_points_are_refused) {
  std::vector<Point3> points;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) points.emplace_back(i, j, 0.5 * i - 0.25 * j);
  EXPECT_EQ(message_of<DegenerateInput>([&] { (void)power_crust(points); }),
            "all 100 points are coplanar: nothing to reconstruct");
}

TEST(PowerCrustChecks, collinear_points_are_refused) {
  std::vector<Point3> points;
  for (int i = 0; i < 20; ++i) points.emplace_back(i, 2 * i, -i);
  EXPECT_EQ(message_of<DegenerateInput>([&] { (void)power_crust(points); }),
            "all 20 points are collinear: nothing to reconstruct");
}

TEST(PowerCrustChecks, duplicates_are_merged_and_reported) {
  auto points = test_support::sample_builtin("sphere", 1000, 0.0);
  const std::size_t distinct = points.size();
  points.push_back(points[3]);
  points.push_back(points[500]);
  points.push_back(points[3]);
  const auto result = power_crust(points);
  EXPECT_EQ(result.stats.input_points, distinct + 3);
  EXPECT_EQ(result.stats.duplicate_points, 3u);
  ASSERT_EQ(result.samples.size(), distinct);
  ASSERT_EQ(result.input_to_sample.size(), distinct + 3);
  EXPECT_EQ(result.input_to_sample[distinct], 3u);
  EXPECT_EQ(result.input_to_sample[distinct + 1], 500u);
  EXPECT_EQ(result.input_to_sample[distinct + 2], 3u);
  for (std::size_t i = 0; i < distinct; ++i) EXPECT_EQ(result.input_to_sample[i], i);
  ASSERT_FALSE(result.warnings.empty());
  EXPECT_EQ(result.warnings.front(), "3 duplicate points merged");
  EXPECT_TRUE(test_support::crust_topology(result.crust).is_closed());
}

TEST(PowerCrustChecks, options_out_of_range_name_field_and_value) {
  const auto points = test_support::sphere_rings(6, 8);
  PowerCrustOptions options;
  options.bounding_box_scale = 0.5;
  EXPECT_EQ(message_of<InvalidOptions>([&] { (void)power_crust(points, options); }),
            "PowerCrustOptions.bounding_box_scale must be in (1, 1000] (got 0.5)");
  options = {};
  options.pole_joggle = 0.05;
  EXPECT_EQ(message_of<InvalidOptions>([&] { (void)power_crust(points, options); }),
            "PowerCrustOptions.pole_joggle must be in [0, 1e-2] (got 0.05)");
  options = {};
  options.neighbor_threshold = 2.0;
  EXPECT_EQ(message_of<InvalidOptions>([&] { (void)power_crust(points, options); }),
            "PowerCrustOptions.neighbor_threshold must be in [-1, 1] (got 2)");
  options = {};
  options.second_pass_threshold = -1.5;
  EXPECT_EQ(message_of<InvalidOptions>([&] { (void)power_crust(points, options); }),
            "PowerCrustOptions.second_pass_threshold must be in [-1, 1] (got -1.5)");
  options = {};
  options.sampling_estimate = 0.0;
  EXPECT_EQ(message_of<InvalidOptions>([&] { (void)power_crust(points, options); }),
            "PowerCrustOptions.sampling_estimate must be in (0, 1] (got 0)");
  options = {};
  options.min_pole_radius_rel_spacing = -1.0;
  EXPECT_EQ(message_of<InvalidOptions>([&] { (void)power_crust(points, options); }),
            "PowerCrustOptions.min_pole_radius_rel_spacing must be a finite number >= 0 (got -1)");
}
