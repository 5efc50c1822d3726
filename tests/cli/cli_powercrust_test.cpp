// End-to-end tests of `envcrust powercrust`: closed results, noisy poles, refusals.
#include "cli_fixture.h"
#include "envcrust/io.h"
#include "fixtures/shapes.h"
#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using envcrust::testing::CliTest;
using envcrust::testing::run_envcrust;
using envcrust::testing::run_envcrust_json;
namespace fs = std::filesystem;


TEST_F(CliTest, powercrust_of_a_torus_sample_is_a_closed_torus) {
  const auto j = run_envcrust_json("powercrust builtin:torus -n 4000 -o " + path("t.ply") + " --medial-axis " +
                                   path("ma.ply") + " --poles " + path("poles.txt") + " --json");
  EXPECT_EQ(j["crust"]["euler_characteristic"], 0);
  EXPECT_EQ(j["crust"]["is_closed"], true);
  EXPECT_EQ(j["crust"]["is_manifold"], true);
  EXPECT_GT(j["inner_poles"].get<int>(), 0);
  // The medial axis: the In poles, all inside the tube (core circle radius 1, tube 0.4),
  // joined by the power shape's triangles.
  const auto axis = envcrust::io::read_polygon_mesh(path("ma.ply"));
  EXPECT_EQ(axis.vertices.size(), j["inner_poles"].get<std::size_t>());
  EXPECT_GT(axis.faces.size(), 0u);
  for (const auto& v : axis.vertices) EXPECT_LT(std::hypot(std::hypot(v.x(), v.y()) - 1.0, v.z()), 0.4);
  // One line per pole after the header.
  const auto poles = envcrust::testing::slurp(path("poles.txt"));
  EXPECT_EQ(static_cast<std::size_t>(std::count(poles.begin(), poles.end(), '\n')), j["poles"].get<std::size_t>() + 1);
}

TEST_F(CliTest, powercrust_leaves_out_small_poles_of_a_noisy_sample) {
  ASSERT_EQ(run_envcrust("sample sphere -n 20000 --noise 0.001 --seed 2 -q -o " + path("s.xyz")).exit_code, 0);
  const auto j = run_envcrust_json("powercrust " + path("s.xyz") + " --min-pole-radius 3 -o " + path("s.ply") + " --json");
  EXPECT_GT(j["filtered_poles"].get<std::size_t>(), j["poles"].get<std::size_t>() / 10);
  EXPECT_EQ(j["crust"]["euler_characteristic"], 2);
  EXPECT_EQ(j["crust"]["is_closed"], true);
  const auto r = run_envcrust("powercrust " + path("s.xyz") + " --min-pole-radius -1 -o " + path("x.ply"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err, "envcrust: usage error: --min-pole-radius: must be a number in [0, 100] (got '-1')\n");
  EXPECT_FALSE(fs::exists(path("x.ply")));
}

// Five points make a Delaunay triangulation but no crust: an error, not an empty mesh.
TEST_F(CliTest, powercrust_of_too_few_points_is_an_error_and_writes_nothing) {
  {
    std::ofstream out(path("five.xyz"));
    out << "0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.3 0.3 0.3\n";
  }
  const auto r = run_envcrust("powercrust " + path("five.xyz") + " -o " + path("c.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: " + path("five.xyz") + ": the Power Crust has no face (5 points, ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("): the samples are too few or too sparse for a closed surface; nothing written\n"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("c.ply")));
}

TEST_F(CliTest, powercrust_sampling_estimate_reports_bad_second_poles) {
  ASSERT_EQ(run_envcrust("sample sphere -n 10000 --noise 0.001 --seed 1 -q -o " + path("s.xyz")).exit_code, 0);
  const auto j = run_envcrust_json("powercrust " + path("s.xyz") + " --sampling-estimate 0.6 -o " + path("s.ply") +
                                   " --json");
  EXPECT_GT(j["bad_second_poles"].get<std::size_t>(), 0u);  // measured 51
  EXPECT_GT(j["bad_poles_left_out"].get<std::size_t>(), 0u);
  EXPECT_EQ(j["crust"]["euler_characteristic"], 2);
  const auto text = run_envcrust("powercrust " + path("s.xyz") + " --sampling-estimate 0.6 --drop-bad-pole-pairs -o " +
                                 path("t.ply"));
  EXPECT_NE(text.out.find("second poles nearer than the --sampling-estimate bound"), std::string::npos) << text.out;
  const auto zero = run_envcrust("powercrust " + path("s.xyz") + " --sampling-estimate 1.5 -o " + path("x.ply"));
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_FALSE(fs::exists(path("x.ply")));
}

TEST_F(CliTest, powercrust_refuses_coplanar_points) {
  {
    std::ofstream f(path("flat.xyz"));
    for (int i = 0; i < 10; ++i) f << i << " " << (i * i) % 7 << " 0\n";
  }
  const auto r = run_envcrust("powercrust " + path("flat.xyz") + " -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("flat.xyz") + ": all 10 points are coplanar: nothing to reconstruct\n");
  EXPECT_FALSE(fs::exists(path("x.ply")));
}
