// End-to-end Power Crust on sampled closed surfaces: topology and distance to the truth.
#include "support.h"

#include <gtest/gtest.h>

using namespace envcrust;
using namespace envcrust::powercrust;

TEST(PowerCrust, sphere_sample_gives_closed_manifold_of_euler_two) {
  const auto points = test_support::sample_builtin("sphere", 2000, 0.0);
  const auto result = power_crust(points);
  const auto t = topology::analyze_topology(result.crust);
  EXPECT_TRUE(t.is_closed());
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_LT(test_support::relative_hausdorff(result.crust, "sphere"), 0.01);
}
