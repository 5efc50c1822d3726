// End-to-end tests of `envcrust reconstruct` on point files: estimated normals, detected or
// given boundaries, stray samples, hints, and the messages for bad point input.
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
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using envcrust::testing::CliTest;
using envcrust::testing::run_envcrust;
using envcrust::testing::run_envcrust_json;
namespace fs = std::filesystem;


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
  // The first run, with a local rho, needed no cut and is the result: its rho reaches the
  // ceiling (5% of the diagonal) everywhere on a cylinder of reach 1 and diagonal 2 sqrt 3.
  const auto& local = j["local_rho_first"];
  EXPECT_EQ(local["kept"], true);
  EXPECT_EQ(local["result"]["defects"], 0);
  EXPECT_NEAR(local["rho_max"].get<double>(), 0.05 * 2 * std::sqrt(3.0), 0.002);
  EXPECT_EQ(local["envelope_samples"], j["envelope"]["samples"]);
  EXPECT_FALSE(j.contains("adaptive_retry"));
}

// A closed point file: the plain Power Crust runs first and, with no defect, is the result; no
// envelope is made (the report's envelope is null). Asking for the envelope file makes one.
TEST_F(CliTest, reconstruct_of_a_closed_point_file_keeps_a_clean_power_crust_first) {
  ASSERT_EQ(run_envcrust("sample sphere -n 4000 --seed 5 -q -o " + path("s.xyz")).exit_code, 0);
  const auto r = run_envcrust("reconstruct " + path("s.xyz") + " -r builtin:sphere -o " + path("s.ply"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  the input has no boundary curve: the direct Power Crust first ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" s) has genus 0 (0 defects), kept (no envelope run)\n"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("  envelope: rho"), std::string::npos) << r.out;
  const auto j = run_envcrust_json("reconstruct " + path("s.xyz") + " -r builtin:sphere -o " + path("s.ply") +
                                   " --json");
  EXPECT_EQ(j["power_crust_first"]["kept"], true);
  EXPECT_EQ(j["power_crust_first"]["result"]["defects"], 0);
  EXPECT_TRUE(j["envelope"].is_null());
  EXPECT_FALSE(j.contains("local_rho_first"));
  const auto& a = j["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 2);
  EXPECT_EQ(a["boundary_loops"], 0);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.01);
  EXPECT_LT(a["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), 0.01);
  const auto e = run_envcrust_json("reconstruct " + path("s.xyz") + " -o " + path("e.ply") + " --envelope-out " +
                                   path("env.xyz") + " --json");
  EXPECT_FALSE(e.contains("power_crust_first"));
  EXPECT_GT(e["envelope"]["samples"].get<long>(), 0);
  EXPECT_TRUE(fs::exists(path("env.xyz")));
}

// Normals in a point file say nothing about the rim: the reach of its surface is read the same
// with them as without. The hemisphere (reach 1) with its exact normals in the file read a reach
// of 0.10 from a rim vertex whose fitted curve tilts its conormal, and ran with a tenth of the
// rho and 20 times the output vertices of the same points without normals.
TEST_F(CliTest, reconstruct_reads_the_same_reach_with_the_files_normals_as_without) {
  ASSERT_EQ(run_envcrust("sample hemisphere -n 10000 --seed 2 --normals -q -o " + path("hn.xyz")).exit_code, 0);
  {
    std::ifstream in(path("hn.xyz"));
    std::ofstream out(path("h.xyz"));
    out << std::setprecision(17);
    double x, y, z, nx, ny, nz;
    while (in >> x >> y >> z >> nx >> ny >> nz) out << x << ' ' << y << ' ' << z << '\n';
  }
  // The uniform run alone: the local-rho first run, kept on a hemisphere, estimates no reach.
  const auto with = run_envcrust_json("reconstruct " + path("hn.xyz") + " -r builtin:hemisphere -o " +
                                      path("hn.ply") + " --no-adaptive-retry --json");
  const auto without = run_envcrust_json("reconstruct " + path("h.xyz") + " -r builtin:hemisphere -o " +
                                         path("h.ply") + " --no-adaptive-retry --json");
  const double reach_with = with["envelope"]["reach"]["reach"].get<double>();
  const double reach_without = without["envelope"]["reach"]["reach"].get<double>();
  EXPECT_GT(reach_with, 0.8);  // the hemisphere's reach is 1
  EXPECT_NEAR(reach_with, reach_without, 0.1 * reach_without);
  const auto& a = with["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 1);
  EXPECT_EQ(a["boundary_loops"], 1);
  EXPECT_LT(a["vertices"].get<double>(), 3.0 * 10000);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
}

// Strays in a scan (50 specks in the cylinder's bounding box, 0.5% of the points) are removed
// before anything else: every speck farther than 3 spacings from the surface is removed, and
// no sample of it. The output's vertices are the samples kept, so it lies within 0.5% of the
// diagonal or, where a speck nearer than that was kept, within 1.1 times the speck's distance.
// Kept (--keep-outliers), the specks shrink the estimated reach and with it rho (more than
// twice the envelope samples).
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
  double farthest_kept = 0;  // of the specks not removed
  for (std::size_t i = samples; i < read.points.size(); ++i) {
    const bool is_removed = std::any_of(removed.begin(), removed.end(), [&](const envcrust::Point3& p) {
      return CGAL::squared_distance(p, read.points[i]) < 1e-18;
    });
    if (!is_removed) farthest_kept = std::max(farthest_kept, distance_to_cylinder(read.points[i]));
  }
  const double diagonal = std::sqrt(12.0);  // the cylinder's box, 2 x 2 x 2
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(),
            std::max(0.005, 1.1 * farthest_kept / diagonal));
  const auto text = run_envcrust("envelope " + path("specks.xyz") + " -o " + path("e.xyz"));
  EXPECT_NE(text.out.find("\n  input: " + std::to_string(removed.size()) +
                          " stray samples removed (--outliers-out writes them, --keep-outliers keeps them)\n"),
            std::string::npos)
      << text.out;
  const auto kept = run_envcrust_json("reconstruct " + path("specks.xyz") + " -r builtin:cylinder -o " +
                                      path("k.ply") + " --keep-outliers --json");
  EXPECT_EQ(kept["input_outliers_removed"], 0);
  EXPECT_LT(kept["envelope"]["rho"].get<double>(), 0.7 * j["envelope"]["rho"].get<double>());
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
  // The report names the surface that guided the output: the Power Crust's, not the sheet.
  const auto text = run_envcrust("reconstruct " + path("t.xyz") + " --no-analysis -o " + path("f.ply"));
  EXPECT_NE(text.out.find("  output: the input samples meshed along the Power Crust's surface ("), std::string::npos)
      << text.out;
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

// A strip 100 times longer than wide, as a scan of a belt would give it (no normals): its
// detected rims bound the automatic rho to the strip's half-width, where half of 10% of the
// diagonal (1.0, five times the width) tore it into pieces.
TEST_F(CliTest, reconstruct_a_narrow_strip_with_rho_from_its_width) {
  {
    std::ofstream out(path("strip.xyz"));
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> along(0.0, 20.0), across(0.0, 0.2);
    out << std::setprecision(17);
    for (int i = 0; i < 8000; ++i) out << along(rng) << ' ' << across(rng) << " 0\n";
  }
  const auto j = run_envcrust_json("reconstruct " + path("strip.xyz") + " -o " + path("strip.ply") + " --json");
  EXPECT_EQ(j["envelope"]["rho_from"], "width");
  const double half_width = j["envelope"]["half_width"].get<double>();
  EXPECT_GT(half_width, 0.08);  // the detected rims lie at the outermost samples, inside the edges
  EXPECT_LE(half_width, 0.1);
  EXPECT_DOUBLE_EQ(j["envelope"]["rho"].get<double>(), half_width);
  const auto& a = j["analysis"];
  EXPECT_EQ(a["components"], 1);
  EXPECT_EQ(a["euler_characteristic"], 1);
  EXPECT_EQ(a["boundary_loops"], 1);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
}

// An annulus (radii 0.3 and 1, 20,000 samples at random) sampled ten times more densely on
// its half x > 0: the dense half's samples along the step have all their nearest neighbours
// on their side and are read as a boundary, and the sparse half's rims fall into pieces (by
// default the result is a disc with one loop); with --boundary-density-steps the step is no
// boundary, and with --boundary-local-spacing the sparse rims are linked in their own
// spacing.
TEST_F(CliTest, reconstruct_an_annulus_whose_density_steps_tenfold) {
  {
    std::ofstream out(path("annulus.xyz"));
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    out << std::setprecision(17);
    for (int written = 0; written < 20000;) {
      const double r = std::sqrt(0.09 + 0.91 * u(rng)), a = 2 * M_PI * u(rng);
      const double x = r * std::cos(a), y = r * std::sin(a);
      if (x < 0 && u(rng) > 0.1) continue;
      out << x << ' ' << y << " 0\n";
      ++written;
    }
  }
  const auto j = run_envcrust_json("reconstruct " + path("annulus.xyz") + " -o " + path("annulus.ply") +
                                   " --boundary-density-steps --boundary-local-spacing --json");
  EXPECT_EQ(j["input_boundary_curves"], 2);
  const auto& a = j["analysis"];
  EXPECT_EQ(a["components"], 1);
  EXPECT_EQ(a["euler_characteristic"], 0);
  ASSERT_EQ(a["boundary_loops"], 2);
  EXPECT_EQ(a["self_intersections"]["face_pairs"], 0);
  // The loops: the circles of radius 1 and 0.3 (lengths 6.28 and 1.88), a little inside.
  std::vector<double> lengths;
  for (const auto& loop : a["loops"]) lengths.push_back(loop["length"].get<double>());
  std::sort(lengths.begin(), lengths.end());
  ASSERT_EQ(lengths.size(), 2u);
  EXPECT_NEAR(lengths[0], 2 * M_PI * 0.3, 0.25) << lengths[0] << " " << lengths[1];
  EXPECT_NEAR(lengths[1], 2 * M_PI, 0.4);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.025);

  // With the step kept as a boundary the detector's curves run along it too.
  const auto total_length = [](const nlohmann::json& report) {
    double sum = 0.0;
    for (const auto& curve : report["curves"]) sum += curve["length"].get<double>();
    return sum;
  };
  const auto plain = run_envcrust_json("boundary " + path("annulus.xyz") +
                                       " --boundary-density-steps --boundary-local-spacing --json");
  const auto kept = run_envcrust_json("boundary " + path("annulus.xyz") + " --boundary-local-spacing --json");
  EXPECT_GT(total_length(kept), total_length(plain) + 0.2) << kept["curves"].dump();
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

// A speck of 13 samples 0.2 above the plane of a square of 10,000, with its rim given: the
// result has no piece there (under the 20 samples a piece must lie on), and the report says
// the curve was left out, not closed.
TEST_F(CliTest, reconstruct_says_a_boundary_curve_whose_piece_is_missing_was_left_out) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  envcrust::PointSet points;
  for (int i = 0; i < 10000; ++i) points.points.emplace_back(2 * u(rng) - 1, 2 * u(rng) - 1, 0.0);
  for (int i = -2; i <= 2; ++i)  // a grid 0.02 apart, as dense as the square: 13 samples
    for (int k = -2; k <= 2; ++k)
      if (i * i + k * k <= 4) points.points.emplace_back(1.5 + 0.02 * i, 0.02 * k, 0.2);
  envcrust::io::write_points(path("p.xyz"), points);
  {
    std::ofstream out(path("rims.xyz"));
    out.precision(17);
    for (int k = 0; k < 12; ++k) {
      const double a = 2 * 3.141592653589793 * k / 12;
      out << 1.5 + 0.035 * std::cos(a) << " " << 0.035 * std::sin(a) << " 0.2\n";
    }
    for (int i = 0; i < 40; ++i) {
      const double t = -1 + 2.0 * i / 40;
      out << t << " -1 0\n1 " << t << " 0\n" << -t << " 1 0\n-1 " << -t << " 0\n";
    }
  }
  const auto j = run_envcrust_json("reconstruct " + path("p.xyz") + " --boundary " + path("rims.xyz") + " -o " +
                                   path("m.ply") + " --json --quiet");
  EXPECT_EQ(j["input_boundary_curves"], 2);
  EXPECT_EQ(j["analysis"]["components"], 1);
  const auto& check = j["boundary_check"];
  ASSERT_EQ(check["left_out_curves"].size(), 1u);
  ASSERT_EQ(check["unresolved_curves"].size(), 1u);
  EXPECT_EQ(check["left_out_curves"][0], check["unresolved_curves"][0]);
  const auto curve = check["left_out_curves"][0].get<int>();
  bool named = false;
  for (const auto& w : j["warnings"]) {
    const std::string text = w.get<std::string>();
    if (text.rfind("input boundary curve " + std::to_string(curve) + " ", 0) != 0) continue;
    named = true;
    EXPECT_NE(text.find(") is left out of the result with the part of the surface it bounds (no part of the result "
                        "lies within "),
              std::string::npos) << text;
    EXPECT_EQ(text.find("closed in the result"), std::string::npos) << text;
  }
  EXPECT_TRUE(named) << j["warnings"];
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

// A point file comes out on its own points by default (the samples meshed along the sheet,
// as `--extract samples` says); `--extract sheet` gives the finer sheet itself; an unknown
// --extract value is a usage error.
TEST_F(CliTest, reconstruct_meshes_a_point_files_own_points_by_default) {
  ASSERT_EQ(run_envcrust("sample hemisphere -n 5000 --seed 4 -q -o " + path("h.xyz")).exit_code, 0);
  const auto samples = run_envcrust_json("reconstruct " + path("h.xyz") + " -r builtin:hemisphere -o " +
                                         path("s.ply") + " --json");
  ASSERT_TRUE(samples.contains("sample_meshing"));
  EXPECT_EQ(samples["sample_meshing"]["is_kept"], true);
  EXPECT_EQ(samples["sample_meshing"]["samples_topology"], "chi 1, 1 loop, 1 piece, orientable");
  EXPECT_EQ(samples["sample_meshing"]["sheet_topology"], "chi 1, 1 loop, 1 piece, orientable");
  const auto& a = samples["analysis"];
  EXPECT_EQ(a["euler_characteristic"], 1);
  EXPECT_EQ(a["boundary_loops"], 1);
  EXPECT_LE(a["vertices"].get<int>(), 5000);
  EXPECT_GE(a["vertices"].get<int>(), 4950);
  EXPECT_LT(a["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), 0.005);
  const auto sheet = run_envcrust_json("reconstruct " + path("h.xyz") + " -r builtin:hemisphere -o " +
                                       path("t.ply") + " --extract sheet --json");
  EXPECT_FALSE(sheet.contains("sample_meshing"));
  EXPECT_EQ(sheet["analysis"]["euler_characteristic"], 1);
  EXPECT_GT(sheet["analysis"]["vertices"].get<int>(), 5000);
  const auto bad = run_envcrust("reconstruct " + path("h.xyz") + " -o " + path("u.ply") + " --extract faces");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--extract"), std::string::npos) << bad.err;
}
