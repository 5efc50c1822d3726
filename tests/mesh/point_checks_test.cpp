// merge_duplicate_points and spread_dimension: the first copy represents each group, NaN is
// named, and points on a point, a line (also rounded as a file prints it) and a plane read as
// such.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <string>

using namespace envcrust;

TEST(MergeDuplicatePoints, keeps_first_occurrences_in_order_and_maps_every_input) {
  const std::vector<Point3> points{{1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
  const mesh::MergedPoints m = mesh::merge_duplicate_points(points);
  EXPECT_EQ(m.duplicates, 3u);
  ASSERT_EQ(m.points.size(), 3u);
  EXPECT_EQ(m.points[0], Point3(1, 0, 0));
  EXPECT_EQ(m.points[1], Point3(0, 1, 0));
  EXPECT_EQ(m.points[2], Point3(0, 0, 1));
  EXPECT_EQ(m.input_to_merged, (std::vector<Index>{0, 1, 0, 2, 1, 0}));
}

TEST(MergeDuplicatePoints, names_a_non_finite_point) {
  std::vector<Point3> points{{0, 0, 0}, {1, 1, 1}, {0, std::numeric_limits<double>::quiet_NaN(), 0}};
  try {
    (void)mesh::merge_duplicate_points(points);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "point 2 has a non-finite coordinate");
  }
}

TEST(SpreadDimension, tells_a_point_a_line_a_plane_and_a_volume) {
  std::vector<Point3> one(5, Point3(2, 3, 4));
  EXPECT_EQ(mesh::spread_dimension(one, 1e-12), 0);
  // On the line t (1, 2, 3), each coordinate rounded to 6 digits as a point file prints it.
  std::vector<Point3> line;
  for (int i = 0; i < 50; ++i) {
    auto round6 = [](double v) { return std::strtod(std::to_string(v).c_str(), nullptr); };
    const double t = i / 7.0;
    line.emplace_back(round6(t), round6(2 * t), round6(3 * t));
  }
  const double diagonal = mesh::bbox_diagonal(line);
  EXPECT_EQ(mesh::spread_dimension(line, 1e-6 * diagonal), 1);
  EXPECT_EQ(mesh::spread_dimension(line, 1e-12 * diagonal), 3) << "rounding scattered them around the line";
  std::vector<Point3> plane;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j) plane.emplace_back(i, j, 0.5 * i - 0.25 * j);
  EXPECT_EQ(mesh::spread_dimension(plane, 1e-9), 2);
  plane.emplace_back(3, 3, 1);
  EXPECT_EQ(mesh::spread_dimension(plane, 1e-9), 3);
}
