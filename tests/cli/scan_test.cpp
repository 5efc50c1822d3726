// Real scans through the CLI (label slow: 1-130 s each on 2 cores; skipped when
// ../shared/data is absent). Each test asserts the result: its topology (pieces, chi, loops,
// orientability, genus), that it is embedded, and its distances to the scan's own mesh or
// points, within tolerances a little above what was measured (2026-12-05); which repairs ran
// to get there is not asserted. A run that exits non-zero (bad input, or a result that fails
// its own checks, exit 4) fails the test. Issue #5: the foot is a manifold with the ankle as
// its only boundary loop; the bunny is a genus-0 manifold with its detected base holes, with a
// uniform or an adaptive rho; the lion head, as a mesh and as points, is a disc. Issue #4: the
// original Power Crust program's own sample inputs come out as the closed surfaces they sample.
#include "cli_fixture.h"
#include "run_command.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using envcrust::testing::CliTest;
using envcrust::testing::run_envcrust_json;

// The analysis says: one orientable manifold piece with `loops` boundary loops and Euler
// characteristic `chi`.
void expect_one_orientable_piece(const nlohmann::json& a, int loops, int chi) {
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(a["components"], 1);
  EXPECT_EQ(a["is_orientable"], true);
  EXPECT_EQ(a["boundary_loops"], loops);
  EXPECT_EQ(a["euler_characteristic"], chi);
}

TEST_F(CliTest, issue_5_foot_scan_is_a_manifold_disc_with_the_ankle_loop) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "foot_vhacd";
  if (!std::filesystem::exists(folder / "points.xyz")) GTEST_SKIP() << "no " << folder;
  const auto j = run_envcrust_json("reconstruct " + (folder / "points.xyz").string() + " -o " + path("foot.ply") +
                                   " --rho-adaptive --boundary-min-width 7 --reference " +
                                   (folder / "foot_open.off").string() + " --json");
  EXPECT_EQ(j["input_boundary_curves"], 1);
  const auto& a = j["analysis"];
  expect_one_orientable_piece(a, 1, 1);
  // The ankle loop of the scan's own mesh is 2.39 long; ours follows the sparse rim samples.
  EXPECT_NEAR(a["loops"][0]["length"].get<double>(), 2.39, 0.6);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.02);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.02);
}

// The bunny with the defaults: one orientable genus-0 piece with the base's 4 detected holes,
// embedded, near the scan's mesh (measured 1.22% / 2.12% of the diagonal).
TEST_F(CliTest, issue_5_bunny_is_one_orientable_genus_0_piece_with_its_base_holes) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "stanford_bunny_zipper";
  if (!std::filesystem::exists(folder / "points.xyz")) GTEST_SKIP() << "no " << folder;
  const auto j = run_envcrust_json("reconstruct " + (folder / "points.xyz").string() + " -o " + path("bunny.ply") +
                                   " --reference " + (folder / "bun_zipper.ply").string() + " --json");
  EXPECT_EQ(j["input_boundary_curves"], 4);  // the base's 4 holes; the small one on the body is missed
  EXPECT_EQ(j["boundary_check"]["is_consistent"], true);
  const auto& a = j["analysis"];
  expect_one_orientable_piece(a, 4, -2);  // genus 0 with 4 holes
  EXPECT_EQ(a["component_list"][0]["genus"], 0);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.015);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.025);
  // Four of the mesh's five holes are followed by a loop of the result (the fifth, on the body,
  // is below the resolution): measured 0.44%, 0.46%, 0.92% and 2.75% (the base's narrow slot).
  std::vector<double> matches;
  for (const auto& m : a["boundary_matches"])
    matches.push_back(m["hausdorff_rel_diag"].is_number() ? m["hausdorff_rel_diag"].get<double>() : 1.0);
  std::sort(matches.begin(), matches.end());
  ASSERT_EQ(matches.size(), 5u);
  EXPECT_LT(matches[2], 0.012);
  EXPECT_LT(matches[3], 0.033);
  EXPECT_EQ(a["self_intersections"]["face_pairs"], 0);
  EXPECT_EQ(a["is_embedded"], true);
  // No topology hint is left; the only one names the base's narrow slot (a real hole, 4.4
  // spacings wide) as what --boundary-min-width would drop.
  for (const auto& hint : j["hints"])
    EXPECT_EQ(hint.get<std::string>().rfind("detected boundary loop", 0), 0u) << hint;
}

// With --rho-adaptive (small where the ear tips are thin, large where the samples are
// sparse) the result has the same topology, embedded (measured 1.24% / 1.70%).
TEST_F(CliTest, issue_5_bunny_with_adaptive_rho_is_one_genus_0_piece) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "stanford_bunny_zipper";
  if (!std::filesystem::exists(folder / "points.xyz")) GTEST_SKIP() << "no " << folder;
  const auto j = run_envcrust_json("reconstruct " + (folder / "points.xyz").string() + " -o " + path("bunny.ply") +
                                   " --rho-adaptive --reference " + (folder / "bun_zipper.ply").string() + " --json");
  const auto& a = j["analysis"];
  expect_one_orientable_piece(a, 4, -2);
  EXPECT_EQ(a["component_list"][0]["genus"], 0);
  EXPECT_EQ(a["is_embedded"], true);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.015);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.021);
}

// The lion head as a mesh (a disc whose density varies 20x; its ears are plates thinner than
// rho, their rims folded by up to 133 degrees): the input's disc, with its ears and mouth
// closed, embedded; measured 2.60% / 5.84% of the diagonal, the border loop within 0.20% of
// the mesh's own.
TEST_F(CliTest, issue_5_lion_head_mesh_is_a_disc_with_its_border_loop) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "cgal_lion_head";
  if (!std::filesystem::exists(folder / "lion-head.off")) GTEST_SKIP() << "no " << folder;
  const std::string mesh = (folder / "lion-head.off").string();
  const auto j = run_envcrust_json("reconstruct " + mesh + " -o " + path("lion.ply") + " --reference " + mesh + " --json");
  EXPECT_EQ(j["input_genus"], 0);
  const auto& a = j["analysis"];
  expect_one_orientable_piece(a, 1, 1);
  EXPECT_EQ(a["self_intersections"]["face_pairs"], 0);
  EXPECT_EQ(a["is_embedded"], true);
  ASSERT_EQ(a["boundary_matches"].size(), 1u);
  EXPECT_LT(a["boundary_matches"][0]["hausdorff_rel_diag"].get<double>(), 0.005);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.032);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.07);
}

// The lion head as a point file (8,356 points whose spacing varies 20x): one loop along the
// sparse neck rim, the disc embedded (the ears and the open mouth closed); measured 3.94% /
// 6.09% of the diagonal, the neck loop within 1.68% of the mesh's own.
TEST_F(CliTest, issue_5_lion_head_points_are_a_disc_with_the_neck_loop) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "cgal_lion_head";
  if (!std::filesystem::exists(folder / "points.xyz")) GTEST_SKIP() << "no " << folder;
  const auto j = run_envcrust_json("reconstruct " + (folder / "points.xyz").string() + " -o " + path("lion.ply") +
                                   " --reference " + (folder / "lion-head.off").string() + " --json");
  EXPECT_EQ(j["input_boundary_curves"], 1);
  const auto& a = j["analysis"];
  expect_one_orientable_piece(a, 1, 1);
  EXPECT_EQ(a["self_intersections"]["face_pairs"], 0);
  // The neck loop of the scan's own mesh is 2.18 long (measured 2.26).
  EXPECT_NEAR(a["loops"][0]["length"].get<double>(), 2.18, 0.2);
  ASSERT_EQ(a["boundary_matches"].size(), 1u);
  EXPECT_LT(a["boundary_matches"][0]["hausdorff_rel_diag"].get<double>(), 0.022);
  EXPECT_EQ(j["boundary_check"]["is_consistent"], true);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.045);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.07);
}

// Every curve the detector reports on a scan is at least min_loop_length (20 spacings) long.
// On the face scan and the second bunny view a path ran out and back along one chain of
// flagged samples; with its switchbacks removed it was left a loop of 0.7 and 5.8 spacings
// (3 and 7 vertices) that still passed, since only the path was held to the length.
TEST_F(CliTest, issue_5_detected_scan_loops_are_never_shorter_than_the_minimum) {
  const std::filesystem::path data = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data";
  for (const char* file : {"face_yh_scan_vhacd/points.xyz", "stanford_bunny_range_scans/bun045_points.xyz"}) {
    if (!std::filesystem::exists(data / file)) GTEST_SKIP() << "no " << data / file;
    const auto j = run_envcrust_json("boundary " + (data / file).string() + " --json");
    const double spacing = j["spacing"].get<double>();
    ASSERT_GT(j["curves"].size(), 5u) << file;
    for (const auto& curve : j["curves"]) EXPECT_GE(curve["length"].get<double>(), 20 * spacing) << file;
  }
}

// The sample inputs shipped with the original Power Crust program (synthetic closed surfaces):
// two capsules of different sizes, and a knotted tube whose first point, (0, 0, 0), is a
// stray one in the empty middle of the knot. The crust of each is the closed surface, within
// about a sample spacing of the points (measured: 1.5% and 2.6% of the diagonal, vertices of
// the crust to the nearest point; every point within 0.02% of the crust).
TEST_F(CliTest, issue_4_power_crust_reproduces_the_original_programs_samples) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "powercrust_samples";
  if (!std::filesystem::exists(folder / "knot.pts")) GTEST_SKIP() << "no " << folder;
  struct Case {
    std::string name;
    int components, chi, genus;
  };
  for (const Case& c : {Case{"hotdogs", 2, 4, 0}, Case{"knot", 1, 0, 1}}) {
    SCOPED_TRACE(c.name);
    const std::string points = (folder / (c.name + ".pts")).string();
    const auto pc = run_envcrust_json("powercrust " + points + " -o " + path(c.name + ".ply") + " --json");
    EXPECT_EQ(pc["duplicate_points"], 0);
    EXPECT_EQ(pc["unknown_poles"], 0);
    EXPECT_TRUE(pc["warnings"].empty()) << pc["warnings"];
    EXPECT_EQ(pc["crust"]["is_closed"], true);
    EXPECT_EQ(pc["crust"]["is_manifold"], true);
    EXPECT_EQ(pc["crust"]["misoriented_edges"], 0);

    // The knot's stray centre point is left out of the reference: it lies on no surface.
    std::string reference = points;
    if (c.name == "knot") {
      reference = path("knot_without_the_stray_point.xyz");
      std::ifstream in(points);
      std::ofstream out(reference);
      std::string line;
      std::getline(in, line);
      EXPECT_EQ(line.find_first_not_of(" 0"), std::string::npos) << line;
      while (std::getline(in, line)) out << line << '\n';
    }
    const auto a = run_envcrust_json("analyze " + path(c.name + ".ply") + " --reference " + reference + " --json");
    EXPECT_EQ(a["components"], c.components);
    EXPECT_EQ(a["euler_characteristic"], c.chi);
    EXPECT_EQ(a["is_orientable"], true);
    EXPECT_EQ(a["boundary_loops"], 0);
    for (const auto& piece : a["component_list"]) EXPECT_EQ(piece["genus"], c.genus);
    EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.03);
    EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.001);
  }
}

// The original program's samples through `reconstruct` with the defaults: the capsules are
// two closed spheres (measured 3.05% / 2.99% from the points). The knotted tube, about 15
// samples around a tube of radius 1 and 0.7 apart along it, is too sparse for any envelope
// (its gaps need rho 0.84, the tube allows less than 1): it comes out the closed knotted
// torus all the same (the direct Power Crust's), measured 2.56% from the points, every point
// but the stray centre one within 0.012% of it.
TEST_F(CliTest, issue_5_closed_samples_too_sparse_for_the_envelope_come_out_closed) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "powercrust_samples";
  if (!std::filesystem::exists(folder / "knot.pts")) GTEST_SKIP() << "no " << folder;
  const auto hotdogs = run_envcrust_json("reconstruct " + (folder / "hotdogs.pts").string() + " -o " +
                                         path("hotdogs.ply") + " --json");
  const auto& h = hotdogs["analysis"];
  EXPECT_EQ(h["is_manifold"], true);
  EXPECT_EQ(h["components"], 2);
  EXPECT_EQ(h["euler_characteristic"], 4);
  EXPECT_EQ(h["boundary_loops"], 0);
  EXPECT_EQ(h["is_orientable"], true);
  EXPECT_EQ(h["is_embedded"], true);
  for (const auto& piece : h["component_list"]) EXPECT_EQ(piece["genus"], 0);
  EXPECT_LT(h["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.035);
  EXPECT_LT(h["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.035);

  // The knot's stray centre point lies on no surface: it is left out of the reference.
  const std::string reference = path("knot_without_the_stray_point.xyz");
  {
    std::ifstream in(folder / "knot.pts");
    std::ofstream out(reference);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line.find_first_not_of(" 0"), std::string::npos) << line;
    while (std::getline(in, line)) out << line << '\n';
  }
  const auto knot = run_envcrust_json("reconstruct " + (folder / "knot.pts").string() + " -o " + path("knot.ply") +
                                      " --reference " + reference + " --json");
  const auto& a = knot["analysis"];
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(a["components"], 1);
  EXPECT_EQ(a["euler_characteristic"], 0);
  EXPECT_EQ(a["boundary_loops"], 0);
  EXPECT_EQ(a["is_orientable"], true);
  EXPECT_EQ(a["is_embedded"], true);
  ASSERT_EQ(a["component_list"].size(), 1u);
  EXPECT_EQ(a["component_list"][0]["genus"], 1);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.03);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.001);
  EXPECT_TRUE(knot["hints"].empty()) << knot["hints"];
}

// The bunny's coarsest vertex set (453 points, its decimated mesh is no surface): one closed
// genus-0 piece that covers the ears (the envelope's own result leaves both out, 28% of the
// diagonal from the full mesh; the direct Power Crust's is kept), measured 3.56% / 3.77% from
// the full mesh.
TEST_F(CliTest, issue_5_a_sample_whose_ears_the_envelope_leaves_out_comes_out_whole) {
  const std::filesystem::path folder = std::filesystem::path(ENVCRUST_SHARED_DIR) / "data" / "stanford_bunny_zipper";
  if (!std::filesystem::exists(folder / "points_res4.xyz")) GTEST_SKIP() << "no " << folder;
  const auto j = run_envcrust_json("reconstruct " + (folder / "points_res4.xyz").string() + " -o " + path("b.ply") +
                                   " --reference " + (folder / "bun_zipper.ply").string() + " --json");
  const auto& a = j["analysis"];
  EXPECT_EQ(a["components"], 1);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(a["euler_characteristic"], 2);
  EXPECT_EQ(a["boundary_loops"], 0);
  EXPECT_EQ(a["is_orientable"], true);
  EXPECT_EQ(a["is_embedded"], true);
  // 453 points leave the full mesh's boundary up to 3.7% of the diagonal from the nearest.
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.045);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.045);
}

}  // namespace
