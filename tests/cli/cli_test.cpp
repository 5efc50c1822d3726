// End-to-end tests of the envcrust binary: outputs, reports, exit codes and error messages.
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
  EXPECT_GE(j["seconds"]["remesh"].get<double>(), 0.0);
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
  ASSERT_EQ(r.exit_code, 0) << r.err;
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
// and which rho to use instead, without writing the output.
TEST_F(CliTest, reconstruct_with_an_absurd_rho_says_why_and_what_to_use) {
  auto expect_refused = [&](const std::string& rho, const std::string& starts, const std::string& names) {
    const auto r = run_envcrust("reconstruct builtin:cylinder -n 2000 --rho " + rho + " -o " + path("x.ply"));
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
  const auto j = run_envcrust_json("reconstruct " + path("square.xyz") + " -o " + path("s.ply") + " --json");
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
// or which input spacing would work, and the rho it names does work.
TEST_F(CliTest, reconstruct_with_rho_below_the_gaps_says_which_rho_works) {
  const auto r = run_envcrust("reconstruct builtin:cylinder -n 2000 --rho 0.03 -o " + path("x.ply"));
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

TEST_F(CliTest, reconstruct_an_unoriented_point_cloud_of_the_open_cylinder) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 10000 --seed 3 -q -o " + path("c.xyz")).exit_code, 0);
  const auto j = run_envcrust_json("reconstruct " + path("c.xyz") + " -r builtin:cylinder -o " + path("c.ply") +
                                   " --json");
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 2);
  EXPECT_EQ(a["is_manifold"], true);
  // Away from the boundary the sheet follows the samples closely.
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
  // A point file is a scan: the handle cut is on by default and finds nothing to cut here;
  // its orientability is unknown, so only seams that short reversing loops cross would be
  // cut, and there are none.
  EXPECT_EQ(j["sheet"]["cut_handles_rel_rho"], 1.5);
  EXPECT_EQ(j["sheet"]["handle_balls"], 0);
  EXPECT_EQ(j["sheet"]["cut_to_orientable"], true);
  EXPECT_NEAR(j["sheet"]["orientable_max_twist_loop_rel_rho"].get<double>(), 4 * 3.14159265, 1e-6);
  EXPECT_EQ(j["sheet"]["orientation_seams"], 0);
  EXPECT_EQ(j["sheet"]["orientation_twists_kept"], 0);
}

// Strays in a scan (50 specks in the cylinder's bounding box, 0.5% of the points) are removed
// before anything else: every speck farther than 3 spacings from the surface is removed, and
// no sample of it. Kept (--keep-outliers), the specks shrink the estimated reach and with it
// rho (more than twice the envelope samples) and pull the sheet farther from the cylinder.
TEST_F(CliTest, reconstruct_removes_stray_samples_first) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 10000 --seed 3 -q -o " + path("c.xyz")).exit_code, 0);
  auto read = envcrust::io::read_points(path("c.xyz"));
  const std::size_t samples = read.points.size();
  // Radius 1, z in [-1, 1]: the distance of p to the open cylinder.
  auto distance_to_cylinder = [](const envcrust::Point3& p) {
    const double radial = std::hypot(p.x(), p.y()) - 1.0;
    const double beyond = std::max(0.0, std::abs(p.z()) - 1.0);
    return std::hypot(radial, beyond);
  };
  std::uint64_t state = 12345;
  auto next = [&state] {  // a fixed sequence in [-1.2, 1.2]
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return -1.2 + 2.4 * static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  std::size_t far_specks = 0;
  for (int i = 0; i < 50; ++i) {
    read.points.emplace_back(next(), next(), next());
    far_specks += distance_to_cylinder(read.points.back()) > 0.1;  // 3 spacings (0.033)
  }
  envcrust::io::write_points(path("specks.xyz"), read);
  const auto j = run_envcrust_json("reconstruct " + path("specks.xyz") + " -r builtin:cylinder -o " + path("c.ply") +
                                   " --outliers-out " + path("removed.xyz") + " --json");
  const auto removed = envcrust::io::read_points(path("removed.xyz")).points;
  EXPECT_EQ(j["input_outliers_removed"], removed.size());
  EXPECT_EQ(j["input_points"], samples + 50 - removed.size());
  std::size_t removed_far = 0;
  for (const auto& p : removed) {
    EXPECT_GT(distance_to_cylinder(p), 0.02) << "a sample of the cylinder removed";
    removed_far += distance_to_cylinder(p) > 0.1;
  }
  EXPECT_EQ(removed_far, far_specks);
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
  const auto text = run_envcrust("envelope " + path("specks.xyz") + " -o " + path("e.xyz"));
  EXPECT_NE(text.out.find("\n  input: " + std::to_string(removed.size()) +
                          " stray samples removed (--outliers-out writes them, --keep-outliers keeps them)\n"),
            std::string::npos)
      << text.out;
  const auto kept = run_envcrust_json("reconstruct " + path("specks.xyz") + " -r builtin:cylinder -o " +
                                      path("k.ply") + " --keep-outliers --json");
  EXPECT_EQ(kept["input_outliers_removed"], 0);
  EXPECT_LT(kept["envelope"]["rho"].get<double>(), 0.7 * j["envelope"]["rho"].get<double>());
  EXPECT_GT(kept["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(),
            j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>());
  EXPECT_GT(kept["envelope"]["samples"].get<double>(), 2.0 * j["envelope"]["samples"].get<double>());
}

// A point file of a Moebius strip comes out non-orientable, as it should: its orientation
// seam is crossed by no reversing loop shorter than 4 pi rho (they run around the strip, about
// 2 pi / rho = 35 rho long), so --orientable=auto keeps it as a twist and says so. Since a
// point file does not say whether the scanned surface is orientable, the hint names the flag
// that would cut the cross-cap out if it were.
TEST_F(CliTest, reconstruct_a_non_orientable_point_cloud_with_a_hint) {
  ASSERT_EQ(run_envcrust("sample moebius -n 10000 --seed 3 -q -o " + path("m.xyz")).exit_code, 0);
  const auto j = run_envcrust_json("reconstruct " + path("m.xyz") + " -r builtin:moebius -o " + path("m.ply") +
                                   " --json");
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 1);
  EXPECT_EQ(a["is_orientable"], false);
  EXPECT_EQ(j["sheet"]["handle_balls"], 0) << "the strip is a disc at 1.5 rho everywhere";
  EXPECT_EQ(j["sheet"]["orientation_seams"], 0);
  EXPECT_EQ(j["sheet"]["orientation_twists_kept"], 1);
  EXPECT_EQ(j["sheet"]["faces_removed_at_seams"], 0);
  ASSERT_EQ(j["warnings"].size(), 1u) << j["warnings"].dump();
  EXPECT_EQ(j["warnings"][0], "the sheet has 1 orientation-reversing twist that no loop shorter than 12.6 rho "
                              "reverses: kept as part of the surface (a Moebius strip's twist), not cut");
  ASSERT_EQ(j["hints"].size(), 1u);
  EXPECT_EQ(j["hints"][0], "the result is non-orientable (1 cross-cap): if the input scans an orientable surface, "
                           "--orientable removes it and closes the holes");
}

// A point file of a torus keeps its handle (every ball of 1.5 rho is a disc on it); the hint
// says which --cut-handles would also remove wider handles, should the scan have fewer.
TEST_F(CliTest, reconstruct_a_torus_point_cloud_keeps_its_handle_with_a_hint) {
  ASSERT_EQ(run_envcrust("sample torus -n 5000 --seed 2 -q -o " + path("t.xyz")).exit_code, 0);
  const auto j = run_envcrust_json("reconstruct " + path("t.xyz") + " --no-boundary -r builtin:torus -o " +
                                   path("t.ply") + " --json");
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 0);
  EXPECT_EQ(j["sheet"]["handle_balls"], 0);
  EXPECT_LT(j["analysis"]["distance"]["hausdorff_rel_diag"].get<double>(), 0.005);
  ASSERT_EQ(j["hints"].size(), 1u);
  EXPECT_EQ(j["hints"][0], "the result has genus 1 after the cuts at 1.5 rho: if the scanned surface has fewer "
                           "handles, --cut-handles 3 also removes the ones up to twice as wide");
}

// A torus sampled too sparsely for estimated normals (400 points) falls into pieces although
// its samples are one connected set within 2 rho: without the Power Crust fallback the hint
// says so and names the direct Power Crust, which gets the torus; with it (the default) the
// result is that torus. Two spheres apart come out as two pieces, as their samples are: no
// hint.
TEST_F(CliTest, a_result_in_more_pieces_than_its_samples_hints_at_the_direct_power_crust) {
  ASSERT_EQ(run_envcrust("sample torus -n 400 --seed 1 -q -o " + path("t.xyz")).exit_code, 0);
  const auto fallback = run_envcrust_json("reconstruct " + path("t.xyz") + " -o " + path("f.ply") + " --json");
  EXPECT_EQ(fallback["power_crust_fallback"]["kept"], "power_crust");
  EXPECT_GT(fallback["power_crust_fallback"]["envelope"]["extra_pieces"].get<int>(), 0);
  EXPECT_EQ(fallback["analysis"]["components"], 1);
  EXPECT_EQ(fallback["analysis"]["euler_characteristic"], 0);
  EXPECT_TRUE(fallback["hints"].empty()) << fallback["hints"];
  const auto j = run_envcrust_json("reconstruct " + path("t.xyz") + " --no-power-crust-fallback -o " + path("t.ply") +
                                   " --json");
  EXPECT_FALSE(j.contains("power_crust_fallback"));
  const auto pieces = j["analysis"]["components"].get<int>();
  ASSERT_GT(pieces, 1);
  const double rho = j["envelope"]["rho"].get<double>();
  std::ostringstream expected;
  expected << std::setprecision(4) << "the result has " << pieces
           << " pieces where the samples form 1 connected set (neighbours within 2 rho = " << 2 * rho
           << "): the sample may be too sparse for the estimated normals and the envelope (rho " << rho
           << ", estimated reach " << j["envelope"]["reach"]["reach"].get<double>()
           << "); if the surface is closed, --method powercrust, which needs no normals, copes with sparser samples";
  EXPECT_NE(std::find(j["hints"].begin(), j["hints"].end(), expected.str()), j["hints"].end()) << j["hints"];
  const auto direct = run_envcrust_json("reconstruct " + path("t.xyz") + " --method powercrust -o " + path("d.ply") +
                                        " --json");
  EXPECT_EQ(direct["analysis"]["components"], 1);
  EXPECT_EQ(direct["analysis"]["euler_characteristic"], 0);

  ASSERT_EQ(run_envcrust("sample sphere -n 2000 --seed 1 -q -o " + path("s.xyz")).exit_code, 0);
  {
    std::ifstream in(path("s.xyz"));
    std::ofstream out(path("two.xyz"));
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);
    for (const auto& l : lines) out << l << "\n";
    for (const auto& l : lines) {
      std::istringstream fields(l);
      double x = 0, y = 0, z = 0;
      fields >> x >> y >> z;
      out << std::setprecision(17) << x + 5 << " " << y << " " << z << "\n";
    }
  }
  const auto two = run_envcrust_json("reconstruct " + path("two.xyz") + " -o " + path("two.ply") + " --json");
  EXPECT_EQ(two["analysis"]["components"], 2);
  EXPECT_EQ(two["analysis"]["euler_characteristic"], 4);
  EXPECT_EQ(two["hints"], nlohmann::json::array());
}

// An orientable mesh says its surface is orientable: the sheet is cut to an orientable one by
// default (--orientable=auto), and --orientable=no or --cut-handles 0 turn the cuts off.
TEST_F(CliTest, reconstruct_an_orientable_mesh_with_the_scan_cuts_by_default) {
  ASSERT_EQ(run_envcrust("sample cylinder --mesh -q -o " + path("c.off")).exit_code, 0);
  const auto j = run_envcrust_json("reconstruct " + path("c.off") + " -r builtin:cylinder -o " + path("c.ply") +
                                   " --json");
  EXPECT_EQ(j["input_is_orientable"], true);
  // The result has the input's genus (0): no second run with adaptive rho.
  EXPECT_EQ(j["input_genus"], 0);
  EXPECT_FALSE(j.contains("adaptive_retry"));
  EXPECT_EQ(j["sheet"]["cut_to_orientable"], true);
  EXPECT_EQ(j["sheet"]["cut_handles_rel_rho"], 1.5);
  EXPECT_EQ(j["sheet"]["orientation_seams"], 0);
  EXPECT_EQ(j["sheet"]["handle_balls"], 0);
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
  EXPECT_EQ(j["analysis"]["is_orientable"], true);
  EXPECT_LT(j["analysis"]["distance"]["hausdorff_rel_diag"].get<double>(), 0.005);
  const auto k = run_envcrust_json("reconstruct " + path("c.off") +
                                   " --orientable=no --cut-handles 0 --no-analysis -o " +
                                   path("c2.ply") + " --json");
  EXPECT_EQ(k["sheet"]["cut_to_orientable"], false);
  EXPECT_EQ(k["sheet"]["cut_handles_rel_rho"], 0.0);
  const auto bad = run_envcrust("reconstruct " + path("c.off") + " --orientable=maybe -o " + path("x.ply"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--orientable: maybe not in {auto,yes,no}"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(path("x.ply")));
}

// Without --reference a mesh input is measured against its own surface: its 338 vertices alone
// would read the cylinder's long triangles as error (9.6% of the diagonal, not 0.2%).
TEST_F(CliTest, reconstruct_measures_a_mesh_input_against_its_own_surface) {
  ASSERT_EQ(run_envcrust("sample cylinder --mesh -q -o " + path("c.off")).exit_code, 0);
  const auto j = run_envcrust_json("reconstruct " + path("c.off") + " -o " + path("c.ply") + " --json");
  EXPECT_EQ(j["reference"], path("c.off"));
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
  EXPECT_LT(j["analysis"]["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.005);
  ASSERT_EQ(run_envcrust("sample cylinder -n 3000 -q -o " + path("c.xyz")).exit_code, 0);
  const auto k = run_envcrust_json("reconstruct " + path("c.xyz") + " -o " + path("c2.ply") + " --json");
  EXPECT_EQ(k["reference"], "input points");
  EXPECT_EQ(run_envcrust_json("reconstruct builtin:cylinder -n 3000 -o " + path("c3.ply") + " --json")["reference"],
            "builtin:cylinder");
}

TEST_F(CliTest, reconstruct_refuses_zero_self_intersection_rounds) {
  const auto bad = run_envcrust("reconstruct builtin:cylinder --self-intersection-rounds 0 -o " + path("x.ply"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--self-intersection-rounds: Value 0 not in range 1 to 100"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(path("x.ply")));
}

// A square scanned with an unsampled stripe (0.8 x 0.06, about 6 local spacings wide): the
// detector reads the stripe as a second boundary loop, and the hint names the
// --boundary-min-width that drops it; with it the square is one disc.
TEST_F(CliTest, reconstruct_hints_at_an_unsampled_stripe_read_as_a_hole) {
  ASSERT_EQ(run_envcrust("sample square -n 20000 --seed 1 -q -o " + path("sq.xyz")).exit_code, 0);
  const auto points = envcrust::io::read_points(path("sq.xyz"));
  envcrust::PointSet kept;
  for (const auto& p : points.points)
    if (!(std::abs(p.x()) < 0.4 && std::abs(p.y()) < 0.03)) kept.points.push_back(p);
  envcrust::io::write_points(path("stripe.xyz"), kept);
  const auto j = run_envcrust_json("reconstruct " + path("stripe.xyz") + " -o " + path("s.ply") + " --json");
  ASSERT_EQ(j["input_boundary_widths"].size(), 2u);
  const double stripe = j["input_boundary_widths"][1].get<double>();
  EXPECT_GT(stripe, 3.0);
  EXPECT_LT(stripe, 8.0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
  std::ostringstream width;
  width << std::fixed << std::setprecision(1) << stripe;
  std::ostringstream widest;
  widest << std::fixed << std::setprecision(1) << j["input_boundary_widths"][0].get<double>();
  const int k = static_cast<int>(std::floor(stripe)) + 1;
  ASSERT_EQ(j["hints"].size(), 1u) << j["hints"].dump();
  EXPECT_EQ(j["hints"][0], "detected boundary loop 1 is " + width.str() + " local spacings wide (the widest " +
                               widest.str() + "): if it is an unsampled stripe rather than a hole of the surface, "
                               "--boundary-min-width " + std::to_string(k) + " drops it");
  const auto f = run_envcrust_json("reconstruct " + path("stripe.xyz") + " --boundary-min-width " + std::to_string(k) +
                                   " -o " + path("s.ply") + " --json");
  EXPECT_EQ(f["input_boundary_curves"], 1);
  EXPECT_EQ(f["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(f["analysis"]["boundary_loops"], 1);
  EXPECT_TRUE(f["hints"].empty()) << f["hints"].dump();
}

// Issue #5: the boundary of a point cloud can be given instead of detected.
TEST_F(CliTest, reconstruct_with_given_boundary_points) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 10000 --seed 3 -q -o " + path("c.xyz") + " --boundary-out " +
                         path("rim.xyz")).exit_code, 0);
  {  // both rims in one file, every 10th exact vertex (a sparse pick)
    std::ofstream out(path("rims.xyz"));
    for (const char* name : {"rim.0.xyz", "rim.1.xyz"}) {
      std::ifstream in(path(name));
      std::string line;
      for (int i = 0; std::getline(in, line); ++i)
        if (i % 10 == 0) out << line << "\n";
    }
  }
  const auto j = run_envcrust_json("reconstruct " + path("c.xyz") + " --boundary " + path("rims.xyz") +
                                   " -r builtin:cylinder -o " + path("c.ply") + " --json");
  EXPECT_EQ(j["input_boundary_curves"], 2);
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 2);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);

  // The same loops as closed curves, one .polyline file each (as `sample --boundary-out`
  // writes them), the option repeated.
  ASSERT_EQ(run_envcrust("sample cylinder -q --boundary-out " + path("rim.polyline")).exit_code, 0);
  const auto jc = run_envcrust_json("reconstruct " + path("c.xyz") + " --boundary " + path("rim.0.polyline") +
                                    " --boundary " + path("rim.1.polyline") + " -o " + path("c2.ply") + " --json");
  EXPECT_EQ(jc["input_boundary_curves"], 2);
  EXPECT_EQ(jc["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(jc["analysis"]["boundary_loops"], 2);

  // Refused: a point off the surface (named with its file), builtin input, --no-boundary.
  {
    std::ofstream out(path("far.xyz"));
    out << "1 0 0\n0 0 9\n";
  }
  const auto far = run_envcrust("reconstruct " + path("c.xyz") + " --boundary " + path("far.xyz") + " -o " + path("x.ply"));
  EXPECT_EQ(far.exit_code, 1);
  EXPECT_EQ(far.err.rfind("envcrust: error: " + path("far.xyz") + ": boundary point 1 at (0, 0, 9) is ", 0), 0u) << far.err;
  EXPECT_FALSE(fs::exists(path("x.ply")));
  const auto builtin = run_envcrust("reconstruct builtin:cylinder --boundary " + path("rims.xyz") + " -o " + path("x.ply"));
  EXPECT_EQ(builtin.exit_code, 2);
  EXPECT_EQ(builtin.err, "envcrust: usage error: --boundary applies to point files: builtin:cylinder brings its exact boundary\n");
  const auto both = run_envcrust("reconstruct " + path("c.xyz") + " --no-boundary --boundary " + path("rims.xyz") +
                                 " -o " + path("x.ply"));
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(both.err, "envcrust: usage error: --no-boundary excludes --boundary\n");
}

// A given boundary loop shorter than 2 pi rho (here a circle of radius 0.15 on the mantle,
// where the samples go on: no hole) is closed by any envelope: the report says it is below
// the reconstruction's resolution instead of counting it as a curve the result missed.
TEST_F(CliTest, reconstruct_names_a_boundary_curve_below_its_resolution) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 4000 -q -o " + path("c.xyz") + " --boundary-out " +
                         path("rim.polyline")).exit_code, 0);
  {
    std::ofstream out(path("small.polyline"));
    out.precision(17);
    for (int k = 0; k < 32; ++k) {
      const double a = 2 * 3.141592653589793 * k / 32, y = 0.15 * std::cos(a);
      out << std::sqrt(1 - y * y) << " " << y << " " << 0.15 * std::sin(a) << "\n";
    }
  }
  const auto j = run_envcrust_json("reconstruct " + path("c.xyz") + " --boundary " + path("small.polyline") +
                                   " --boundary " + path("rim.0.polyline") + " --boundary " + path("rim.1.polyline") +
                                   " -o " + path("c.ply") + " --json");
  EXPECT_EQ(j["input_boundary_curves"], 3);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
  const auto& check = j["boundary_check"];
  const double rho = j["envelope"]["rho"].get<double>();
  EXPECT_NEAR(check["min_resolvable_length"].get<double>(), 2 * 3.141592653589793 * rho, 1e-9);
  ASSERT_EQ(check["unresolved_curves"].size(), 1u);
  EXPECT_TRUE(check["missing_curves"].empty());
  EXPECT_EQ(check["is_consistent"], true);
  const auto curve = check["unresolved_curves"][0].get<int>();
  const double length = check["matches"][curve]["curve_length"].get<double>();
  EXPECT_LT(length, 2 * 3.141592653589793 * 0.15);
  std::ostringstream expected;
  expected.precision(4);
  expected << "input boundary curve " << curve << " (length " << length << ") is closed in the result: shorter than "
           << check["min_resolvable_length"].get<double>()
           << ", it is below the resolution of the reconstruction (the envelope bridges every hole shorter than 2 pi rho)";
  EXPECT_NE(std::find(j["warnings"].begin(), j["warnings"].end(), expected.str()), j["warnings"].end()) << j["warnings"];

  // Detected: a hole of radius 0.12 punched in 10,000 samples reads as a loop 4.6 local
  // spacings wide beside the rims' 32.4, which the stripe hint's widths alone would name
  // (--boundary-min-width), but the envelope closes it anyway: no hint.
  ASSERT_EQ(run_envcrust("sample cylinder -n 10000 -q -o " + path("c10k.xyz")).exit_code, 0);
  auto holed = envcrust::io::read_points(path("c10k.xyz"));
  std::erase_if(holed.points, [](const envcrust::Point3& p) {
    return CGAL::squared_distance(p, envcrust::Point3(1, 0, 0)) < 0.12 * 0.12;
  });
  envcrust::io::write_points(path("holed.xyz"), holed);
  const auto d = run_envcrust_json("reconstruct " + path("holed.xyz") + " -o " + path("h.ply") + " --json");
  EXPECT_EQ(d["input_boundary_curves"], 3);
  EXPECT_EQ(d["analysis"]["boundary_loops"], 2);
  EXPECT_EQ(d["boundary_check"]["unresolved_curves"].size(), 1u);
  EXPECT_EQ(d["boundary_check"]["is_consistent"], true);
  EXPECT_TRUE(d["hints"].empty()) << d["hints"];
}

TEST_F(CliTest, reconstruct_too_few_points_names_the_file) {
  {
    std::ofstream out(path("few.xyz"));
    for (int i = 0; i < 20; ++i) out << std::cos(0.3 * i) << " " << std::sin(0.3 * i) << " " << 0.05 * i << "\n";
  }
  expect_reconstruct_refuses("few.xyz",
                             "boundary detection needs at least 33 points, each with its 32 nearest neighbours (got 20)");
}

// Points on a line, or one point repeated, are no surface: refused with the file's name
// before any stage runs.
TEST_F(CliTest, reconstruct_refuses_points_on_a_line_and_repeated_points) {
  {
    std::ofstream out(path("line.xyz"));
    for (int i = 0; i < 100; ++i) out << i / 7.0 << " " << 2 * i / 7.0 << " " << -i / 7.0 << "\n";  // 6 digits
  }
  expect_reconstruct_refuses("line.xyz",
                             "all 100 points lie on a line (within 1e-5 of their extent, 34.6): no surface to reconstruct");
  {
    std::ofstream out(path("same.xyz"));
    for (int i = 0; i < 50; ++i) out << (i % 2 ? "1 2 3\n" : "1 2 4\n");
  }
  expect_reconstruct_refuses("same.xyz", "need at least 5 distinct points, got 2 (48 duplicates merged)");
}

// Every output is checked before the run: a report in a missing folder used to fail after
// the whole reconstruction, with the mesh already written.
TEST_F(CliTest, reconstruct_checks_every_output_before_it_runs) {
  const auto r = run_envcrust("reconstruct builtin:cylinder -o " + path("x.ply") + " --report " +
                              path("missing/r.json"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("missing/r.json") + ": folder '" + path("missing") +
                       "' does not exist\n");
  EXPECT_FALSE(fs::exists(path("x.ply")));
  const auto e = run_envcrust("reconstruct builtin:cylinder -o " + path("x.ply") + " --envelope-out " + path("e.off"));
  EXPECT_EQ(e.exit_code, 1);
  EXPECT_EQ(e.err, "envcrust: error: " + path("e.off") + ": unknown extension '.off' (expected .xyz, .ply)\n");
  EXPECT_FALSE(fs::exists(path("x.ply")));
}

// x y z r g b: the last three columns, whole numbers in 0..255, are colours; read as normals
// they would all point into one octant. They are dropped and the normals estimated, with a
// note; the open cylinder comes out with its two rims. Normals that are whole numbers but
// none above 1 stay normals.
TEST_F(CliTest, six_columns_of_colours_are_not_read_as_normals) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 4000 -q -o " + path("c.xyz")).exit_code, 0);
  {
    std::ifstream in(path("c.xyz"));
    std::ofstream out(path("rgb.xyz"));
    std::string line;
    for (int i = 0; std::getline(in, line); ++i) out << line << " " << (i * 7) % 256 << " 128 0\n";
  }
  const auto j = run_envcrust_json("reconstruct " + path("rgb.xyz") + " -o " + path("c.ply") + " --json");
  const std::string note = "columns 4-6 are whole numbers in 0..255 on every line: read as colours, not normals";
  EXPECT_NE(std::find(j["notes"].begin(), j["notes"].end(), note), j["notes"].end()) << j["notes"];
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
  {
    std::ofstream out(path("unit.xyz"));
    for (int i = 0; i < 40; ++i) out << std::cos(0.3 * i) << " " << std::sin(0.3 * i) << " " << 0.05 * i << " 0 0 1\n";
  }
  const auto unit = run_envcrust_json("boundary " + path("unit.xyz") + " --json");
  EXPECT_EQ(std::find(unit["notes"].begin(), unit["notes"].end(), note), unit["notes"].end()) << unit["notes"];
}

// Exports with more columns read by their header's names (CloudCompare's "//X,Y,Z,..." CSV)
// or, in Leica's .pts, as point counts and x y z intensity r g b: the same points, the same
// two rims as the plain file.
TEST_F(CliTest, csv_with_a_header_and_leica_pts_read_as_the_plain_points) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 4000 --seed 2 -q -o " + path("c.xyz")).exit_code, 0);
  {
    std::ifstream in(path("c.xyz"));
    std::ofstream csv(path("c.csv"));
    std::ofstream pts(path("c.pts"));
    csv << "//X,Y,Z,R,G,B,Intensity\n";
    pts << "4000\n";
    std::string line;
    for (int i = 0; std::getline(in, line); ++i) {
      std::istringstream fields(line);
      std::string x, y, z;
      fields >> x >> y >> z;
      csv << x << "," << y << "," << z << "," << i % 256 << ",128,0," << 0.001 * i << "\n";
      pts << x << " " << y << " " << z << " " << -i % 2000 << " " << i % 256 << " 128 0\n";
    }
  }
  const auto plain = run_envcrust_json("boundary " + path("c.xyz") + " --json");
  for (const char* name : {"c.csv", "c.pts"}) {
    const auto j = run_envcrust_json(std::string("boundary ") + path(name) + " --json");
    EXPECT_EQ(j["points"], 4000) << name;
    EXPECT_EQ(j["curves"].size(), 2u) << name;
    EXPECT_EQ(j["curves"], plain["curves"]) << name;
  }
}

// Normals in a point file may have any length (they are scaled to unit length), but not
// zero: the error names the file and the point (counted from 1 in file order).
TEST_F(CliTest, reconstruct_refuses_a_zero_normal_naming_the_point) {
  {
    std::ofstream out(path("n.xyz"));
    for (int i = 0; i < 40; ++i) out << std::cos(0.3 * i) << " " << std::sin(0.3 * i) << " " << 0.05 * i << " 0 0 " << (i == 6 ? 0 : 2.5) << "\n";
  }
  expect_reconstruct_refuses("n.xyz", "point 7 has a zero normal");
  // All of them zero (an exporter's placeholder): no normals given, and they are estimated.
  ASSERT_EQ(run_envcrust("sample cylinder -n 4000 -q -o " + path("c.xyz")).exit_code, 0);
  {
    std::ifstream in(path("c.xyz"));
    std::ofstream out(path("zeros.xyz"));
    std::string line;
    while (std::getline(in, line)) out << line << " 0 0 0\n";
  }
  const auto j = run_envcrust_json("reconstruct " + path("zeros.xyz") + " -o " + path("z.ply") + " --json");
  const std::string note = "every normal in the file is zero: read as no normals";
  EXPECT_NE(std::find(j["notes"].begin(), j["notes"].end(), note), j["notes"].end()) << j["notes"];
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
}

// A few stray points make the widest gaps of the input; the warning about gaps counts the
// samples that see one, which tells them from a sparse region, and the result stays right.
TEST_F(CliTest, reconstruct_counts_the_samples_behind_a_gap_warning) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 4000 --seed 5 -q -o " + path("c.xyz")).exit_code, 0);
  {
    std::ofstream out(path("c.xyz"), std::ios::app);
    for (int i = 0; i < 6; ++i) out << 0.3 * (i - 2.5) << " 0.1 " << (i % 2 ? 1.6 : -1.6) << "\n";  // beyond the rims
  }
  // Kept (--keep-outliers): by default these strays are removed before anything else.
  const auto j = run_envcrust_json("reconstruct " + path("c.xyz") + " -r builtin:cylinder -o " + path("c.ply") +
                                   " --keep-outliers --json");
  std::string gaps;
  for (const auto& w : j["warnings"])
    if (w.get<std::string>().rfind("the input has gaps of up to ", 0) == 0) gaps = w.get<std::string>();
  ASSERT_FALSE(gaps.empty()) << j["warnings"].dump();
  const auto at = gaps.find(" at ");
  const auto of = gaps.find(" of 4006 samples (rho is ");
  ASSERT_NE(at, std::string::npos) << gaps;
  ASSERT_NE(of, std::string::npos) << gaps;
  const int wide = std::stoi(gaps.substr(at + 4, of - at - 4));
  EXPECT_GE(wide, 1) << gaps;
  EXPECT_LE(wide, 6) << gaps;  // the stray points, not the cylinder's samples
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
}

// A scan that repeats its points (overlapping views written out together) reconstructs as
// the points once: before the merge, every copy read as a zero spacing and the envelope came
// out with holes ("the reconstruction is empty").
TEST_F(CliTest, reconstruct_merges_repeated_points) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 4000 --seed 5 -q -o " + path("c.xyz")).exit_code, 0);
  const std::string once = envcrust::testing::slurp(path("c.xyz"));
  {
    std::ofstream out(path("twice.xyz"));
    out << once << once;
  }
  const auto a = run_envcrust_json("reconstruct " + path("c.xyz") + " --no-analysis -o " + path("a.ply") + " --json");
  const auto b = run_envcrust_json("reconstruct " + path("twice.xyz") + " -r builtin:cylinder -o " + path("b.ply") +
                                   " --json");
  EXPECT_EQ(b["input_points"], 4000);
  EXPECT_EQ(b["notes"][0], "4000 duplicate points merged");
  EXPECT_EQ(b["envelope"]["rho"], a["envelope"]["rho"]);
  EXPECT_EQ(b["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(b["analysis"]["boundary_loops"], 2);
  EXPECT_LT(b["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
}

TEST_F(CliTest, reconstruct_a_moebius_mesh) {
  ASSERT_EQ(run_envcrust("sample moebius --mesh -q -o " + path("m.off")).exit_code, 0);
  const auto r = run_envcrust("reconstruct " + path("m.off") + " -r builtin:moebius -o " + path("r.ply") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 1);
  EXPECT_EQ(a["is_orientable"], false);
  // The mesh's vertices and face centres lie on a regular grid: a quadric fitted to the nearest
  // six of them was ill-conditioned (0.6-2.4% of the diagonal off); twelve read 0.01-0.05%.
  EXPECT_LT(a["distance"]["hausdorff_rel_diag"].get<double>(), 0.001);
  // The input mesh is non-orientable itself: no orientation cut by default, and no hint.
  EXPECT_EQ(j["input_is_orientable"], false);
  EXPECT_EQ(j["sheet"]["cut_to_orientable"], false);
  EXPECT_EQ(j["sheet"]["cut_handles_rel_rho"], 1.5);  // a scan's default; every ball is a disc here
  EXPECT_EQ(j["sheet"]["handle_balls"], 0);
  EXPECT_TRUE(j["hints"].empty()) << j["hints"].dump();
  // --orientable=yes overrides what the mesh says: the strip is cut across into a disc.
  const auto f = run_envcrust_json("reconstruct " + path("m.off") + " --orientable=yes -o " + path("d.ply") +
                                   " --json");
  EXPECT_EQ(f["sheet"]["orientation_seams"], 1);
  EXPECT_EQ(f["analysis"]["is_orientable"], true);
  EXPECT_EQ(f["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(f["analysis"]["boundary_loops"], 1);
  const auto text = run_envcrust("reconstruct " + path("m.off") + " --no-analysis -o " + path("r.ply"));
  EXPECT_EQ(text.out.find("hint:"), std::string::npos) << "no analysis, no hint";
}

// Scans often repeat triangles (the face scan in ../shared/data has 18): they are dropped with
// a note instead of making the mesh look non-manifold.
TEST_F(CliTest, reconstruct_drops_repeated_faces_of_a_mesh) {
  ASSERT_EQ(run_envcrust("sample cylinder --mesh -q -o " + path("c.off")).exit_code, 0);
  std::string text;
  {
    std::ifstream in(path("c.off"));
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  // Repeat the first face twice (once reversed): patch the face count and append the lines.
  std::istringstream lines(text);
  std::string header, counts, line;
  std::getline(lines, header);
  std::getline(lines, counts);
  std::size_t v = 0, f = 0, e = 0;
  std::istringstream(counts) >> v >> f >> e;
  std::vector<std::string> body;
  while (std::getline(lines, line)) body.push_back(line);
  ASSERT_EQ(body.size(), v + f);
  std::size_t n = 0, a = 0, b = 0, c = 0;
  std::istringstream(body[v]) >> n >> a >> b >> c;
  {
    std::ofstream out(path("dup.off"));
    out << "OFF\n" << v << ' ' << f + 2 << " 0\n";
    for (const auto& l : body) out << l << '\n';
    out << "3 " << a << ' ' << b << ' ' << c << "\n3 " << a << ' ' << c << ' ' << b << '\n';
  }
  const auto j = run_envcrust_json("reconstruct " + path("dup.off") + " -r builtin:cylinder -o " + path("r.ply") +
                                   " --json");
  const auto notes = j["notes"].get<std::vector<std::string>>();
  EXPECT_NE(std::find(notes.begin(), notes.end(), "2 repeated or degenerate faces dropped"), notes.end());
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
}

TEST_F(CliTest, reconstruct_refuses_a_mesh_of_zero_area_naming_it) {
  {
    std::ofstream f(path("flat.off"));
    f << "OFF\n3 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n3 0 2 1\n";  // collinear, and again reversed
  }
  expect_reconstruct_refuses("flat.off", "the mesh has no face of positive area");
  {
    std::ofstream f(path("twice.off"));
    f << "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n3 2 1 2\n";  // each face uses a vertex twice
  }
  expect_reconstruct_refuses("twice.off", "the mesh has no faces but 2 that use a vertex twice");
}

TEST_F(CliTest, reconstruct_refuses_a_non_manifold_mesh) {
  {
    std::ofstream f(path("fin.off"));
    f << "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n";
  }
  const auto r = run_envcrust("reconstruct " + path("fin.off") + " -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "envcrust: error: " + path("fin.off") +
                       ": edge (0, 1) has 3 faces: the mesh is not a surface (--as-points reads its vertices as a "
                       "point file)\n");
}

// --as-points: a mesh that is no surface (an open cylinder's grid, 120 x 60, with a fin of
// two more triangles on one of its edges) is read as its vertices, and comes out as the
// cylinder.
TEST_F(CliTest, reconstruct_as_points_reads_a_broken_meshs_vertices) {
  {
    envcrust::TriangleMesh mesh = envcrust::fixtures::open_cylinder(120, 60);
    const auto edge = mesh.triangles[mesh.triangles.size() / 2];
    for (const double lift : {0.001, 0.002}) {
      const envcrust::Point3 a = mesh.vertices[edge[0]];
      mesh.vertices.emplace_back(a.x() * (1 + lift), a.y() * (1 + lift), a.z() + lift);
      mesh.triangles.push_back({edge[0], edge[1], static_cast<envcrust::Index>(mesh.vertices.size() - 1)});
    }
    envcrust::io::write_mesh(path("fin.off"), mesh);
  }
  const auto refused = run_envcrust("reconstruct " + path("fin.off") + " -o " + path("x.ply"));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("faces: the mesh is not a surface (--as-points reads its vertices as a point file)"),
            std::string::npos)
      << refused.err;
  const auto j = run_envcrust_json("reconstruct " + path("fin.off") + " --as-points -r builtin:cylinder -o " +
                                   path("c.ply") + " --json");
  EXPECT_EQ(j["source"], "points");
  ASSERT_FALSE(j["notes"].empty());
  EXPECT_EQ(j["notes"][0].get<std::string>().find("the mesh's "), 0u) << j["notes"];
  EXPECT_NE(j["notes"][0].get<std::string>().find(" vertices read as a point file (--as-points)"), std::string::npos);
  EXPECT_EQ(j["input_boundary_curves"], 2);
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 0);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 2);
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
}

TEST_F(CliTest, as_points_applies_to_mesh_files_only) {
  ASSERT_EQ(run_envcrust("sample cylinder -n 2000 -q -o " + path("c.xyz")).exit_code, 0);
  const auto points = run_envcrust("reconstruct " + path("c.xyz") + " --as-points -o " + path("x.ply"));
  EXPECT_EQ(points.exit_code, 2);
  EXPECT_EQ(points.err, "envcrust: usage error: --as-points applies to mesh files: " + path("c.xyz") + " has no faces\n");
  const auto builtin = run_envcrust("reconstruct builtin:cylinder --as-points -o " + path("x.ply"));
  EXPECT_EQ(builtin.exit_code, 2);
  EXPECT_EQ(builtin.err,
            "envcrust: usage error: --as-points applies to mesh files: builtin:cylinder is sampled with its exact normals\n");
  EXPECT_FALSE(fs::exists(path("x.ply")));
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

// --boundary-take-in bulges the curve out past samples the outer fit leaves beyond it: on the
// square's point file (seed 3: a void at its left edge with two samples across its mouth) the
// detected curve comes closer to the true rim (measured 2.48% -> 2.01% of the diagonal; the
// samples leave the rim up to 1.69% from them).
TEST_F(CliTest, boundary_take_in_brings_the_curve_out_to_the_samples_beyond_it) {
  const auto plain = run_envcrust_json("boundary builtin:square --seed 3 --json");
  const auto taken = run_envcrust_json("boundary builtin:square --seed 3 --boundary-take-in --json");
  ASSERT_EQ(plain["curves"].size(), 1u);
  ASSERT_EQ(taken["curves"].size(), 1u);
  const double before = plain["reference"]["true_loops"][0]["hausdorff_rel_diag"].get<double>();
  const double after = taken["reference"]["true_loops"][0]["hausdorff_rel_diag"].get<double>();
  const double gap = taken["reference"]["samples_gap"]["max_rel_diag"].get<double>();
  EXPECT_LT(after, 0.85 * before);
  EXPECT_LT(after, 1.25 * gap);
}

// A mesh bent by more than 80 degrees along a long crease gets a note naming the crease, and
// fitted normal lines round it off (the default), or (--creases join) the crease is left out
// of the reach estimate (rho is not dragged down by it) and the sheet joins samples across
// it: either way the fold comes out as one disc, the rounded one closer to the fold (0.63% /
// 0.81% of the diagonal against 1.36% / 1.78% at the automatic rho, measured). Bent by 45
// degrees, no note.
TEST_F(CliTest, reconstruct_rounds_off_or_joins_a_mesh_across_a_sharp_crease) {
  auto strings_of = [](const nlohmann::json& j) {
    std::vector<std::string> out;
    for (const auto& w : j) out.push_back(w.get<std::string>());
    return out;
  };
  auto has_crease_note = [&](const nlohmann::json& j) {
    for (const auto& n : strings_of(j["notes"]))
      if (n.find("bends by more than") != std::string::npos) return true;
    return false;
  };
  auto has_note = [&](const nlohmann::json& j, const std::string& start, const std::string& end) {
    for (const auto& n : strings_of(j["notes"]))
      if (n.rfind(start, 0) == 0 && n.size() >= end.size() && n.compare(n.size() - end.size(), end.size(), end) == 0)
        return true;
    return false;
  };
  envcrust::io::write_mesh(path("fold90.off"), envcrust::fixtures::folded_sheet(90.0, 20));
  const std::string named = "the mesh bends by more than 80 degrees across 20 edges (1 long in all, up to 90 degrees near";
  for (const std::string mode : {"round", "join"}) {
    const auto sharp = run_envcrust_json("reconstruct " + path("fold90.off") + " --creases " + mode +
                                         " --no-adaptive-retry -o " + path("r90.ply") + " --json");
    EXPECT_TRUE(has_note(sharp, named,
                         mode == "round" ? "creases, which fitted normal lines round off (--creases join: joined across by the sheet)"
                                         : "creases, left out of the reach estimate and joined across by the sheet"))
        << mode << ": " << sharp["notes"].dump();
    EXPECT_EQ(sharp["analysis"]["euler_characteristic"], 1) << mode;
    EXPECT_EQ(sharp["analysis"]["boundary_loops"], 1) << mode;
    EXPECT_EQ(sharp["analysis"]["components"], 1) << mode;
    EXPECT_EQ(sharp["analysis"]["is_manifold"], true) << mode;
    // The fold is rounded off within rho; the fitted normals' envelope follows it closer.
    const double rho_rel_diag = sharp["envelope"]["rho"].get<double>() / std::sqrt(3.0);
    const double bar = mode == "round" ? 0.01 : rho_rel_diag;
    EXPECT_LT(sharp["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), bar) << mode;
    EXPECT_LT(sharp["analysis"]["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), bar) << mode;
  }
  envcrust::io::write_mesh(path("fold45.off"), envcrust::fixtures::folded_sheet(45.0, 20));
  const auto mild = run_envcrust_json("reconstruct " + path("fold45.off") + " --rho 0.1 --no-adaptive-retry -o " +
                                      path("r45.ply") + " --json");
  EXPECT_FALSE(has_crease_note(mild));
  EXPECT_EQ(mild["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(mild["analysis"]["boundary_loops"], 1);
  EXPECT_EQ(mild["analysis"]["components"], 1);
}

// A mesh whose faces repeat their vertices along seams (five separate grids of the open box,
// as exporters that split vertices write them) is welded first, as the analyzer welds it:
// one disc with the rim as its loop, not five squares with a false border along every seam.
TEST_F(CliTest, reconstruct_welds_a_mesh_whose_faces_repeat_their_vertices) {
  const envcrust::TriangleMesh faces = envcrust::fixtures::open_box_faces(12);
  envcrust::io::write_mesh(path("box_faces.off"), faces);
  const auto j = run_envcrust_json("reconstruct " + path("box_faces.off") + " -o " + path("box_faces.ply") + " --json");
  // 5 x 13^2 vertices given; the open box's 12-grid has 6 x 13^2 - 12 x 13 + 8 = 866 on the
  // closed cube, less the top's 11^2 inner ones: 745.
  const std::size_t repeated = faces.vertices.size() - (6 * 169 - 12 * 13 + 8 - 121);
  bool named = false;
  for (const auto& n : j["notes"])
    if (n.get<std::string>() == std::to_string(repeated) + " vertices at the coordinates of another welded to it") named = true;
  EXPECT_TRUE(named) << j["notes"].dump();
  EXPECT_EQ(j["input_boundary_curves"], 1) << j.dump();
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 1);
  EXPECT_EQ(j["analysis"]["components"], 1);
  EXPECT_EQ(j["analysis"]["is_manifold"], true);
  // The creases and corners are rounded off within rho (0.087, 5% of the diagonal 1.73; the
  // worst place is a corner of the rim, where a crease meets the border).
  const double rho_rel_diag = j["envelope"]["rho"].get<double>() / std::sqrt(3.0);
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), rho_rel_diag);
  EXPECT_LT(j["analysis"]["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), rho_rel_diag);
}

// A point file whose normals jump across sharp creases (an open box with each face's exact
// normal) gets a note naming the creases, and fitted normal lines, which round them off,
// replace the file's: one disc close to the box. The file's normals jumping at the box's
// edges used to tear the sheet there (10,000 points: 4 closed pieces, chi 8, 14% off, 88 s).
TEST_F(CliTest, reconstruct_rounds_off_the_creases_a_point_file_s_normals_jump_across) {
  const envcrust::PointSet samples = envcrust::fixtures::open_box_samples(5000, 5);
  envcrust::io::write_points(path("box.xyz"), samples);
  envcrust::io::write_mesh(path("box_truth.off"), envcrust::fixtures::open_box_faces(40));
  const auto j = run_envcrust_json("reconstruct " + path("box.xyz") + " -r " + path("box_truth.off") + " -o " +
                                   path("box_points.ply") + " --json");
  std::vector<std::string> notes;
  for (const auto& n : j["notes"]) notes.push_back(n.get<std::string>());
  const std::string jump = "the normals given jump by more than 80 degrees across ";
  const std::string rounded = "): creases, which fitted normal lines round off (--creases join: joined across by the sheet)";
  ASSERT_TRUE(std::any_of(notes.begin(), notes.end(), [&](const std::string& n) {
    return n.rfind(jump, 0) == 0 && n.size() > rounded.size() &&
           n.compare(n.size() - rounded.size(), rounded.size(), rounded) == 0;
  })) << j["notes"].dump();
  EXPECT_EQ(j["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(j["analysis"]["boundary_loops"], 1);
  EXPECT_EQ(j["analysis"]["components"], 1);
  EXPECT_EQ(j["analysis"]["is_manifold"], true);
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.025);
  // The true surface to the result: the rim lies up to this far from the nearest sample.
  double rim_gap = 0;
  for (int k = 0; k < 400; ++k) {
    const double t = (k % 100) / 100.0;
    const int side = k / 100;
    const envcrust::Point3 rim = side == 0 ? envcrust::Point3(t, 0, 1) : side == 1 ? envcrust::Point3(1, t, 1)
                               : side == 2 ? envcrust::Point3(1 - t, 1, 1) : envcrust::Point3(0, 1 - t, 1);
    double nearest = 1e300;
    for (const auto& p : samples.points) nearest = std::min(nearest, std::sqrt(CGAL::squared_distance(p, rim)));
    rim_gap = std::max(rim_gap, nearest);
  }
  const double diagonal = std::sqrt(3.0);
  EXPECT_LT(j["analysis"]["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(),
            std::max(0.025, 1.1 * rim_gap / diagonal));
  // Without normals the same points read no crease and come out alike.
  envcrust::PointSet bare = samples;
  bare.normals.clear();
  envcrust::io::write_points(path("box_bare.xyz"), bare);
  const auto plain = run_envcrust_json("reconstruct " + path("box_bare.xyz") + " -r " + path("box_truth.off") +
                                       " -o " + path("box_bare.ply") + " --json");
  for (const auto& n : plain["notes"]) EXPECT_EQ(n.get<std::string>().find("jump by more than"), std::string::npos);
  EXPECT_EQ(plain["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(plain["analysis"]["boundary_loops"], 1);
}
