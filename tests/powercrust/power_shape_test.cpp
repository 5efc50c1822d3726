// The power shape: simplices among In poles only, sorted and without duplicates.
#include "support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace envcrust;
using namespace envcrust::powercrust;

TEST(PowerCrustPowerShape, simplices_join_inner_poles_once_each) {
  const auto points = test_support::sample_builtin("torus", 5000, 0.001);
  const auto result = power_crust(points);
  const auto& shape = result.power_shape;
  EXPECT_FALSE(shape.edges.empty());
  EXPECT_FALSE(shape.triangles.empty());
  EXPECT_FALSE(shape.tetrahedra.empty());
  auto inner = [&](Index p) { return result.poles[p].label == PoleLabel::In && !result.poles[p].is_hidden; };
  for (const auto& e : shape.edges) EXPECT_TRUE(e[0] < e[1] && inner(e[0]) && inner(e[1]));
  for (const auto& t : shape.triangles)
    EXPECT_TRUE(std::is_sorted(t.begin(), t.end()) && inner(t[0]) && inner(t[1]) && inner(t[2]));
  EXPECT_TRUE(std::adjacent_find(shape.edges.begin(), shape.edges.end()) == shape.edges.end());
  EXPECT_TRUE(std::adjacent_find(shape.triangles.begin(), shape.triangles.end()) == shape.triangles.end());
  EXPECT_TRUE(std::is_sorted(shape.tetrahedra.begin(), shape.tetrahedra.end()));
  // Every face of an inner tetrahedron is an inner triangle.
  const std::set<std::array<Index, 3>> triangles(shape.triangles.begin(), shape.triangles.end());
  for (const auto& t : shape.tetrahedra) {
    EXPECT_TRUE(triangles.count({t[1], t[2], t[3]}) && triangles.count({t[0], t[2], t[3]}) &&
                triangles.count({t[0], t[1], t[3]}) && triangles.count({t[0], t[1], t[2]}));
  }
}

TEST(PowerCrustPowerShape, outputs_are_skipped_when_not_asked_for) {
  const auto points = test_support::sample_builtin("sphere", 2000, 0.0);
  PowerCrustOptions options;
  options.build_crust = false;
  options.build_power_shape = false;
  const auto result = power_crust(points, options);
  EXPECT_TRUE(result.crust.triangles.empty());
  EXPECT_TRUE(result.power_shape.edges.empty());
  EXPECT_GT(result.stats.inner_poles, 0u);
}
