// power_crust as a whole: progress, cancellation, stats that add up.
#include "support.h"

#include "envcrust/errors.h"

#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <vector>

using namespace envcrust;
using namespace envcrust::powercrust;

TEST(PowerCrust, sphere_sample_gives_closed_manifold_of_euler_two) {
  const auto points = test_support::sample_builtin("sphere", 2000, 0.0);
  const auto result = power_crust(points);
  const auto t = test_support::crust_topology(result.crust);
  EXPECT_TRUE(t.is_closed());
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_TRUE(result.warnings.empty());
}

TEST(PowerCrust, progress_reports_every_stage_in_order) {
  const auto points = test_support::sample_builtin("sphere", 2000, 0.0);
  std::vector<std::string> finished;
  Progress progress;
  progress.callback = [&](std::string_view stage, double fraction) {
    if (fraction == 1.0) finished.emplace_back(stage);
  };
  (void)power_crust(points, {}, progress);
  EXPECT_EQ(finished, (std::vector<std::string>{"delaunay", "poles", "power_diagram", "labeling",
                                                "crust", "power_shape"}));
}

TEST(PowerCrust, cancellation_stops_after_the_running_stage) {
  const auto points = test_support::sample_builtin("sphere", 2000, 0.0);
  std::atomic<bool> cancel{false};
  Progress progress;
  progress.cancel = &cancel;
  progress.callback = [&](std::string_view stage, double) {
    if (stage == "poles") cancel = true;
  };
  try {
    (void)power_crust(points, {}, progress);
    FAIL() << "expected cancellation";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "power crust cancelled");
  }
}

TEST(PowerCrust, stats_count_what_the_result_holds) {
  const auto points = test_support::sample_builtin("torus", 3000, 0.001);
  const auto result = power_crust(points);
  const auto& s = result.stats;
  EXPECT_EQ(s.input_points, points.size());
  EXPECT_EQ(s.poles, result.poles.size());
  EXPECT_EQ(s.inner_poles + s.outer_poles + (s.unknown_poles - s.resolved_unknown_poles), s.poles);
  std::size_t hidden = 0;
  for (const auto& p : result.poles) hidden += p.is_hidden;
  EXPECT_EQ(s.hidden_poles, hidden);
  EXPECT_EQ(s.crust_faces, result.crust.triangles.size());
  EXPECT_GT(s.crust_polygons, 0u);
  EXPECT_GT(s.power_diagram_cells, 0u);
}
