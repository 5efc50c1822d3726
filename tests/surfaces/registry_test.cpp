// Built-in names, the factory, expected topologies and the unknown-name error.
#include "envcrust/errors.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {
namespace {

TEST(Registry, lists_the_thirteen_builtins_in_a_stable_order) {
  const std::vector<std::string> expected{
      "cylinder",       "cylinder-nurbs", "paraboloid", "horn",       "cusp",
      "trefoil-ribbon", "unknot-ribbon",  "moebius",    "hemisphere", "square",
      "saddle",         "sphere",         "torus"};
  EXPECT_EQ(builtin_names(), expected);
}

TEST(Registry, every_name_makes_a_surface_of_that_name_with_consistent_metadata) {
  for (const std::string& name : builtin_names()) {
    const auto surface = make_builtin(name);
    EXPECT_EQ(surface->name(), name);
    EXPECT_FALSE(surface->description().empty());
    EXPECT_EQ(surface->description().find('\n'), std::string::npos);
    const ExpectedTopology t = surface->expected_topology();
    EXPECT_EQ(t.boundary_knots.size(), static_cast<std::size_t>(t.boundary_loops)) << name;
    if (t.boundary_loops < 2) {
      EXPECT_EQ(t.abs_linking_number, 0) << name;
    }
    const ParameterDomain d = surface->domain();
    EXPECT_LT(d.u0, d.u1);
    EXPECT_LT(d.v0, d.v1);
    EXPECT_NE(d.v_gluing, Gluing::PeriodicFlipped);
  }
}

TEST(Registry, only_the_moebius_strip_is_non_orientable) {
  for (const std::string& name : builtin_names()) {
    EXPECT_EQ(make_builtin(name)->expected_topology().is_orientable, name != "moebius") << name;
  }
}

TEST(Registry, unknown_name_lists_the_known_ones) {
  try {
    (void)make_builtin("foo");
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown surface 'foo' (known: cylinder, cylinder-nurbs, paraboloid, horn, cusp, "
              "trefoil-ribbon, unknot-ribbon, moebius, hemisphere, square, saddle, sphere, torus)");
  }
}

TEST(Ribbons, ribbon_strands_clear_each_other_by_more_than_the_width) {
  // Crossings of the z-projection: pairs of far-apart parameters with nearly equal (x, y).
  for (const char* name : {"unknot-ribbon", "trefoil-ribbon"}) {
    const auto ribbon = make_builtin(name);
    const double width = ribbon->domain().v1;
    const int n = 1500;
    std::vector<Point3> curve;
    for (int i = 0; i < n; ++i)
      curve.push_back(ribbon->evaluate(2 * std::numbers::pi * i / n, 0).position);
    double smallest_gap = 1e9;
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        const int separation = std::min(j - i, n - (j - i));
        if (separation < n / 20) continue;
        const double dxy = std::hypot(curve[i].x() - curve[j].x(), curve[i].y() - curve[j].y());
        if (dxy < 0.02) {
          smallest_gap = std::min(smallest_gap, std::abs(curve[i].z() - curve[j].z()));
        }
      }
    }
    EXPECT_GT(smallest_gap, width + 0.5) << name;
  }
}

}  // namespace
}  // namespace envcrust::surfaces
