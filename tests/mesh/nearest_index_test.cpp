// Tests of NearestIndex: queries against a brute-force search, and an index of no points.
#include "envcrust/nearest_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace envcrust {
namespace {

TEST(NearestIndex, queries_match_a_brute_force_search) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point3> points;
  for (int i = 0; i < 500; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  const NearestIndex index(points);
  for (int k = 0; k < 50; ++k) {
    const Point3 q(u(rng), u(rng), u(rng));
    std::vector<std::size_t> by_distance(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) by_distance[i] = i;
    std::sort(by_distance.begin(), by_distance.end(), [&](std::size_t a, std::size_t b) {
      return CGAL::squared_distance(q, points[a]) < CGAL::squared_distance(q, points[b]);
    });
    const auto [nearest, d] = index.nearest(q);
    EXPECT_EQ(nearest, by_distance[0]);
    EXPECT_NEAR(d, std::sqrt(CGAL::squared_distance(q, points[nearest])), 1e-12);
    // Halfway between the 10th and the 11th nearest: no point on the sphere.
    const double r = 0.5 * (std::sqrt(CGAL::squared_distance(q, points[by_distance[9]])) +
                            std::sqrt(CGAL::squared_distance(q, points[by_distance[10]])));
    std::vector<std::size_t> inside;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (CGAL::squared_distance(q, points[i]) <= r * r) inside.push_back(i);
    ASSERT_EQ(inside.size(), 10u);
    EXPECT_EQ(index.within(q, r), inside);
    EXPECT_TRUE(index.any_within(q, r));
    EXPECT_FALSE(index.any_within(q, 0.5 * d));
  }
}

// A closed surface has no boundary curve: indexes of its curves' vertices hold no points, and
// every query answers "none" (CGAL asserts on building an empty tree).
TEST(NearestIndex, an_index_of_no_points_answers_every_query_with_none) {
  const std::vector<Point3> none;
  const NearestIndex index(none);
  const Point3 q(0, 0, 0);
  EXPECT_TRUE(index.empty());
  EXPECT_EQ(index.size(), 0u);
  EXPECT_FALSE(index.any_within(q, 1.0));
  EXPECT_TRUE(index.within(q, 1.0).empty());
  EXPECT_TRUE(index.nearest(q, 3).empty());
  EXPECT_TRUE(index.nearest_indices(q, 3).empty());
}

}  // namespace
}  // namespace envcrust
