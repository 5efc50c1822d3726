// End-to-end tests of `envcrust reconstruct` on mesh files: repeated faces and vertices,
// refusals, --as-points, sharp creases.
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

namespace {

// The samples' median spacing (the report's sample_meshing) over the diagonal of a unit box,
// 0 when the sheet is the output.
double spacing_rel_diag(const nlohmann::json& report) {
  if (!report.contains("sample_meshing") || !report["sample_meshing"]["is_kept"].get<bool>()) return 0.0;
  return report["sample_meshing"]["spacing"].get<double>() / std::sqrt(3.0);
}

}  // namespace


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
  // An advancing front cannot make a Moebius band: the output is the sheet, simplified to
  // about the input's number of points (the sheet has a third more here).
  EXPECT_EQ(j["sample_meshing"]["is_kept"], false);
  EXPECT_EQ(j["simplify"]["is_simplified"], true);
  EXPECT_EQ(j["simplify"]["vertices_after"], a["vertices"]);
  EXPECT_GT(j["simplify"]["vertices_before"].get<double>(), 1.2 * a["vertices"].get<double>());
  EXPECT_LT(a["vertices"].get<double>(), 1.1 * j["input_points"].get<double>());
  // --orientable=yes overrides what the mesh says: the strip is cut across into a disc.
  const auto f = run_envcrust_json("reconstruct " + path("m.off") + " --orientable=yes -o " + path("d.ply") +
                                   " --json");
  EXPECT_EQ(f["sheet"]["orientation_seams"], 1);
  EXPECT_EQ(f["analysis"]["is_orientable"], true);
  EXPECT_EQ(f["analysis"]["euler_characteristic"], 1);
  EXPECT_EQ(f["analysis"]["boundary_loops"], 1);
  const auto text = run_envcrust("reconstruct " + path("m.off") + " --no-analysis -o " + path("r.ply"));
  EXPECT_EQ(text.out.find("hint:"), std::string::npos) << "no analysis, no hint";
  EXPECT_NE(text.out.find("  output: the sheet, simplified from "), std::string::npos) << text.out;
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
    // The output's vertices are the mesh's samples (vertices and face centres): where the fold
    // meets the border a triangle of theirs may cut the corner, by up to one sample spacing.
    const double bar = std::max(mode == "round" ? 0.01 : rho_rel_diag, spacing_rel_diag(sharp));
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
  // The creases and corners are rounded off within rho (0.05, 2.9% of the diagonal 1.73) or,
  // the output's vertices being the mesh's samples, cut by a triangle of theirs: the worst
  // place is a corner of the rim, where a crease meets the border, cut across by an edge
  // between grid vertices (1/12 apart, 1.5 times the samples' median spacing of 0.055 with
  // the face centres).
  const double bar = std::max(j["envelope"]["rho"].get<double>() / std::sqrt(3.0), 1.5 * spacing_rel_diag(j));
  EXPECT_LT(j["analysis"]["distance"]["mesh_to_reference"]["max_rel_diag"].get<double>(), bar);
  EXPECT_LT(j["analysis"]["distance"]["reference_to_mesh"]["max_rel_diag"].get<double>(), bar);
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
