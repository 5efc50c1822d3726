// End-to-end tests of the envcrust binary: help, usage, sample, analyze and progress.
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


TEST_F(CliTest, every_subcommand_has_help) {
  for (const std::string sub : {"sample", "analyze", "reconstruct", "boundary", "envelope", "powercrust", "render"}) {
    const auto r = run_envcrust(sub + " --help");
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.out.find("--json"), std::string::npos) << sub;
  }
  EXPECT_EQ(run_envcrust("--help").exit_code, 0);
}

TEST_F(CliTest, missing_subcommand_is_a_usage_error) {
  const auto r = run_envcrust("");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("envcrust: usage error:"), std::string::npos) << r.err;
}

TEST_F(CliTest, sample_list_names_every_surface_with_its_topology) {
  const auto j = run_envcrust_json("sample --list --json");
  ASSERT_EQ(j.size(), 13u);
  bool saw_moebius = false;
  for (const auto& s : j) {
    if (s["name"] == "moebius") {
      saw_moebius = true;
      EXPECT_EQ(s["expected"]["orientable"], false);
      EXPECT_EQ(s["expected"]["boundary_loops"], 1);
    }
  }
  EXPECT_TRUE(saw_moebius);
}

// Counts and sizes are checked as typed: a negative count read into an unsigned option used
// to wrap around to a huge one (std::bad_alloc, exit 3).
TEST_F(CliTest, counts_and_sizes_are_checked_with_a_plain_message) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"sample torus -n -5 -o " + path("t.xyz"), "--count: must be a whole number in 1..100000000 (got '-5')"},
      {"sample torus -n 2.5 -o " + path("t.xyz"), "--count: must be a whole number in 1..100000000 (got '2.5')"},
      {"reconstruct builtin:torus -n -5 -o " + path("t.ply"), "--count: must be a whole number in 1..100000000 (got '-5')"},
      {"analyze builtin:torus --samples -5", "--samples: must be a whole number in 0..100000000 (got '-5')"},
      {"reconstruct builtin:cylinder --cut-handles -2 -o " + path("t.ply"),
       "--cut-handles: must be a number >= 0 (got '-2')"},
      {"reconstruct builtin:cylinder --orientable-cut 0 -o " + path("t.ply"),
       "--orientable-cut: must be a number > 0 (got '0')"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_envcrust(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, "envcrust: usage error: " + message + "\n") << args;
  }
  EXPECT_FALSE(fs::exists(path("t.xyz")));
  EXPECT_FALSE(fs::exists(path("t.ply")));
}

TEST_F(CliTest, sample_writes_the_requested_number_of_points_deterministically) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 500 --seed 7 --normals -q -o " + path("a.xyz")).exit_code, 0);
  ASSERT_EQ(run_envcrust("sample cylinder -n 500 --seed 7 --normals -q -o " + path("b.xyz")).exit_code, 0);
  const auto a = envcrust::io::read_points(path("a.xyz"));
  const auto b = envcrust::io::read_points(path("b.xyz"));
  ASSERT_EQ(a.size(), 500u);
  ASSERT_TRUE(a.has_normals());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.points[i], b.points[i]);
    const double r = std::hypot(a.points[i].x(), a.points[i].y());
    EXPECT_NEAR(r, 1.0, 1e-12);
  }
}

TEST_F(CliTest, unknown_surface_is_refused_with_the_known_names) {
  const auto r = run_envcrust("sample nosuch -n 5 -o " + path("x.xyz"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: unknown surface 'nosuch' (known: cylinder,", 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(path("x.xyz")));
}

TEST_F(CliTest, analyze_reports_a_moebius_tessellation_as_non_orientable) {
  ASSERT_EQ(run_envcrust("sample moebius --mesh -q -o " + path("m.ply")).exit_code, 0);
  const auto j = run_envcrust_json("analyze " + path("m.ply") + " --json");
  EXPECT_EQ(j["euler_characteristic"], 0);
  EXPECT_EQ(j["boundary_loops"], 1);
  EXPECT_EQ(j["is_orientable"], false);
  EXPECT_EQ(j["is_manifold"], true);
  EXPECT_EQ(j["loops"][0]["knot"]["type"], "unknot");
}

TEST_F(CliTest, analyze_against_a_builtin_reference_measures_distances_and_boundaries) {
  ASSERT_EQ(run_envcrust("sample trefoil-ribbon --mesh -q -o " + path("t.off")).exit_code, 0);
  const auto j = run_envcrust_json("analyze " + path("t.off") +
                                   " --reference builtin:trefoil-ribbon --samples 20000 --json --report " +
                                   path("rep.json"));
  EXPECT_EQ(j, nlohmann::json::parse(envcrust::testing::slurp(path("rep.json"))));
  EXPECT_EQ(j["loops"][0]["knot"]["type"], "trefoil");
  EXPECT_EQ(j["loops"][1]["knot"]["type"], "trefoil");
  EXPECT_EQ(std::abs(j["linking"][0]["linking_number"].get<int>()), 3);
  EXPECT_LT(j["distance"]["hausdorff_rel_diag"].get<double>(), 1e-6);
  ASSERT_EQ(j["boundary_matches"].size(), 2u);
  for (const auto& m : j["boundary_matches"]) EXPECT_LT(m["hausdorff_rel_diag"].get<double>(), 1e-3);
}

// A reference mesh's border loops are the true boundary: the coarse cylinder's two rims
// match the exact tessellation's within the facets' sagitta; a closed reference has none.
TEST_F(CliTest, analyze_against_a_mesh_reference_matches_its_border_loops) {
  ASSERT_EQ(run_envcrust("sample cylinder --mesh -q -o " + path("c.off")).exit_code, 0);
  ASSERT_EQ(run_envcrust("reconstruct builtin:cylinder -n 2000 -q -o " + path("r.ply")).exit_code, 0);
  const auto j = run_envcrust_json("analyze " + path("r.ply") + " --reference " + path("c.off") + " --json");
  ASSERT_EQ(j["boundary_matches"].size(), 2u);
  EXPECT_NE(j["boundary_matches"][0]["mesh_loop"], j["boundary_matches"][1]["mesh_loop"]);
  for (const auto& m : j["boundary_matches"]) EXPECT_LT(m["hausdorff_rel_diag"].get<double>(), 0.005) << m;
  ASSERT_EQ(run_envcrust("sample sphere --mesh -q -o " + path("s.off")).exit_code, 0);
  const auto closed = run_envcrust_json("analyze " + path("r.ply") + " --reference " + path("s.off") + " --json");
  EXPECT_FALSE(closed.contains("boundary_matches"));
}

TEST_F(CliTest, analyze_a_point_reference) {
  ASSERT_EQ(run_envcrust("sample sphere --mesh -q -o " + path("s.obj")).exit_code, 0);
  ASSERT_EQ(run_envcrust("sample sphere -n 2000 -q -o " + path("s.xyz")).exit_code, 0);
  const auto j = run_envcrust_json("analyze " + path("s.obj") + " -r " + path("s.xyz") + " --samples 5000 --json");
  EXPECT_EQ(j["euler_characteristic"], 2);
  EXPECT_LT(j["distance"]["reference_to_mesh"]["max"].get<double>(), 1e-3);
  // Mesh points are up to the sampling gap away from the nearest of 2000 points.
  EXPECT_GT(j["distance"]["mesh_to_reference"]["max"].get<double>(), 0.02);
}

TEST_F(CliTest, analyze_curve_reports_the_knot_type) {
  ASSERT_EQ(run_envcrust("sample trefoil-ribbon -q --boundary-out " + path("loop.polyline")).exit_code, 0);
  const auto r = run_envcrust("analyze --curve " + path("loop.0.polyline") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["knot"]["type"], "trefoil");
  const auto text = run_envcrust("analyze --curve " + path("loop.1.polyline"));
  EXPECT_NE(text.out.find("trefoil (Alexander polynomial t^2 - t + 1"), std::string::npos) << text.out;
}

TEST_F(CliTest, analyze_missing_file_names_it) {
  const auto r = run_envcrust("analyze " + path("none.off"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: " + path("none.off") + ":", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
}

TEST_F(CliTest, analyze_needs_a_mesh_or_a_curve) {
  const auto r = run_envcrust("analyze");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "envcrust: usage error: analyze: a MESH (or --curve CURVE) is required\n");
}

TEST_F(CliTest, garbage_mesh_is_an_error_not_a_crash) {
  {
    std::ofstream f(path("bad.off"));
    f << "OFF\n3 1 0\n0 0 0\n1 0 0\n";
  }
  const auto r = run_envcrust("analyze " + path("bad.off"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: " + path("bad.off"), 0), 0u) << r.err;
}

// On a terminal (util-linux `script` gives the command one) the long stages draw a bar with
// the step under way: the point file's reading, normals and boundary detection, the envelope
// and each step of the sheet; not when stderr is a file, nor with --quiet.
TEST_F(CliTest, progress_names_each_step_on_a_terminal_only) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 3000 -o " + path("c.xyz")).exit_code, 0);
  const std::string command = std::string(ENVCRUST_BINARY) + " reconstruct " + path("c.xyz") + " -o " +
                              path("c.ply") + " --no-analysis";
  auto on_terminal = [&](const std::string& extra) {
    const std::string typescript = path("typescript.txt");
    const std::string shell = "script -qec '" + command + extra + "' /dev/null > " + typescript + " 2>&1";
    if (std::system(shell.c_str()) != 0) return std::string("script failed");
    return envcrust::testing::slurp(typescript);
  };
  if (std::system("command -v script > /dev/null") != 0) GTEST_SKIP() << "no util-linux script";
  const std::string shown = on_terminal("");
  for (const std::string step : {"input: normals", "input: boundary", "envelope", "sheet: Voronoi polygons",
                                 "sheet: cleaning", "sheet: projection", "sheet: handle cut", "medial sheet"})
    EXPECT_NE(shown.find(step), std::string::npos) << step << " in:\n" << shown;
  EXPECT_NE(shown.find("100%"), std::string::npos) << shown;
  EXPECT_EQ(on_terminal(" --quiet").find('%'), std::string::npos);
  const auto piped = run_envcrust("reconstruct " + path("c.xyz") + " -o " + path("c.ply") + " --no-analysis");
  EXPECT_EQ(piped.exit_code, 0);
  EXPECT_EQ(piped.err.find('%'), std::string::npos) << piped.err;
}

// The analyzer says whether a mesh passes through itself: a tessellated sphere is an
// embedded surface, two triangles piercing each other are not (one pair, and a warning).
TEST_F(CliTest, analyze_reports_faces_that_pass_through_each_other) {
  ASSERT_EQ(run_envcrust("sample sphere --mesh -o " + path("s.ply")).exit_code, 0);
  const auto sphere = run_envcrust("analyze " + path("s.ply"));
  EXPECT_NE(sphere.out.find("\n  self-intersections: none (an embedded surface)\n"), std::string::npos) << sphere.out;
  {
    std::ofstream off(path("x.off"));
    off << "OFF\n6 2 0\n0 0 0\n2 0 0\n0 2 0\n0.5 0.5 -1\n0.5 0.5 1\n3 3 0.5\n3 0 1 2\n3 3 4 5\n";
  }
  const auto j = run_envcrust_json("analyze " + path("x.off") + " --json");
  EXPECT_EQ(j["self_intersections"]["face_pairs"], 1);
  EXPECT_EQ(j["self_intersections"]["faces"], 2);
  EXPECT_EQ(j["self_intersections"]["examples"].size(), 1u);
  EXPECT_EQ(j["is_embedded"], false);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0].get<std::string>().rfind("1 pairs of faces pass through each other (2 faces), e.g. near (", 0), 0u);
  const auto skipped = run_envcrust_json("analyze " + path("x.off") + " --no-self-intersections --json");
  EXPECT_FALSE(skipped.contains("self_intersections"));
  EXPECT_FALSE(skipped.contains("is_embedded"));
  EXPECT_TRUE(skipped["warnings"].empty());
  const auto text = run_envcrust("analyze " + path("x.off"));
  EXPECT_NE(text.out.find("\n  self-intersections: 1 pairs of faces pass through each other (2 faces), e.g. near ("),
            std::string::npos)
      << text.out;
}
