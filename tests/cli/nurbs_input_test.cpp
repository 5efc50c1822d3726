// NURBS patch files (IGES entity 128, NURBS-Python JSON) through the binary: sampled with
// exact normals and boundary curves, reconstructed, used as references, and refused by name.
#include "cli_fixture.h"
#include "fixtures/nurbs_patches.h"
#include "run_command.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace envcrust::testing {
namespace {

class NurbsInput : public CliTest {
 protected:
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }
};

/// The analysis of a result: a manifold with the given topology within `max_hausdorff` of the
/// diagonal (0.5% by default).
void expect_result(const nlohmann::json& a, int euler_characteristic, int loops, bool is_orientable,
                   double max_hausdorff = 0.005) {
  EXPECT_EQ(a["euler_characteristic"], euler_characteristic);
  EXPECT_EQ(a["boundary_loops"], loops);
  EXPECT_EQ(a["is_manifold"], true);
  EXPECT_EQ(a["is_orientable"], is_orientable);
  EXPECT_LT(a["distance"]["hausdorff_rel_diag"].get<double>(), max_hausdorff);
}

TEST_F(NurbsInput, reconstructs_a_json_cylinder_patch_open_with_its_exact_boundary) {
  const std::string file = write("cyl.json", geomdl_json(cylinder_patch()));
  const auto j = run_envcrust_json("reconstruct " + file + " -n 5000 -o " + path("c.ply") + " --json");
  EXPECT_EQ(j["source"], "nurbs");
  EXPECT_EQ(j["reference"], file);  // the exact surface is the truth
  const auto& a = j["analysis"];
  expect_result(a, 0, 2, true);
  // Both true rims are matched by a reconstructed loop within 1% of the diagonal.
  ASSERT_EQ(a["boundary_matches"].size(), 2u) << a;
  for (const auto& b : a["boundary_matches"]) EXPECT_LT(b["hausdorff_rel_diag"].get<double>(), 0.01) << b;
}

TEST_F(NurbsInput, an_iges_sphere_is_sampled_tessellated_and_measured_against) {
  const std::string file = write("sphere.igs", iges_text(sphere_patch()));
  const auto s = run_envcrust_json("sample " + file + " --mesh -o " + path("s.ply") + " --json");
  EXPECT_EQ(s["expected"]["euler_characteristic"], 2);
  EXPECT_EQ(s["expected"]["boundary_loops"], 0);
  const auto a = run_envcrust_json("analyze " + path("s.ply") + " --reference " + file + " --json");
  EXPECT_EQ(a["euler_characteristic"], 2);
  EXPECT_EQ(a["boundary_loops"], 0);
  EXPECT_LT(a["distance"]["hausdorff_rel_diag"].get<double>(), 1e-3);
  const auto r = run_envcrust_json("reconstruct " + file + " -n 4000 -o " + path("r.ply") + " --json");
  expect_result(r["analysis"], 2, 0, true);
}

TEST_F(NurbsInput, a_moebius_patch_comes_out_non_orientable_with_one_loop) {
  const std::string file = write("band.json", geomdl_json(moebius_patch()));
  const auto list = run_envcrust_json("sample " + file + " -n 10 -o " + path("b.xyz") + " --json");
  EXPECT_EQ(list["expected"]["orientable"], false);
  const auto j = run_envcrust_json("reconstruct " + file + " -n 4000 -o " + path("m.ply") + " --json");
  expect_result(j["analysis"], 0, 1, false);
}

TEST_F(NurbsInput, the_shipped_trefoil_ribbon_example_has_two_linked_trefoil_edges) {
  // examples/nurbs/trefoil-ribbon.igs (scripts/make_nurbs_examples.py): a periodic cubic
  // B-spline around a trefoil's shape, extruded along z.
  const std::string file = std::string(ENVCRUST_SOURCE_DIR) + "/examples/nurbs/trefoil-ribbon.igs";
  const auto s = run_envcrust_json("sample " + file + " -n 10 -o " + path("t.xyz") + " --json");
  EXPECT_EQ(s["expected"]["boundary_knots"], nlohmann::json({"trefoil", "trefoil"}));
  EXPECT_EQ(s["expected"]["abs_linking_number"], 3);
  const auto j = run_envcrust_json("reconstruct " + file + " -n 5000 -o " + path("t.ply") + " --json");
  const auto& a = j["analysis"];
  expect_result(a, 0, 2, true);
  ASSERT_EQ(a["loops"].size(), 2u);
  for (const auto& loop : a["loops"]) EXPECT_EQ(loop["knot"]["type"], "trefoil");
  ASSERT_EQ(a["linking"].size(), 1u);
  EXPECT_EQ(std::abs(a["linking"][0]["linking_number"].get<int>()), 3);
}

TEST_F(NurbsInput, a_trimmed_iges_square_with_a_round_hole_comes_out_with_two_loops) {
  const std::string file = write("holed.igs", iges_trimmed_text(square_patch(), {}, {{iges_circle(0.5, 0.5, 0.25)}}));
  const auto s = run_envcrust_json("sample " + file + " --mesh -o " + path("truth.ply") + " --json");
  EXPECT_EQ(s["expected"]["euler_characteristic"], 0);
  EXPECT_EQ(s["expected"]["boundary_loops"], 2);
  const auto j = run_envcrust_json("reconstruct " + file + " -n 5000 -o " + path("h.ply") + " --json");
  expect_result(j["analysis"], 0, 2, true);
  ASSERT_EQ(j["analysis"]["boundary_matches"].size(), 2u);
  for (const auto& b : j["analysis"]["boundary_matches"]) EXPECT_LT(b["hausdorff_rel_diag"].get<double>(), 0.01) << b;
}

TEST_F(NurbsInput, the_shipped_models_of_several_patches_come_out_whole) {
  // examples/nurbs/tube-quarters.json: four quarter tubes joined smoothly, an open cylinder.
  const std::string examples = std::string(ENVCRUST_SOURCE_DIR) + "/examples/nurbs/";
  const auto t = run_envcrust_json("reconstruct " + examples + "tube-quarters.json -n 5000 -o " + path("t.ply") + " --json");
  EXPECT_EQ(t["source"], "nurbs");
  expect_result(t["analysis"], 0, 2, true);
  ASSERT_EQ(t["analysis"]["boundary_matches"].size(), 2u);
  for (const auto& b : t["analysis"]["boundary_matches"]) EXPECT_LT(b["hausdorff_rel_diag"].get<double>(), 0.01) << b;
  // examples/nurbs/cup.igs: a tube and the disc closing its bottom at a right angle, a disc
  // whose crease is rounded off (as sharp creases are: within 1% of the diagonal).
  const auto s = run_envcrust_json("sample " + examples + "cup.igs --mesh -o " + path("cup.ply") + " --json");
  EXPECT_EQ(s["patches"], 2);
  EXPECT_EQ(s["expected"]["euler_characteristic"], 1);
  EXPECT_EQ(s["expected"]["boundary_loops"], 1);
  const auto c = run_envcrust_json("reconstruct " + examples + "cup.igs -o " + path("c.ply") + " --json");
  const auto& a = c["analysis"];
  expect_result(a, 1, 1, true, 0.01);
  ASSERT_EQ(a["boundary_matches"].size(), 1u);
  EXPECT_LT(a["boundary_matches"][0]["hausdorff_rel_diag"].get<double>(), 0.005);
  bool creases_named = false;
  for (const auto& note : c["notes"])
    creases_named = creases_named || note.get<std::string>().starts_with("the patches meet by more than 80 degrees");
  EXPECT_TRUE(creases_named) << c["notes"];
}

TEST_F(NurbsInput, a_trimmed_plate_and_the_tube_in_its_hole_are_one_open_sink) {
  // IGES as CAD writes faces: the unit square trimmed by a round hole (144 over 128), and an
  // untrimmed tube of the hole's radius hanging from it down to z = -0.5. Joined along the
  // hole's circle: an annulus (chi 0) whose loops are the square's border and the tube's rim.
  auto tube = cylinder_patch();  // z in [-1, 1]
  for (auto& q : tube.control_points) q = Point3(0.5 + 0.25 * q.x(), 0.5 + 0.25 * q.y(), -0.25 * (1 - q.z()));
  std::vector<IgesEntity> entities;
  append_trimmed(entities, square_patch(), {}, {{iges_circle(0.5, 0.5, 0.25)}});
  entities.push_back({128, iges_surface_values(tube), 0});
  const std::string file = write("sink.igs", iges_file(entities));
  const auto s = run_envcrust_json("sample " + file + " --mesh -o " + path("sink.ply") + " --json");
  EXPECT_EQ(s["patches"], 2);
  EXPECT_EQ(s["expected"]["euler_characteristic"], 0);
  EXPECT_EQ(s["expected"]["boundary_loops"], 2);
  const auto j = run_envcrust_json("reconstruct " + file + " -n 8000 -o " + path("r.ply") + " --json");
  const auto& a = j["analysis"];
  expect_result(a, 0, 2, true, 0.01);
  ASSERT_EQ(a["boundary_matches"].size(), 2u);
  for (const auto& b : a["boundary_matches"]) EXPECT_LT(b["hausdorff_rel_diag"].get<double>(), 0.01) << b;
}

TEST_F(NurbsInput, join_tolerance_joins_faces_that_meet_less_closely) {
  // The open box with its bottom 0.003 below its sides: beyond the default tolerance (5e-4 of
  // the diagonal, 0.00087), the bottom is a piece of its own (chi 1 = a tube of sides + a
  // disc, 3 loops) and the gap is named; --join-tolerance 0.002 (0.0035) joins it.
  auto patches = open_box_patches();
  for (auto& q : patches[0].control_points) q = Point3(q.x(), q.y(), q.z() - 0.003);
  const std::string file = write("gap.igs", iges_text(patches));
  const auto apart = run_envcrust_json("sample " + file + " --mesh -o " + path("a.ply") + " --json");
  EXPECT_EQ(apart["expected"]["boundary_loops"], 3);
  EXPECT_EQ(apart["joins"]["near_misses"], 4);  // the bottom's corners (the sides' lower ones are joined to each other)
  EXPECT_NEAR(apart["joins"]["nearest_miss"].get<double>(), 0.003, 1e-9);
  const auto joined = run_envcrust_json("sample " + file + " --join-tolerance 0.002 --mesh -o " + path("j.ply") + " --json");
  EXPECT_EQ(joined["expected"]["euler_characteristic"], 1);
  EXPECT_EQ(joined["expected"]["boundary_loops"], 1);
  EXPECT_EQ(joined["joins"]["near_misses"], 0);
  EXPECT_NEAR(joined["joins"]["largest_gap"].get<double>(), 0.003, 1e-9);
}

TEST_F(NurbsInput, patches_that_form_no_surface_are_refused_by_name) {
  const auto c = [](double x, double y, double z) { return Point3(x, y, z); };
  write("book.igs", iges_text(std::vector{bilinear_patch(c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)),
                                          bilinear_patch(c(0, 0, 0), c(0, 1, 0), c(0, 1, 1), c(0, 0, 1)),
                                          bilinear_patch(c(0, 0, 0), c(-1, -1, 0), c(-1, -1, 1), c(0, 0, 1))}));
  expect_reconstruct_refuses("book.igs",
                             "3 patches meet along an edge near (0, 0, 0.5) (1 such edges): the patches form no surface");
  auto bad = cylinder_patch();
  bad.knots_u[4] = 0.1;
  write("second-bad.json", geomdl_json({square_patch(), bad}));
  expect_reconstruct_refuses("second-bad.json", "patch 2 of 2: NURBS surface: knots in u decrease at index 4 (0.25 then 0.1)");
}

TEST_F(NurbsInput, unreadable_and_degenerate_patches_are_refused_by_name) {
  write("trim.igs", iges_trimmed_text(cylinder_patch(), {iges_line(0, -1, 0.5, -1), iges_line(0.5, -1, 0.5, 1),
                                                          iges_line(0.5, 1, 0, 1), iges_line(0, 1, 0, -1)}));
  expect_reconstruct_refuses("trim.igs",
                             "NURBS surface: trimming a patch that closes up (a seam or an edge collapsed to a point) "
                             "is not supported");
  auto patch = cylinder_patch();
  patch.knots_u[4] = 0.1;
  write("knots.json", geomdl_json(patch));
  expect_reconstruct_refuses("knots.json", "NURBS surface: knots in u decrease at index 4 (0.25 then 0.1)");
  write("curve.json", R"({"shape": {"type": "curve", "data": []}})");
  expect_reconstruct_refuses("curve.json", "holds a NURBS curve, not a surface (shape.type must be \"surface\")");
  // The exact boundary comes with the patch: --boundary is for point files.
  write("cyl.json", geomdl_json(cylinder_patch()));
  const CommandResult r = run_envcrust("reconstruct " + path("cyl.json") + " --boundary " + path("cyl.json") +
                                       " -o " + path("x.ply"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "envcrust: usage error: --boundary applies to point files: " + path("cyl.json") +
                       " brings its exact boundary\n");
}

}  // namespace
}  // namespace envcrust::testing
