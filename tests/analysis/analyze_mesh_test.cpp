// The analyzer on the exact tessellation of every built-in surface must report the surface's
// known topology: chi, boundary loops, orientability, boundary knot types and linking.
#include "envcrust/analysis.h"
#include "envcrust/errors.h"
#include "envcrust/surfaces.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace envcrust;

class BuiltinTessellation : public ::testing::TestWithParam<std::string> {};

TEST_P(BuiltinTessellation, analyzer_reports_the_expected_topology) {
  const auto surface = surfaces::make_builtin(GetParam());
  const auto expected = surface->expected_topology();
  const auto mesh = surfaces::tessellate(*surface);
  const auto report = analysis::analyze_mesh(mesh);
  const auto& t = report.topology;
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.degenerate_faces, 0u);
  EXPECT_EQ(t.euler_characteristic, expected.euler_characteristic);
  EXPECT_EQ(static_cast<int>(t.boundary_loops.size()), expected.boundary_loops);
  EXPECT_EQ(t.is_orientable, expected.is_orientable);
  if (expected.is_orientable) {
    EXPECT_EQ(t.misoriented_edges, 0u);
  }
  ASSERT_EQ(report.loops.size(), expected.boundary_knots.size());
  for (std::size_t i = 0; i < report.loops.size(); ++i) {
    ASSERT_TRUE(report.loops[i].knot.has_value()) << "loop " << i;
    EXPECT_EQ(knots::to_string(report.loops[i].knot->type), expected.boundary_knots[i]) << "loop " << i;
  }
  if (expected.boundary_loops == 2) {
    ASSERT_EQ(report.linking.size(), 1u);
    EXPECT_EQ(std::abs(report.linking[0].linking_number), expected.abs_linking_number);
    EXPECT_TRUE(report.linking[0].is_signed);
  }
  EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
}

INSTANTIATE_TEST_SUITE_P(AllSurfaces, BuiltinTessellation,
                         ::testing::ValuesIn(surfaces::builtin_names()),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(Analysis, tessellation_matches_its_surface_and_boundary_within_tolerance) {
  const auto surface = surfaces::make_builtin("cylinder");
  analysis::Reference reference;
  reference.mesh = surfaces::tessellate(*surface);
  for (const auto& c : surfaces::boundary_curves(*surface, 0.01)) reference.boundary.push_back(c.polyline());
  const auto coarse = fixtures::open_cylinder(32, 4);
  analysis::AnalyzeOptions options;
  options.distance.samples = 20000;
  const auto report = analysis::analyze_mesh(coarse, reference, options);
  ASSERT_TRUE(report.distance.has_value());
  const double sagitta = 1 - std::cos(3.141592653589793 / 32);
  EXPECT_NEAR(report.distance->hausdorff, sagitta, 0.05 * sagitta);
  ASSERT_EQ(report.boundary_matches.size(), 2u);
  for (const auto& m : report.boundary_matches) {
    ASSERT_TRUE(m.mesh_loop.has_value());
    EXPECT_NEAR(m.hausdorff, sagitta, 0.05 * sagitta);
  }
  EXPECT_NE(*report.boundary_matches[0].mesh_loop, *report.boundary_matches[1].mesh_loop);
}

TEST(Analysis, capped_cylinder_has_no_boundary_to_match) {
  analysis::Reference reference;
  reference.boundary.push_back({{1, 0, 1}, {0, 1, 1}, {-1, 0, 1}});
  const auto report = analysis::analyze_mesh(fixtures::capped_cylinder(), reference);
  ASSERT_EQ(report.boundary_matches.size(), 1u);
  EXPECT_FALSE(report.boundary_matches[0].mesh_loop.has_value());
  EXPECT_TRUE(report.topology.is_closed());
}

TEST(Analysis, non_manifold_mesh_is_reported_in_warnings) {
  auto m = fixtures::square(2);
  m.vertices.push_back({0.25, 0, 1});
  m.triangles.push_back({0, 1, Index(m.vertices.size() - 1)});
  m.vertices.push_back({0.25, 0, -1});
  m.triangles.push_back({0, 1, Index(m.vertices.size() - 1)});
  const auto report = analysis::analyze_mesh(m);
  ASSERT_FALSE(report.warnings.empty());
  EXPECT_EQ(report.warnings[0], "1 non-manifold edges");
}

// The border of a mesh against the boundary curves it should have: the open cylinder's two
// rims follow the true circles; given one circle only, the other rim is a hole the curves do
// not have; capped, neither circle has a rim.
TEST(BoundaryCheck, names_the_curves_without_a_loop_and_the_loops_without_a_curve) {
  const auto surface = surfaces::make_builtin("cylinder");
  std::vector<Polyline> circles;
  for (const auto& c : surfaces::boundary_curves(*surface, 0.01)) circles.push_back(c.polyline());
  ASSERT_EQ(circles.size(), 2u);
  const auto open = analysis::analyze_mesh(fixtures::open_cylinder(32, 4)).topology;
  const double sagitta = 1 - std::cos(3.141592653589793 / 32);

  const auto both = analysis::check_boundary(open, circles, 2 * sagitta);
  EXPECT_TRUE(both.is_consistent());
  ASSERT_EQ(both.matches.size(), 2u);
  EXPECT_NE(*both.matches[0].mesh_loop, *both.matches[1].mesh_loop);
  // Below the facets' own sagitta no rim follows its circle.
  const auto strict = analysis::check_boundary(open, circles, 0.5 * sagitta);
  EXPECT_EQ(strict.missing_curves, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(strict.extra_loops.size(), 2u);

  const auto one = analysis::check_boundary(open, {circles[0]}, 2 * sagitta);
  EXPECT_TRUE(one.missing_curves.empty());
  ASSERT_EQ(one.extra_loops.size(), 1u);
  EXPECT_NE(one.extra_loops[0], *one.matches[0].mesh_loop);

  const auto capped = analysis::check_boundary(analysis::analyze_mesh(fixtures::capped_cylinder()).topology, circles, 0.1);
  EXPECT_EQ(capped.missing_curves, (std::vector<std::size_t>{0, 1}));
  EXPECT_TRUE(capped.extra_loops.empty());
  EXPECT_FALSE(capped.matches[0].mesh_loop.has_value());

  // Circles of length 2 pi closed by a reconstruction that cannot open holes shorter than 7
  // are unresolved, not missing; one that could open holes of length 6 missed them.
  const auto unresolved = analysis::check_boundary(analysis::analyze_mesh(fixtures::capped_cylinder()).topology,
                                                   circles, 0.1, 0.9, 7.0);
  EXPECT_TRUE(unresolved.missing_curves.empty());
  EXPECT_EQ(unresolved.unresolved_curves, (std::vector<std::size_t>{0, 1}));
  EXPECT_TRUE(unresolved.is_consistent());
  const auto resolvable = analysis::check_boundary(analysis::analyze_mesh(fixtures::capped_cylinder()).topology,
                                                   circles, 0.1, 0.9, 6.0);
  EXPECT_EQ(resolvable.missing_curves, (std::vector<std::size_t>{0, 1}));
  EXPECT_TRUE(resolvable.unresolved_curves.empty());
  // A curve with no vertex of the result near it was left out, not closed (the capped
  // cylinder closes its rims; a copy of one 10 away has nothing of the result near it).
  EXPECT_TRUE(unresolved.left_out_curves.empty());
  Polyline far = circles[0];
  for (Point3& p : far) p = p + Vector3(10, 0, 0);
  const auto away = analysis::check_boundary(analysis::analyze_mesh(fixtures::capped_cylinder()).topology,
                                             {circles[0], far}, 0.1, 0.9, 7.0);
  EXPECT_EQ(away.unresolved_curves, (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(away.left_out_curves, (std::vector<std::size_t>{1}));
  EXPECT_EQ(analysis::check_boundary(analysis::analyze_mesh(fixtures::capped_cylinder()).topology, {far}, 0.1)
                .left_out_curves,
            (std::vector<std::size_t>{0}));  // missing too when long enough to resolve
  // A curve that is followed is neither, however short.
  EXPECT_TRUE(analysis::check_boundary(open, circles, 2 * sagitta, 0.9, 7.0).unresolved_curves.empty());

  EXPECT_THROW(analysis::check_boundary(open, circles, 0.0), InvalidInput);
  EXPECT_THROW(analysis::check_boundary(open, circles, 0.1, 0.0), InvalidInput);
  EXPECT_THROW(analysis::check_boundary(open, circles, 0.1, 1.5), InvalidInput);
  EXPECT_THROW(analysis::check_boundary(open, circles, 0.1, 0.9, -1.0), InvalidInput);
}

// A ragged scan rim: one stretch of the curve (here 3 of its 628 vertices, pulled 0.05 out,
// five times the tolerance; 1.6% of its length) runs where no loop goes. The rim still
// follows it along 90% of both (the default), but not along all of it (the full Hausdorff
// distance, fraction 1).
TEST(BoundaryCheck, a_loop_follows_a_curve_with_a_notch_along_most_of_it) {
  const auto surface = surfaces::make_builtin("cylinder");
  std::vector<Polyline> circles;
  for (const auto& c : surfaces::boundary_curves(*surface, 0.01)) circles.push_back(c.polyline());
  for (std::size_t k = 100; k < 103; ++k) {
    const Point3& p = circles[0][k];
    circles[0][k] = Point3(1.05 * p.x(), 1.05 * p.y(), p.z());
  }
  const auto open = analysis::analyze_mesh(fixtures::open_cylinder(32, 4)).topology;
  const double tolerance = 2 * (1 - std::cos(3.141592653589793 / 32));
  const auto ragged = analysis::check_boundary(open, circles, tolerance);
  EXPECT_TRUE(ragged.is_consistent());
  EXPECT_GT(ragged.matches[0].hausdorff, 0.045);
  EXPECT_LT(ragged.follow_distances[0], tolerance);
  const auto full = analysis::check_boundary(open, circles, tolerance, 1.0);
  EXPECT_EQ(full.missing_curves, (std::vector<std::size_t>{0}));
  EXPECT_EQ(full.extra_loops.size(), 1u);
}
