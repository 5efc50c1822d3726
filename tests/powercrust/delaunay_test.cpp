// The bounding cube and the Delaunay cells with their Voronoi vertices, as exposed by the API.
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace envcrust;
using namespace envcrust::powercrust;

TEST(PowerCrustDelaunay, bounding_cube_is_centred_on_data_far_from_the_origin) {
  auto points = test_support::sample_builtin("sphere", 2000, 0.0);
  for (auto& p : points) p = Point3(p.x() + 1000, p.y() - 500, p.z() + 20);
  const auto result = power_crust(points);
  // The sphere spans 2 per axis: corners at centre +- 4 * 2.
  for (const auto& c : result.bounding_points) {
    EXPECT_NEAR(std::abs(c.x() - 1000), 8.0, 0.01);
    EXPECT_NEAR(std::abs(c.y() + 500), 8.0, 0.01);
    EXPECT_NEAR(std::abs(c.z() - 20), 8.0, 0.01);
  }
  const auto t = test_support::crust_topology(result.crust);
  EXPECT_TRUE(t.is_closed());
  EXPECT_EQ(t.euler_characteristic, 2);
}

TEST(PowerCrustDelaunay, kept_cells_carry_their_circumcentres_and_poles) {
  const auto points = test_support::sample_builtin("torus", 2000, 0.0);
  PowerCrustOptions options;
  options.keep_delaunay_cells = true;
  const auto result = power_crust(points, options);
  ASSERT_EQ(result.delaunay_cells.size(), result.stats.delaunay_cells);
  // About 6.5 cells per point for points in space; surface samples give more.
  EXPECT_GT(result.delaunay_cells.size(), 5 * points.size());
  EXPECT_LT(result.delaunay_cells.size(), 12 * points.size());
  const std::size_t n = result.samples.size();
  auto position = [&](Index v) { return v < n ? result.samples[v] : result.bounding_points[v - n]; };
  std::set<Index> poles_seen;
  for (const auto& cell : result.delaunay_cells) {
    EXPECT_TRUE(std::is_sorted(cell.vertices.begin(), cell.vertices.end()));
    for (Index v : cell.vertices) {
      const double d = std::sqrt(CGAL::squared_distance(cell.center, position(v)));
      EXPECT_NEAR(d, cell.radius, 1e-9 * std::max(1.0, cell.radius));
    }
    if (cell.pole != kNoPole) poles_seen.insert(cell.pole);
  }
  // Every pole is some cell's centre.
  EXPECT_EQ(poles_seen.size(), result.poles.size());
}
