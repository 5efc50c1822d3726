// Remeshing the extracted sheet keeps its topology, knots and distance to the true surface
// while cutting the faces and raising the smallest angle.
#include "envcrust/analysis.h"
#include "envcrust/errors.h"
#include "envcrust/extract.h"
#include "envcrust/remesh.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"
#include "fixtures/shapes.h"
#include "fixtures/surface_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>

using namespace envcrust;

namespace {

struct Sheet {
  TriangleMesh mesh;
  analysis::Reference reference;
};

Sheet sheet_of(const std::string& name, std::size_t n) {
  const auto samples = fixtures::builtin_samples(name, n);
  Sheet s;
  s.mesh = extract::extract_sheet(envelope::sample_envelope(samples), samples).mesh;
  s.reference.mesh = surfaces::tessellate(*surfaces::make_builtin(name));
  for (const auto& c : samples.boundary) s.reference.boundary.push_back(c.polyline());
  return s;
}

analysis::AnalysisReport analyze(const TriangleMesh& mesh, const analysis::Reference& reference) {
  analysis::AnalyzeOptions ao;
  ao.distance.samples = 20000;
  return analysis::analyze_mesh(mesh, reference, ao);
}

TriangleMesh grid(int n) { return fixtures::square(n); }  // [0,1]^2, right triangles

std::string invalid_options_message(const remesh::RemeshOptions& o) {
  try {
    (void)remesh::remesh(grid(2), o);
  } catch (const InvalidOptions& e) {
    return e.what();
  }
  return "no InvalidOptions thrown";
}

}  // namespace

struct Case {
  std::string surface;
  remesh::BoundaryMode boundary;
};

class RemeshSheet : public ::testing::TestWithParam<Case> {};

TEST_P(RemeshSheet, keeps_topology_knots_and_distance_with_fewer_better_triangles) {
  const auto sheet = sheet_of(GetParam().surface, 10000);
  remesh::RemeshOptions options;
  options.boundary = GetParam().boundary;
  const auto result = remesh::remesh(sheet.mesh, options);
  const auto before = analyze(sheet.mesh, sheet.reference);
  const auto after = analyze(result.mesh, sheet.reference);
  const auto& s = result.stats;
  auto rel = [](const analysis::AnalysisReport& r, double d) { return 100 * r.distance->relative(d); };
  std::printf("%s %s: faces %zu -> %zu, target %.4f, min angle %.2f -> %.2f deg, H %.3f%% -> %.3f%% "
              "(m->r %.3f%% -> %.3f%%), %.2f s\n",
              GetParam().surface.c_str(), options.boundary == remesh::BoundaryMode::Keep ? "keep" : "resample",
              s.faces_before, s.faces_after, s.target_edge_length, s.min_angle_deg_before, s.min_angle_deg_after,
              rel(before, before.distance->hausdorff), rel(after, after.distance->hausdorff),
              rel(before, before.distance->mesh_to_reference.max), rel(after, after.distance->mesh_to_reference.max),
              s.seconds);
  for (const auto& w : result.warnings) std::printf("  warning: %s\n", w.c_str());
  ASSERT_TRUE(s.is_remeshed);
  EXPECT_TRUE(result.warnings.empty());
  const auto& t = after.topology;
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.welded_vertices, 0u);  // no two vertices at one position (a Moebius seam is welded)
  EXPECT_EQ(t.components.size(), before.topology.components.size());
  EXPECT_EQ(t.euler_characteristic, before.topology.euler_characteristic);
  EXPECT_EQ(t.boundary_loops.size(), before.topology.boundary_loops.size());
  EXPECT_EQ(t.is_orientable, before.topology.is_orientable);
  ASSERT_EQ(after.loops.size(), before.loops.size());
  for (std::size_t i = 0; i < after.loops.size(); ++i) {
    ASSERT_TRUE(after.loops[i].knot.has_value());
    ASSERT_TRUE(before.loops[i].knot.has_value());
    EXPECT_EQ(knots::to_string(after.loops[i].knot->type), knots::to_string(before.loops[i].knot->type));
  }
  EXPECT_EQ(s.faces_after, result.mesh.triangles.size());
  EXPECT_LT(3 * s.faces_after, s.faces_before);
  // Keep mode leaves thin ears along the protected border (three consecutive border
  // vertices; measured on the hemisphere: about 200 triangles under 5 degrees).
  // Resample: measured +4.7 degrees on the cylinder (its smallest angles sit at the border,
  // whose vertices do not move) to +28 on the torus.
  if (options.boundary == remesh::BoundaryMode::Resample) {
    EXPECT_GT(s.min_angle_deg_after, s.min_angle_deg_before + 3.0);
  }
  // The extraction test's bars: 0.5% of the diagonal both ways, 1% per boundary loop.
  EXPECT_LT(after.distance->relative(after.distance->mesh_to_reference.max), 0.005);
  EXPECT_LT(after.distance->relative(after.distance->reference_to_mesh.max), 0.005);
  for (const auto& m : after.boundary_matches) {
    ASSERT_TRUE(m.mesh_loop.has_value());
    EXPECT_LT(after.distance->relative(m.hausdorff), 0.01);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Surfaces, RemeshSheet,
    ::testing::Values(Case{"trefoil-ribbon", remesh::BoundaryMode::Resample},
                      Case{"cylinder", remesh::BoundaryMode::Resample},
                      Case{"torus", remesh::BoundaryMode::Resample},
                      Case{"hemisphere", remesh::BoundaryMode::Keep},
                      Case{"moebius", remesh::BoundaryMode::Resample},
                      Case{"moebius", remesh::BoundaryMode::Keep}),
    [](const auto& info) {
      std::string name = info.param.surface;
      std::replace(name.begin(), name.end(), '-', '_');
      return name + (info.param.boundary == remesh::BoundaryMode::Keep ? "_keep" : "_resample");
    });

TEST(Remesh, keep_mode_keeps_every_border_vertex) {
  const TriangleMesh input = grid(20);
  remesh::RemeshOptions options;
  options.boundary = remesh::BoundaryMode::Keep;
  options.target_edge_length = 0.12;
  const auto result = remesh::remesh(input, options);
  ASSERT_TRUE(result.stats.is_remeshed);
  const std::set<Point3> output(result.mesh.vertices.begin(), result.mesh.vertices.end());
  for (const auto& p : input.vertices) {
    const bool on_border = p.x() == 0 || p.x() == 1 || p.y() == 0 || p.y() == 1;
    if (on_border) {
      EXPECT_TRUE(output.count(p)) << p;
    }
  }
  EXPECT_LT(result.stats.faces_after, result.stats.faces_before);
}

TEST(Remesh, resample_mode_keeps_the_border_on_the_input_border) {
  const auto result = remesh::remesh(grid(20), remesh::RemeshOptions{0.12});
  ASSERT_TRUE(result.stats.is_remeshed);
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_EQ(t.euler_characteristic, 1);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  for (const Index v : t.boundary_loops[0].vertices) {
    const Point3& p = t.points[v];
    const double to_border = std::min({std::abs(p.x()), std::abs(1 - p.x()), std::abs(p.y()), std::abs(1 - p.y())});
    EXPECT_LT(to_border, 1e-12) << p;
  }
  EXPECT_NEAR(result.stats.target_edge_length, 0.12, 0.0);
  EXPECT_LT(3 * result.stats.faces_after, result.stats.faces_before);
  EXPECT_GT(result.stats.min_angle_deg_after, 15.0);  // from a perfect grid (45): no sliver (measured 19.0)
}

TEST(Remesh, default_target_is_a_multiple_of_the_median_edge) {
  const auto result = remesh::remesh(grid(20));  // median edge: the grid step 0.05
  EXPECT_NEAR(result.stats.target_edge_length, 3.0 * 0.05, 1e-12);
}

// A non-orientable band is cut open along its orientation seam, remeshed with the seam held
// fixed and welded back: one surface again, no doubled vertex, no extra border.
TEST(Remesh, remeshes_a_moebius_band_through_its_seam) {
  for (const auto mode : {remesh::BoundaryMode::Resample, remesh::BoundaryMode::Keep}) {
    const TriangleMesh band = fixtures::moebius(120, 12);  // edges 0.05 to 0.08
    remesh::RemeshOptions options;
    options.target_edge_length = 0.12;
    options.boundary = mode;
    const auto result = remesh::remesh(band, options);
    ASSERT_TRUE(result.stats.is_remeshed) << (result.warnings.empty() ? "" : result.warnings[0]);
    EXPECT_TRUE(result.warnings.empty());
    EXPECT_LT(2 * result.stats.faces_after, result.stats.faces_before);
    topology::TopologyOptions as_indexed;
    as_indexed.weld_identical_vertices = false;
    for (const auto& t : {topology::analyze_topology(result.mesh), topology::analyze_topology(result.mesh, as_indexed)}) {
      EXPECT_EQ(t.welded_vertices, 0u);
      EXPECT_EQ(t.euler_characteristic, 0);
      EXPECT_EQ(t.components.size(), 1u);
      EXPECT_EQ(t.boundary_loops.size(), 1u);
      EXPECT_FALSE(t.is_orientable);
      EXPECT_TRUE(t.is_manifold());
      EXPECT_EQ(t.degenerate_faces, 0u);
    }
    // Every output vertex stays on the band (projection onto the input).
    for (const auto& p : result.mesh.vertices) {
      const double r = std::hypot(p.x(), p.y());
      EXPECT_LT(std::abs(r - 1.0), 0.41) << p;
      EXPECT_LT(std::abs(p.z()), 0.41) << p;
    }
  }
}

TEST(Remesh, skips_a_non_manifold_mesh_with_a_warning) {
  TriangleMesh fin;  // three triangles on one edge
  fin.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  fin.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const auto result = remesh::remesh(fin);
  EXPECT_FALSE(result.stats.is_remeshed);
  EXPECT_EQ(result.warnings, std::vector<std::string>{
                                 "remeshing skipped: the mesh is not a manifold (1 non-manifold edges, 0 "
                                 "non-manifold vertices)"});
}

// A target so small that the faces would outgrow the memory is skipped before any work: the
// unit square at edge 1e-4 would take about 2.3e8 triangles.
TEST(Remesh, skips_a_target_that_would_make_too_many_faces) {
  remesh::RemeshOptions options;
  options.target_edge_length = 1e-4;
  const auto result = remesh::remesh(grid(10), options);
  EXPECT_FALSE(result.stats.is_remeshed);
  EXPECT_EQ(result.mesh.triangles.size(), grid(10).triangles.size());
  EXPECT_EQ(result.warnings, std::vector<std::string>{
                                 "remeshing skipped: a target edge of 0.0001 would make about 2.3e+08 faces, more "
                                 "than 1e+06 (4 times the mesh's 200, at least 1M)"});
  // At 0.01, about 12,000 faces, it runs.
  options.target_edge_length = 0.01;
  EXPECT_TRUE(remesh::remesh(grid(10), options).stats.is_remeshed);
}

TEST(Remesh, bad_options_give_exact_messages) {
  remesh::RemeshOptions o;
  o.target_edge_length = -1.0;
  EXPECT_EQ(invalid_options_message(o), "RemeshOptions::target_edge_length must be positive (got -1)");
  o = {};
  o.target_edge_length = std::numeric_limits<double>::infinity();
  EXPECT_EQ(invalid_options_message(o), "RemeshOptions::target_edge_length must be positive (got inf)");
  o = {};
  o.edge_length_rel_median = 0.0;
  EXPECT_EQ(invalid_options_message(o), "RemeshOptions::edge_length_rel_median must be positive (got 0)");
  o = {};
  o.iterations = 0;
  EXPECT_EQ(invalid_options_message(o), "RemeshOptions::iterations must be in 1..100 (got 0)");
  o = {};
  o.max_face_growth = 0.5;
  EXPECT_EQ(invalid_options_message(o), "RemeshOptions::max_face_growth must be >= 1 (got 0.5)");
}

TEST(Remesh, bad_face_index_is_invalid_input) {
  TriangleMesh m = grid(1);
  m.triangles[0][2] = 9;
  EXPECT_THROW((void)remesh::remesh(m), InvalidInput);
}

TEST(MinAngle, of_a_right_isosceles_triangle_is_45_degrees) {
  EXPECT_NEAR(remesh::min_angle_deg(grid(1)), 45.0, 1e-9);
  EXPECT_EQ(remesh::min_angle_deg(TriangleMesh{}), 0.0);
}
