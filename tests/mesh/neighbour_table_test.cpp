// Tests of NeighbourTable: rows against a brute-force search, duplicates, tiny sets, subsets.
#include "envcrust/errors.h"
#include "envcrust/neighbour_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace envcrust {
namespace {

std::vector<Point3> random_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point3> out;
  for (std::size_t i = 0; i < n; ++i) out.emplace_back(u(rng), u(rng), 0.2 * u(rng));
  return out;
}

// The distances from point i to its k nearest others, by brute force.
std::vector<double> brute_distances(const std::vector<Point3>& points, std::size_t i, unsigned k) {
  std::vector<double> d;
  for (std::size_t j = 0; j < points.size(); ++j)
    if (j != i) d.push_back(std::sqrt(CGAL::squared_distance(points[i], points[j])));
  std::sort(d.begin(), d.end());
  d.resize(k);
  return d;
}

void expect_rows_are_nearest(const NeighbourTable& table, const std::vector<Point3>& points, unsigned k) {
  ASSERT_EQ(table.size(), points.size());
  ASSERT_EQ(table.k(), k);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto row = table.of(i);
    const std::vector<double> want = brute_distances(points, i, k);
    for (unsigned a = 0; a < k; ++a) {
      ASSERT_NE(row[a], i) << "point " << i << " is its own neighbour";
      ASSERT_LT(row[a], points.size());
      EXPECT_NEAR(std::sqrt(CGAL::squared_distance(points[i], points[row[a]])), want[a], 1e-12)
          << "point " << i << ", neighbour " << a;
    }
  }
}

TEST(NeighbourTable, rows_hold_the_k_nearest_other_points_nearest_first) {
  const auto points = random_points(1500, 3);
  const NeighbourTable table(points, 12);
  expect_rows_are_nearest(table, points, 12);
  // The order visits every point once.
  std::vector<std::size_t> order = table.order();
  std::sort(order.begin(), order.end());
  for (std::size_t r = 0; r < order.size(); ++r) ASSERT_EQ(order[r], r);
}

TEST(NeighbourTable, a_duplicate_is_a_neighbour_at_distance_zero_but_a_point_is_not_its_own) {
  auto points = random_points(200, 5);
  points.push_back(points[17]);
  points.push_back(points[17]);
  const NeighbourTable table(points, 4);
  expect_rows_are_nearest(table, points, 4);
  for (const std::size_t i : {std::size_t{17}, std::size_t{200}, std::size_t{201}}) {
    EXPECT_EQ(CGAL::squared_distance(points[i], points[table.of(i)[0]]), 0.0);
    EXPECT_EQ(CGAL::squared_distance(points[i], points[table.of(i)[1]]), 0.0);
  }
}

TEST(NeighbourTable, fewer_points_than_k_give_rows_of_all_the_others) {
  const std::vector<Point3> points{{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}};
  const NeighbourTable table(points, 10);
  EXPECT_EQ(table.k(), 3u);
  expect_rows_are_nearest(table, points, 3);
  EXPECT_EQ(NeighbourTable(std::vector<Point3>{}, 5).size(), 0u);
  EXPECT_THROW(NeighbourTable(points, 0), InvalidOptions);
}

TEST(NeighbourTable, a_subset_reads_as_a_table_built_on_the_kept_points) {
  const auto points = random_points(1200, 11);
  const NeighbourTable table(points, 10);
  std::vector<char> keep(points.size(), 1);
  std::vector<Point3> kept;
  for (std::size_t i = 0; i < points.size(); ++i) {
    keep[i] = i % 7 == 3 ? 0 : 1;  // every point loses some neighbours somewhere
    if (keep[i]) kept.push_back(points[i]);
  }
  const NeighbourTable sub = table.subset(points, keep);
  expect_rows_are_nearest(sub, kept, 10);
  std::vector<std::size_t> order = sub.order();
  std::sort(order.begin(), order.end());
  for (std::size_t r = 0; r < order.size(); ++r) ASSERT_EQ(order[r], r);
  // Keeping all is the same table.
  const NeighbourTable all = table.subset(points, std::vector<char>(points.size(), 1));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto a = all.of(i), b = table.of(i);
    ASSERT_TRUE(std::equal(a.begin(), a.end(), b.begin(), b.end())) << i;
  }
  EXPECT_THROW((void)table.subset(kept, keep), InvalidInput);
}

}  // namespace
}  // namespace envcrust
