// End-to-end tests of `envcrust reconstruct` on built-in surfaces: open stays open, rho chosen
// or refused with the reason, sparse inputs, the direct Power Crust for comparison.
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


TEST_F(CliTest, reconstruct_keeps_the_open_cylinder_open) {
  const auto j = run_envcrust_json("reconstruct builtin:cylinder -n 5000 -o " + path("c.ply") + " --json");
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 2);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(a["is_orientable"], true);
  EXPECT_LT(a["distance"]["hausdorff_rel_diag"].get<double>(), 0.005);
  EXPECT_GT(j["envelope"]["rho"].get<double>(), 0.0);
  // Built-in samples get no topology cuts by default (the experiments measure the method).
  EXPECT_EQ(j["sheet"]["cut_to_orientable"], false);
  EXPECT_EQ(j["sheet"]["cut_handles_rel_rho"], 0.0);
  EXPECT_FALSE(j.contains("input_is_orientable"));
  // The written file holds the same surface.
  const auto again = run_envcrust("analyze " + path("c.ply") + " --json");
  EXPECT_EQ(nlohmann::json::parse(again.out)["boundary_loops"], 2);
}

TEST_F(CliTest, reconstruct_with_remesh_reports_faces_and_analyzes_the_remeshed_mesh) {
  const auto j = run_envcrust_json("reconstruct builtin:cylinder -n 5000 --remesh -o " + path("c.ply") + " --json");
  const auto& m = j["remesh"];
  EXPECT_EQ(m["is_remeshed"], true);
  EXPECT_LT(3 * m["faces_after"].get<std::size_t>(), m["faces_before"].get<std::size_t>());
  EXPECT_GT(m["min_angle_deg_after"].get<double>(), m["min_angle_deg_before"].get<double>());
  const auto& a = j["analysis"];  // of the remeshed mesh, the one written
  EXPECT_EQ(a["faces"], m["faces_after"]);
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 2);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_LT(a["distance"]["hausdorff_rel_diag"].get<double>(), 0.005);
  const auto again = run_envcrust("analyze " + path("c.ply") + " --json");
  EXPECT_EQ(nlohmann::json::parse(again.out)["faces"], m["faces_after"]);
  // A Moebius band is remeshed too (cut along a seam, welded back) and stays one.
  const auto mj = run_envcrust_json("reconstruct builtin:moebius -n 3000 --remesh --remesh-edge 0.1 -o " +
                                    path("m.ply") + " --json");
  EXPECT_EQ(mj["remesh"]["is_remeshed"], true) << mj["warnings"];
  EXPECT_LT(mj["remesh"]["faces_after"].get<std::size_t>(), mj["remesh"]["faces_before"].get<std::size_t>());
  const auto& ma = mj["analysis"];
  EXPECT_EQ(ma["faces"], mj["remesh"]["faces_after"]);
  EXPECT_EQ(ma["euler_characteristic"], 0);
  EXPECT_EQ(ma["boundary_loops"], 1);
  EXPECT_EQ(ma["is_orientable"], false);
  EXPECT_EQ(ma["is_manifold"], true);
}

TEST_F(CliTest, reconstruct_moebius_is_non_orientable_with_one_boundary) {
  const auto j = run_envcrust_json("reconstruct builtin:moebius -n 5000 -o " + path("m.off") + " --json");
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 1);
  EXPECT_EQ(a["is_orientable"], false);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_TRUE(j["hints"].empty()) << "a built-in surface is known: no hint";
}

TEST_F(CliTest, direct_power_crust_closes_the_open_cylinder) {
  const auto r = run_envcrust("reconstruct builtin:cylinder -n 2000 --method powercrust -o " + path("pc.ply") + " --json");
  // Written, but it fails its own checks (its border follows neither rim): exit code 4.
  ASSERT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(r.err, "envcrust: " + path("pc.ply") + " was written, but the result fails its checks: 2 of the input's "
                   "2 boundary curves followed by no border\n");
  const auto a = nlohmann::json::parse(r.out)["analysis"];
  EXPECT_EQ(a["boundary_loops"], 0);
  EXPECT_EQ(a["is_closed"], true);
  // The caps it adds lie far from the open cylinder.
  EXPECT_GT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>() +
                a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.1);
  // The boundary check names both rims it closed.
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["boundary_check"]["missing_curves"], nlohmann::json::array({0, 1}));
  EXPECT_EQ(j["boundary_check"]["is_consistent"], false);
  const std::string closed =
      "input boundary curve 0 (length 6.283) has no border loop of the result within 1% of the diagonal = 0.0346";
  bool warned = false;
  for (const auto& w : j["warnings"]) warned = warned || w.get<std::string>().rfind(closed, 0) == 0;
  EXPECT_TRUE(warned) << j["warnings"];
  // The envelope's rims follow both circles within 2 rho, and no other loop appears.
  const auto e = run_envcrust_json("reconstruct builtin:cylinder -n 2000 -o " + path("e.ply") + " --json");
  EXPECT_EQ(e["boundary_check"]["is_consistent"], true);
  EXPECT_EQ(e["boundary_check"]["curves"], 2);
  EXPECT_LT(e["boundary_check"]["matches"][0]["hausdorff"].get<double>(), 0.01);
}

TEST_F(CliTest, envelope_writes_samples_with_offset_directions) {
  const auto j = run_envcrust_json("envelope builtin:hemisphere -n 3000 --rho 0.1 -o " + path("e.ply") + " --json");
  EXPECT_DOUBLE_EQ(j["envelope"]["rho"].get<double>(), 0.1);
  const auto points = envcrust::io::read_points(path("e.ply"));
  EXPECT_EQ(points.size(), j["envelope"]["samples"].get<std::size_t>());
  ASSERT_TRUE(points.has_normals());
  for (std::size_t i = 0; i < points.size(); i += 17) {
    // Offset directions are unit and the hemisphere's envelope lies at distance 0.1 from it:
    // sheet points at radius 0.9 or 1.1, rim points 0.1 from the rim circle.
    EXPECT_NEAR(std::sqrt(points.normals[i].squared_length()), 1.0, 1e-9);
    const auto& p = points.points[i];
    const double r = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
    const double to_rim = std::hypot(std::hypot(p.x(), p.y()) - 1.0, p.z());
    const double d = p.z() >= 0 ? std::abs(r - 1.0) : to_rim;
    EXPECT_NEAR(d, 0.1, 0.01);
  }
}

// --orientable cuts the Moebius strip open across its one orientation seam: a disc.
TEST_F(CliTest, reconstruct_orientable_cuts_the_moebius_strip_into_a_disc) {
  const auto j = run_envcrust_json("reconstruct builtin:moebius -n 5000 --orientable -o " + path("m.off") + " --json");
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 1);
  EXPECT_EQ(a["boundary_loops"], 1);
  EXPECT_EQ(a["is_orientable"], true);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(j["sheet"]["orientation_seams"], 1);
  const auto removed = j["sheet"]["faces_removed_at_seams"].get<std::size_t>();
  EXPECT_GT(removed, 0u);
  EXPECT_EQ(j["warnings"][0], "the sheet was non-orientable: " + std::to_string(removed) +
                                  " faces removed around 1 orientation seam");

  const auto bad = run_envcrust("reconstruct builtin:moebius --orientable --orientable-cut 0 -o " + path("x.ply"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--orientable-cut"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(path("x.ply")));
  const auto bad_handles = run_envcrust("reconstruct builtin:moebius --cut-handles -1 -o " + path("x.ply"));
  EXPECT_EQ(bad_handles.exit_code, 2);
  EXPECT_NE(bad_handles.err.find("--cut-handles"), std::string::npos) << bad_handles.err;
  EXPECT_FALSE(fs::exists(path("x.ply")));
  const auto direct = run_envcrust("reconstruct builtin:moebius --method powercrust --orientable -o " + path("x.ply"));
  EXPECT_EQ(direct.exit_code, 2);
  EXPECT_EQ(direct.err, "envcrust: usage error: --orientable and --cut-handles apply to the medial sheet "
                        "(--method envelope --extract sheet)\n");
  EXPECT_FALSE(fs::exists(path("x.ply")));
}

TEST_F(CliTest, reconstruct_refuses_a_bad_rho) {
  const auto r = run_envcrust("reconstruct builtin:cylinder --rho -2 -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "envcrust: usage error: --rho must be 'auto' or a positive number (got '-2')\n");
  EXPECT_FALSE(fs::exists(path("x.ply")));
  const auto q = run_envcrust("reconstruct builtin:cylinder --rho-gap-quantile 2 -o " + path("x.ply"));
  EXPECT_EQ(q.exit_code, 2);
  EXPECT_NE(q.err.find("--rho-gap-quantile"), std::string::npos) << q.err;
  EXPECT_FALSE(fs::exists(path("x.ply")));
}

// A rho far beyond the surface's size wraps it in one blob (no sheets, an empty result), and
// one far below the sampling would make more rim candidates than memory holds: both say why
// and which rho to use instead, without writing the output. (--force: past the refusal before
// the run, cli_data_safety_test.cpp, to the envelope's own.)
TEST_F(CliTest, reconstruct_with_an_absurd_rho_says_why_and_what_to_use) {
  auto expect_refused = [&](const std::string& rho, const std::string& starts, const std::string& names) {
    const auto r = run_envcrust("reconstruct builtin:cylinder -n 2000 --force --rho " + rho + " -o " + path("x.ply"));
    EXPECT_EQ(r.exit_code, 1) << rho;
    EXPECT_EQ(r.err.rfind("envcrust: error: " + starts, 0), 0u) << r.err;
    EXPECT_NE(r.err.find(names), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("x.ply"))) << rho;
  };
  expect_refused("1e6",
                 "builtin:cylinder: the reconstruction is empty: rho 1e+06 is more than a quarter of the input's "
                 "size (diagonal 3.46",
                 "use a rho below 0.346");
  expect_refused("1e-6",
                 "builtin:cylinder: rho 1e-06 at a sample spacing of 0.25 rho is too small for the boundary curves: "
                 "their half-tubes would take ",
                 "(at most 1e+07); rho >= ");
}

// 300 samples of the cylinder are too sparse for half its reach: the automatic rho bridges
// their gaps instead (reported), and the open cylinder still comes out as an annulus.
TEST_F(CliTest, reconstruct_sparse_input_gets_a_rho_that_bridges_its_gaps) {
  const auto j = run_envcrust_json("reconstruct builtin:cylinder -n 300 -o " + path("c.ply") + " --json");
  EXPECT_EQ(j["envelope"]["rho_from"], "gaps");
  EXPECT_GT(j["envelope"]["rho"].get<double>(), 0.18);
  EXPECT_EQ(j["warnings"][0].get<std::string>().rfind("rho raised from 0.17", 0), 0u) << j["warnings"][0];
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
  const auto off = run_envcrust("reconstruct builtin:cylinder -n 300 --rho-gap-quantile 0 -o " + path("c.ply") + " --json");
  ASSERT_EQ(off.exit_code, 0) << off.err;
  EXPECT_EQ(nlohmann::json::parse(off.out)["envelope"]["rho_from"], "reach");
}

// issue 5, too few points: 40 points on the square need a rho of 15% of its diagonal to bridge
// their gaps, and come out closed; the report says the input is too sparse for its size and
// names a count that would do. 80 points of the cylinder give nothing, and the error says why.
TEST_F(CliTest, reconstruct_of_an_input_too_sparse_for_its_size_says_so) {
  ASSERT_EQ(run_envcrust("sample square -n 40 --seed 1 -o " + path("square.xyz")).exit_code, 0);
  // The result is written but passes through itself, so the run exits with 4.
  const auto sparse = run_envcrust("reconstruct " + path("square.xyz") + " -o " + path("s.ply") + " --json");
  EXPECT_EQ(sparse.exit_code, 4) << sparse.err;
  EXPECT_NE(sparse.err.find("fails its checks: passes through itself"), std::string::npos) << sparse.err;
  const auto j = nlohmann::json::parse(sparse.out);
  EXPECT_TRUE(j["envelope"]["input_too_sparse"].get<bool>());
  bool warned = false;
  for (const auto& w : j["warnings"])
    warned = warned || w.get<std::string>().rfind("the input is too sparse for its size: rho 0.4", 0) == 0;
  EXPECT_TRUE(warned) << j["warnings"];
  ASSERT_EQ(run_envcrust("sample cylinder -n 80 --seed 1 -o " + path("cylinder.xyz")).exit_code, 0);
  const auto r = run_envcrust("reconstruct " + path("cylinder.xyz") + " -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("envcrust: error: " + path("cylinder.xyz") +
                       ": the reconstruction is empty: the input is too sparse or noisy for its size (rho "),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("% of its diagonal); sample it denser\n"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("x.ply")));
}

// 300 samples of the torus are too sparse for any envelope (the sheet falls apart: no
// faces), but not for the direct Power Crust: with no boundary curve to keep, reconstruct
// runs it too and keeps its torus, and says so. --no-power-crust-fallback keeps the
// envelope's run, and the empty result is an error.
TEST_F(CliTest, reconstruct_of_a_sparse_closed_sample_keeps_the_direct_power_crust) {
  const auto j = run_envcrust_json("reconstruct builtin:torus -n 300 -o " + path("t.ply") + " --json");
  ASSERT_TRUE(j.contains("power_crust_fallback")) << j;
  const auto& f = j["power_crust_fallback"];
  EXPECT_EQ(f["kept"], "power_crust");
  EXPECT_EQ(f["envelope"]["empty"], true);
  EXPECT_EQ(f["power_crust"]["genus"], 1);
  EXPECT_EQ(f["sample_groups"], 1);
  EXPECT_EQ(j["analysis"]["components"], 1);
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 0);
  EXPECT_EQ(j["analysis"]["is_manifold"], true);
  // Against the exact torus: about a sample spacing (0.23, 5.7% of the diagonal) at most.
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.057);
  EXPECT_TRUE(j["hints"].empty()) << j["hints"];

  const auto text = run_envcrust("reconstruct builtin:torus -n 300 -o " + path("t2.ply"));
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.out.find("  the input has no boundary curve and the envelope's result has no faces (the samples "
                          "form 1 set within 2 rho); the direct Power Crust's has genus 1 (1 defect), kept "
                          "(--no-power-crust-fallback: keep the envelope's)\n"),
            std::string::npos)
      << text.out;

  const auto r = run_envcrust("reconstruct builtin:torus -n 300 --no-power-crust-fallback -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("envcrust: error: builtin:torus: the reconstruction is empty", 0), 0u) << r.err;
  EXPECT_FALSE(fs::exists(path("x.ply")));
}

// issue 5: rho too small for the sampling leaves holes everywhere; the error says which rho
// or which input spacing would work, and the rho it names does work. (--force: past the
// refusal before the run, to the run's own.)
TEST_F(CliTest, reconstruct_with_rho_below_the_gaps_says_which_rho_works) {
  const auto r = run_envcrust("reconstruct builtin:cylinder -n 2000 --force --rho 0.03 -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(fs::exists(path("x.ply")));
  const std::string prefix =
      "envcrust: error: builtin:cylinder: the reconstruction is empty: rho 0.03 is too small for the "
      "input's gaps (up to ";
  ASSERT_EQ(r.err.rfind(prefix, 0), 0u) << r.err;
  const auto at = r.err.find("use --rho ");
  ASSERT_NE(at, std::string::npos) << r.err;
  const double suggested = std::stod(r.err.substr(at + 10));
  EXPECT_GT(suggested, 0.03);
  const auto j = run_envcrust_json("reconstruct builtin:cylinder -n 2000 --rho " + std::to_string(suggested * 1.01) +
                                   " --json -o " + path("y.ply"));
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
}

TEST_F(CliTest, reconstruct_warns_when_rho_exceeds_the_reach) {
  const auto r = run_envcrust("reconstruct builtin:cylinder -n 3000 --rho 1.5 --no-analysis -o " + path("x.ply") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto warnings = nlohmann::json::parse(r.out)["warnings"];
  ASSERT_FALSE(warnings.empty());
  EXPECT_EQ(warnings[0].get<std::string>().rfind("rho 1.5 may be too large:", 0), 0u);
}

// A small dense patch far from the rest (25 samples on a 5 x 5 grid, 3 radii away from a
// 2,000-sample hemisphere) is too small to be kept as a piece of the sheet: the result then
// leaves input samples out, and the report says so.
TEST_F(CliTest, a_result_that_leaves_a_patch_of_samples_out_says_so) {
  ASSERT_EQ(run_envcrust("sample hemisphere -n 2000 -o " + path("h.xyz") + " --quiet").exit_code, 0);
  {
    std::ofstream out(path("h.xyz"), std::ios::app);
    for (int i = 0; i < 5; ++i)
      for (int k = 0; k < 5; ++k) out << 3.0 + 0.02 * i << ' ' << 0.02 * k << " 0\n";
  }
  const auto j = run_envcrust_json("reconstruct " + path("h.xyz") + " -o " + path("h.ply") + " --json");
  EXPECT_EQ(j["checks"]["uncovered_patches"], 1);
  EXPECT_EQ(j["analysis"]["components"], 1);
  const std::string said =
      "the result leaves out 1 patch of the input's samples (9 or more samples farther than 2 rho from it)";
  EXPECT_NE(std::find(j["warnings"].begin(), j["warnings"].end(), said), j["warnings"].end()) << j["warnings"];
  // Without the patch the same hemisphere leaves nothing out.
  ASSERT_EQ(run_envcrust("sample hemisphere -n 2000 -o " + path("g.xyz") + " --quiet").exit_code, 0);
  const auto g = run_envcrust_json("reconstruct " + path("g.xyz") + " -o " + path("g.ply") + " --json");
  EXPECT_EQ(g["checks"]["uncovered_patches"], 0);
  EXPECT_EQ(std::count_if(g["warnings"].begin(), g["warnings"].end(),
                          [](const auto& w) { return w.template get<std::string>().find("leaves out") != std::string::npos; }),
            0);
}
