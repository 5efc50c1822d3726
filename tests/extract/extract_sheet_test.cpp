// The medial sheet of the envelope of exact samples reproduces each surface's topology and
// geometry.
#include "envcrust/analysis.h"
#include "envcrust/errors.h"
#include "envcrust/extract.h"
#include "envcrust/mesh.h"
#include "envcrust/topology.h"
#include "envcrust/surfaces.h"
#include "fixtures/surface_samples.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

using namespace envcrust;

namespace {

struct Case {
  std::string surface;
  std::size_t points;
};

envelope::SurfaceSamples exact_samples(const surfaces::Surface& surface, std::size_t n) {
  return fixtures::builtin_samples(surface.name(), n);
}

// The sheet's analysis against the exact tessellation and the samples' boundary curves.
analysis::AnalysisReport analyze_against_truth(const TriangleMesh& mesh, const surfaces::Surface& surface,
                                               const envelope::SurfaceSamples& samples) {
  analysis::Reference reference;
  reference.mesh = surfaces::tessellate(surface);
  for (const auto& c : samples.boundary) reference.boundary.push_back(c.polyline());
  analysis::AnalyzeOptions options;
  options.distance.samples = 20000;
  return analysis::analyze_mesh(mesh, reference, options);
}

}  // namespace

class SheetOfBuiltin : public ::testing::TestWithParam<Case> {};

TEST_P(SheetOfBuiltin, has_the_surface_topology_and_stays_close) {
  const auto surface = surfaces::make_builtin(GetParam().surface);
  const auto samples = exact_samples(*surface, GetParam().points);
  const auto env = envelope::sample_envelope(samples);
  const auto sheet = extract::extract_sheet(env, samples);
  const auto report = analyze_against_truth(sheet.mesh, *surface, samples);
  const auto expected = surface->expected_topology();
  const auto& t = report.topology;
  std::printf("%s: rho %.4f h %.4f env %zu | V %zu F %zu chi %ld loops %zu orient %d nm %zu/%zu | "
              "H %.3f%% (m->r %.3f%%, r->m %.3f%%) | split %zu filled %zu dropped %zu nmf %zu proj %zu/%zu\n",
              GetParam().surface.c_str(), env.rho, env.spacing, env.samples.size(), t.vertices, t.faces,
              t.euler_characteristic, t.boundary_loops.size(), t.is_orientable, t.non_manifold_edges,
              t.non_manifold_vertices, 100 * report.distance->relative(report.distance->hausdorff),
              100 * report.distance->relative(report.distance->mesh_to_reference.max),
              100 * report.distance->relative(report.distance->reference_to_mesh.max),
              sheet.stats.vertices_split, sheet.stats.holes_filled, sheet.stats.components_dropped,
              sheet.stats.non_manifold_faces_removed, sheet.stats.vertices_projected,
              sheet.stats.projections_refused);
  for (const auto& m : report.boundary_matches)
    std::printf("   boundary %zu: %.3f%%\n", m.reference_loop, 100 * report.distance->relative(m.hausdorff));
  EXPECT_TRUE(t.is_manifold());
  ASSERT_TRUE(report.self_intersections.has_value());
  EXPECT_EQ(report.self_intersections->face_pairs, 0u);  // an embedded surface
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, expected.euler_characteristic);
  EXPECT_EQ(static_cast<int>(t.boundary_loops.size()), expected.boundary_loops);
  EXPECT_EQ(t.is_orientable, expected.is_orientable);
  if (t.is_orientable) {
    EXPECT_EQ(t.misoriented_edges, 0u);  // wound consistently, not just orientable
  }
  ASSERT_EQ(report.loops.size(), expected.boundary_knots.size());
  for (std::size_t i = 0; i < report.loops.size(); ++i) {
    ASSERT_TRUE(report.loops[i].knot.has_value());
    EXPECT_EQ(knots::to_string(report.loops[i].knot->type), expected.boundary_knots[i]);
  }
  // Mesh to truth within 0.5% of the diagonal everywhere; truth to mesh too (these samples
  // carry their exact boundary curves, so the boundary is not limited by the sampling).
  EXPECT_LT(report.distance->relative(report.distance->mesh_to_reference.max), 0.005);
  EXPECT_LT(report.distance->relative(report.distance->reference_to_mesh.max), 0.005);
  for (const auto& m : report.boundary_matches) {
    ASSERT_TRUE(m.mesh_loop.has_value());
    EXPECT_LT(report.distance->relative(m.hausdorff), 0.01);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Surfaces, SheetOfBuiltin,
    ::testing::Values(Case{"cylinder", 10000}, Case{"moebius", 10000}, Case{"trefoil-ribbon", 10000},
                      Case{"hemisphere", 10000}, Case{"square", 10000}, Case{"sphere", 10000},
                      Case{"torus", 10000}, Case{"unknot-ribbon", 10000}, Case{"paraboloid", 10000},
                      Case{"saddle", 10000}, Case{"horn", 10000}, Case{"cylinder-nurbs", 10000}),
    [](const auto& info) {
      std::string name = info.param.surface;
      std::replace(name.begin(), name.end(), '-', '_');
      return name;
    });

// issue 5: noisy samples made cells with identical vertices (zero-length Voronoi edges) and
// trim cuts through a vertex's rounding; the trefoil ribbon at 0.25% noise had 58 pairs of
// coincident vertices bounding zero-area faces, which made its boundary loops touch.
TEST(SheetOfNoisySamples, issue_5_has_no_coincident_vertices_or_zero_area_faces) {
  std::printf("seed 3\n");
  const auto samples = fixtures::builtin_samples("trefoil-ribbon", 10000, 0.0025, 3);
  const auto env = envelope::sample_envelope(samples);
  const auto sheet = extract::extract_sheet(env, samples);
  const auto report = analysis::analyze_mesh(sheet.mesh);
  const auto& t = report.topology;
  std::printf("rho %.4f env %zu V %zu F %zu chi %ld comps %zu loops %zu filled %zu dropped %zu\n", env.rho,
              env.samples.size(), t.vertices, t.faces, t.euler_characteristic, t.components.size(),
              t.boundary_loops.size(), sheet.stats.holes_filled, sheet.stats.components_dropped);
  EXPECT_EQ(t.degenerate_faces, 0u);
  std::vector<Point3> positions = sheet.mesh.vertices;
  std::sort(positions.begin(), positions.end());
  EXPECT_EQ(std::adjacent_find(positions.begin(), positions.end()), positions.end());
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.euler_characteristic, 0);
  ASSERT_EQ(report.loops.size(), 2u);
  for (const auto& loop : report.loops) {
    ASSERT_TRUE(loop.knot.has_value());
    EXPECT_EQ(knots::to_string(loop.knot->type), "trefoil");
  }
}

// The same input gives the same sheet, in a second call of one process and on one thread
// (CGAL's range insertion shuffles with a process-wide generator; the extraction inserts
// along a Hilbert curve instead).
TEST(SheetOfBuiltin, is_the_same_on_a_second_call_and_on_one_thread) {
  const auto surface = surfaces::make_builtin("moebius");
  const auto samples = exact_samples(*surface, 3000);
  const auto env = envelope::sample_envelope(samples);
  const auto first = extract::extract_sheet(env, samples);
  const auto second = extract::extract_sheet(env, samples);
  EXPECT_EQ(first.mesh.vertices, second.mesh.vertices);
  EXPECT_EQ(first.mesh.triangles, second.mesh.triangles);
  tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  const auto serial = extract::extract_sheet(env, samples);
  EXPECT_EQ(first.mesh.vertices, serial.mesh.vertices);
  EXPECT_EQ(first.mesh.triangles, serial.mesh.triangles);
}

// issue 5: on the cylinder's planar rims the trimmed border stepped backwards along the
// curve and, lying in the rim plane, crossed itself: the analyzer found no generic
// projection and left the loop's knot type unknown (noisy 10k samples, seed 3).
TEST(SheetOfNoisySamples, issue_5_cylinder_rims_do_not_cross_themselves) {
  std::printf("seed 3\n");
  const auto samples = fixtures::builtin_samples("cylinder", 10000, 0.0025, 3);
  envelope::EnvelopeOptions eo;
  eo.seed = 3;
  const auto sheet = extract::extract_sheet(envelope::sample_envelope(samples, eo), samples);
  const auto report = analysis::analyze_mesh(sheet.mesh);
  EXPECT_EQ(report.topology.euler_characteristic, 0);
  ASSERT_EQ(report.loops.size(), 2u);
  for (const auto& loop : report.loops) {
    ASSERT_TRUE(loop.knot.has_value()) << "a boundary loop could not be typed";
    EXPECT_EQ(knots::to_string(loop.knot->type), "unknot");
  }
}

// issue 5 quality bar: from 10k samples with Gaussian noise of 0.25% of the diagonal the
// sheet keeps the topology and stays within 0.5% of the surface. With tangent planes
// weighted by inverse distance and folds judged in 3D (faces of the rough sheet refused the
// projection), mesh to truth was 0.60% (horn) and 0.56% (unknot ribbon; a border vertex
// whose snap folded a face kept its noisy height).
class SheetOfNoisyBuiltin : public ::testing::TestWithParam<std::string> {};

TEST_P(SheetOfNoisyBuiltin, issue_5_stays_within_half_a_percent_of_the_surface) {
  const auto surface = surfaces::make_builtin(GetParam());
  const auto samples = fixtures::builtin_samples(GetParam(), 10000, 0.0025, 3);
  envelope::EnvelopeOptions eo;
  eo.seed = 3;
  const auto env = envelope::sample_envelope(samples, eo);
  const auto sheet = extract::extract_sheet(env, samples);
  const auto report = analyze_against_truth(sheet.mesh, *surface, samples);
  const auto& t = report.topology;
  const auto expected = surface->expected_topology();
  const double mesh_to_truth = report.distance->relative(report.distance->mesh_to_reference.max);
  const double truth_to_mesh = report.distance->relative(report.distance->reference_to_mesh.max);
  std::printf("%s: rho %.4f noise %.4f chi %ld loops %zu | m->r %.3f%% r->m %.3f%% | proj %zu/%zu\n",
              GetParam().c_str(), env.rho, env.noise, t.euler_characteristic, t.boundary_loops.size(),
              100 * mesh_to_truth, 100 * truth_to_mesh, sheet.stats.vertices_projected,
              sheet.stats.projections_refused);
  EXPECT_TRUE(t.is_manifold());
  ASSERT_TRUE(report.self_intersections.has_value());
  EXPECT_EQ(report.self_intersections->face_pairs, 0u);  // an embedded surface
  // The sheet's own count (first check, re-checks of what moved or was made) agrees with the
  // analyzer's check of the whole result.
  EXPECT_EQ(sheet.stats.self_intersections_left, report.self_intersections->face_pairs);
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, expected.euler_characteristic);
  EXPECT_EQ(static_cast<int>(t.boundary_loops.size()), expected.boundary_loops);
  EXPECT_EQ(t.is_orientable, expected.is_orientable);
  ASSERT_EQ(report.loops.size(), expected.boundary_knots.size());
  for (std::size_t i = 0; i < report.loops.size(); ++i) {
    ASSERT_TRUE(report.loops[i].knot.has_value());
    EXPECT_EQ(knots::to_string(report.loops[i].knot->type), expected.boundary_knots[i]);
  }
  EXPECT_LT(mesh_to_truth, 0.005);
  EXPECT_LT(truth_to_mesh, 0.005);
}

INSTANTIATE_TEST_SUITE_P(Surfaces, SheetOfNoisyBuiltin, ::testing::Values("horn", "unknot-ribbon"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// issue 5: the face scan as a mesh (automatic rho 0.51, about one sample spacing) kept one
// small disc: the component filter took a piece for the outer medial axis when its median
// vertex lay farther than 0.5 rho from the nearest sample, but a point of M itself lies up to
// a sample spacing from one (59% of the face did at 0.51). A grid of spacing a on the square
// with rho = 0.65 a has the same ratio: the envelope bridges the grid's gaps (2.5 rho >
// a sqrt 2), while half of M lies farther than 0.5 rho from every sample (median 0.38 a).
TEST(SheetOfSparseSamples, issue_5_keeps_the_sheet_where_rho_is_near_the_sample_spacing) {
  const auto square = surfaces::make_builtin("square");
  const double a = 0.1;
  envelope::SurfaceSamples samples;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) {
      samples.points.emplace_back(-1.0 + a * i, -1.0 + a * j, 0.0);
      samples.normals.emplace_back(0.0, 0.0, 1.0);
    }
  samples.boundary = surfaces::boundary_curves(*square, a);
  envelope::EnvelopeOptions envelope_options;
  envelope_options.rho = 0.65 * a;
  const auto env = envelope::sample_envelope(samples, envelope_options);

  const auto sheet = extract::extract_sheet(env, samples);
  const auto t = topology::analyze_topology(sheet.mesh);
  std::printf("faces %zu area %.3f chi %ld loops %zu dropped %zu\n", t.faces, mesh::total_area(sheet.mesh),
              t.euler_characteristic, t.boundary_loops.size(), sheet.stats.components_dropped);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_NEAR(mesh::total_area(sheet.mesh), 4.0, 0.2);

  // The filter by rho alone (the old rule) loses most of it.
  extract::SheetOptions rho_only;
  rho_only.max_component_distance_rel_spacing = 0.0;
  const auto lost = extract::extract_sheet(env, samples, rho_only);
  std::printf("rho alone: area %.3f\n", mesh::total_area(lost.mesh));
  EXPECT_LT(mesh::total_area(lost.mesh), 2.0);
}

// SheetOptions::cut_to_orientable: the Moebius strip loses a band across its seam and comes
// out a disc close to the surface; an orientable sheet comes out exactly as without it.
TEST(SheetCutToOrientable, turns_the_moebius_strip_into_a_disc) {
  const auto surface = surfaces::make_builtin("moebius");
  const auto samples = exact_samples(*surface, 10000);
  const auto env = envelope::sample_envelope(samples);
  extract::SheetOptions options;
  options.cut_to_orientable = true;
  const auto cut = extract::extract_sheet(env, samples, options);
  const auto whole = extract::extract_sheet(env, samples);
  const auto t = topology::analyze_topology(cut.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops.size(), 1u);
  EXPECT_TRUE(t.is_orientable);
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(cut.stats.orientation_seams, 1u);
  // A band about 2 rho wide across a strip whose midline is 2 pi long.
  const double kept = mesh::total_area(cut.mesh) / mesh::total_area(whole.mesh);
  EXPECT_LT(kept, 1.0 - 0.5 * env.rho / (2 * 3.141592653589793));
  EXPECT_GT(kept, 1.0 - 4.0 * env.rho / (2 * 3.141592653589793));
  const auto report = analyze_against_truth(cut.mesh, *surface, samples);
  EXPECT_LT(report.distance->relative(report.distance->mesh_to_reference.max), 0.005);
}

// ... and so does cut_handles_rel_rho: every ball of 2.4 rho on the trefoil ribbon's sheet is
// a disc or a half-disc.
TEST(SheetCutToOrientable, leaves_an_orientable_sheet_as_it_was) {
  const auto samples = exact_samples(*surfaces::make_builtin("trefoil-ribbon"), 10000);
  const auto env = envelope::sample_envelope(samples);
  extract::SheetOptions options;
  options.cut_to_orientable = true;
  options.cut_handles_rel_rho = 2.4;
  const auto cut = extract::extract_sheet(env, samples, options);
  const auto whole = extract::extract_sheet(env, samples);
  EXPECT_EQ(cut.stats.orientation_seams, 0u);
  EXPECT_EQ(cut.stats.faces_removed_at_seams, 0u);
  EXPECT_EQ(cut.stats.handle_balls, 0u);
  EXPECT_EQ(cut.stats.faces_removed_at_handles, 0u);
  EXPECT_EQ(cut.mesh.triangles, whole.mesh.triangles);
  EXPECT_EQ(cut.mesh.vertices, whole.mesh.vertices);
  EXPECT_TRUE(cut.warnings.empty());
}

TEST(SheetCutToOrientable, refuses_a_non_positive_band) {
  const auto samples = exact_samples(*surfaces::make_builtin("moebius"), 2000);
  const auto env = envelope::sample_envelope(samples);
  extract::SheetOptions options;
  options.cut_to_orientable = true;
  options.orientable_cut_rel_rho = 0;
  try {
    extract::extract_sheet(env, samples, options);
    FAIL() << "expected InvalidOptions";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "SheetOptions::orientable_cut_rel_rho out of range (got 0)");
  }
}

// Fold pairs (SheetOptions::fold_min_angle_deg) are for sharp creases: on smooth surfaces
// with their rims, no pair of samples whose directions make 60-100 degrees has a segment
// through M, and the result is the same; the angle must stay below min_angle_deg.
TEST(SheetFoldPairs, leave_smooth_surfaces_with_rims_as_they_were) {
  for (const std::string name : {"cylinder", "square", "moebius"}) {
    SCOPED_TRACE(name);
    const auto samples = exact_samples(*surfaces::make_builtin(name), 3000);
    const auto env = envelope::sample_envelope(samples);
    extract::SheetOptions folds;
    folds.fold_min_angle_deg = 60;
    const auto with = extract::extract_sheet(env, samples, folds);
    const auto without = extract::extract_sheet(env, samples);
    EXPECT_EQ(with.stats.crossing_edges, without.stats.crossing_edges);
    EXPECT_EQ(with.mesh.triangles, without.mesh.triangles);
  }
  const auto samples = exact_samples(*surfaces::make_builtin("cylinder"), 2000);
  const auto env = envelope::sample_envelope(samples);
  extract::SheetOptions options;
  options.fold_min_angle_deg = 100;
  try {
    extract::extract_sheet(env, samples, options);
    FAIL() << "expected InvalidOptions";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "SheetOptions::fold_min_angle_deg out of range (got 100)");
  }
}

// The progress callback hears every step, in order, as it begins, with the share of the
// stage done before it rising from 0.
TEST(SheetProgress, announces_each_step_in_order) {
  const auto samples = exact_samples(*surfaces::make_builtin("cylinder"), 5000);
  const auto env = envelope::sample_envelope(samples);
  std::vector<std::pair<std::string, double>> heard;
  Progress progress;
  progress.callback = [&](std::string_view stage, double fraction) { heard.emplace_back(stage, fraction); };
  const auto sheet = extract::extract_sheet(env, samples, {}, progress);
  EXPECT_FALSE(sheet.mesh.triangles.empty());
  const std::vector<std::string> steps = {"sheet: Voronoi polygons", "sheet: cleaning",      "sheet: projection",
                                          "sheet: manifold check",   "sheet: orientation cut", "sheet: handle cut",
                                          "sheet: self-intersections"};
  ASSERT_EQ(heard.size(), steps.size());
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_EQ(heard[k].first, steps[k]);
    if (k > 0) {
      EXPECT_GT(heard[k].second, heard[k - 1].second);
    }
    EXPECT_LT(heard[k].second, 1.0);
  }
  EXPECT_EQ(heard.front().second, 0.0);
}
