// End-to-end tests of `envcrust boundary`: the curves of a point cloud found, written back,
// their knot types.
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


// `envcrust boundary`: the detector alone, measured against the true boundary of a built-in
// surface; its curves written as polylines or as one point file, which reconstruct reads back.
TEST_F(CliTest, boundary_finds_the_cylinder_rims_and_writes_them_back) {
  const auto j = run_envcrust_json("boundary builtin:cylinder --seed 3 -o " + path("rim.polyline") + " --points-out " +
                                   path("band.xyz") + " --json");
  ASSERT_EQ(j["curves"].size(), 2u);
  ASSERT_EQ(j["reference"]["true_loops"].size(), 2u);
  const double gap = j["reference"]["samples_gap"]["max_rel_diag"].get<double>();
  std::set<int> matched;
  for (const auto& t : j["reference"]["true_loops"]) {
    matched.insert(t["nearest_curve"].get<int>());
    // Each rim found within what the samples allow (the largest distance from the true rim
    // to the nearest sample), with room for the curve's smoothing.
    EXPECT_LT(t["hausdorff_rel_diag"].get<double>(), 1.1 * gap);
  }
  EXPECT_EQ(matched, (std::set<int>{0, 1}));
  for (const auto& c : j["curves"]) {
    EXPECT_EQ(c["knot"], "unknot");
    EXPECT_NEAR(c["length"].get<double>(), 2 * M_PI, 0.05 * 2 * M_PI);
    EXPECT_GT(c["width_local_spacings"].get<double>(), 20.0);
  }
  EXPECT_EQ(j["files"], (nlohmann::json{path("rim.0.polyline"), path("rim.1.polyline")}));
  EXPECT_TRUE(fs::exists(path("band.xyz")));
  EXPECT_GT(j["boundary_points"].get<int>(), 300);  // two rims of ~2 pi / 0.035 spacings each

  // The same curves as one point file with conormals: reconstruct --boundary takes it back,
  // and reconstruct --boundary-out writes .polyline files as boundary -o does.
  ASSERT_EQ(run_envcrust("sample cylinder --seed 3 -q -o " + path("c.xyz")).exit_code, 0);
  const auto k = run_envcrust_json("boundary " + path("c.xyz") + " -r builtin:cylinder -o " + path("rims.xyz") + " --json");
  EXPECT_EQ(k["curves"].size(), 2u);
  EXPECT_EQ(k["reference"]["file"], "builtin:cylinder");
  const auto r = run_envcrust_json("reconstruct " + path("c.xyz") + " --boundary " + path("rims.xyz") + " -o " +
                                   path("c.ply") + " --boundary-out " + path("used.polyline") + " --json");
  EXPECT_EQ(r["input_boundary_curves"], 2);
  EXPECT_EQ(r["analysis"]["boundary_loops"], 2);
  EXPECT_TRUE(fs::exists(path("used.0.polyline")) && fs::exists(path("used.1.polyline")));

  // Text report: one line per curve and per true loop.
  const auto text = run_envcrust("boundary builtin:cylinder --seed 3");
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("builtin:cylinder: 10000 points, 2 boundary curves"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("  true loop 1: nearest curve "), std::string::npos) << text.out;

  // Bad input: a missing file named, an output with an unknown extension refused before the run.
  const auto missing = run_envcrust("boundary " + path("none.xyz"));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err.rfind("envcrust: error: " + path("none.xyz") + ":", 0), 0u) << missing.err;
  const auto bad_out = run_envcrust("boundary " + path("c.xyz") + " -o " + path("x.off"));
  EXPECT_EQ(bad_out.exit_code, 1);
  EXPECT_NE(bad_out.err.find("unknown extension '.off'"), std::string::npos) << bad_out.err;
  EXPECT_FALSE(fs::exists(path("x.off")));
}

// A border that passes through itself has no knot type (no projection of it is generic): a
// quad split into two triangles whose corners are placed as a bowtie, so that two border
// edges cross at (0.5, 0.5, 0). The report says "unknown" with a note; the command used to
// stop with the knot code's error, naming no file.
TEST_F(CliTest, boundary_no_knots_leaves_the_knot_types_out) {
  const auto j = run_envcrust_json("boundary builtin:cylinder --seed 3 --no-knots --json");
  ASSERT_EQ(j["curves"].size(), 2u);
  for (const auto& c : j["curves"]) {
    EXPECT_FALSE(c.contains("knot")) << c;
    EXPECT_NEAR(c["length"].get<double>(), 2 * M_PI, 0.05 * 2 * M_PI);
  }
}

TEST_F(CliTest, boundary_of_a_border_through_itself_has_an_unknown_knot_type) {
  {
    std::ofstream out(path("bowtie.off"));
    out << "OFF\n4 2 0\n0 0 0\n1 1 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  }
  const auto j = run_envcrust_json("boundary " + path("bowtie.off") + " --json");
  ASSERT_EQ(j["curves"].size(), 1u);
  EXPECT_EQ(j["curves"][0]["knot"], "unknown");
  const std::string note =
      "curve 0: no knot type: no generic projection found in 200 random directions (are the curves self-intersecting?)";
  EXPECT_NE(std::find(j["notes"].begin(), j["notes"].end(), note), j["notes"].end()) << j["notes"];
  const auto text = run_envcrust("boundary " + path("bowtie.off"));
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("curve 0: 4 vertices, length 4.828 (341% of the diagonal), unknown"), std::string::npos)
      << text.out;
}

// --boundary-take-in bulges the curve out past samples the outer fit leaves beyond it (the
// unit test DetectBoundary.CurvePassesOutsideEverySample builds such a bay): on the square's
// point file at seed 3 (a void at its left edge with two samples across its mouth) the curve
// grows outward, 8.001 -> 8.069 long. Until the ordering took only links with agreeing
// conormals (2026-12-04) it also came closer to the true rim there, 2.48% -> 2.01% of the
// diagonal; now the plain curve is at 1.88% and the bulged one 1.92%, both within what the
// samples allow (they leave the rim up to 1.69% from them).
TEST_F(CliTest, boundary_take_in_brings_the_curve_out_to_the_samples_beyond_it) {
  const auto plain = run_envcrust_json("boundary builtin:square --seed 3 --json");
  const auto taken = run_envcrust_json("boundary builtin:square --seed 3 --boundary-take-in --json");
  ASSERT_EQ(plain["curves"].size(), 1u);
  ASSERT_EQ(taken["curves"].size(), 1u);
  EXPECT_GT(taken["curves"][0]["length"].get<double>(), plain["curves"][0]["length"].get<double>() + 0.03);
  const double before = plain["reference"]["true_loops"][0]["hausdorff_rel_diag"].get<double>();
  const double after = taken["reference"]["true_loops"][0]["hausdorff_rel_diag"].get<double>();
  const double gap = taken["reference"]["samples_gap"]["max_rel_diag"].get<double>();
  EXPECT_LT(before, 1.25 * gap);
  EXPECT_LT(after, 1.25 * gap);
}
