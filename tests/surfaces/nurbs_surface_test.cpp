// NURBS patches as surfaces: the exact jet, the edges found glued or collapsed, the expected
// topology, and the patches refused.
#include "envcrust/nurbs_surface.h"

#include "envcrust/errors.h"
#include "fixtures/nurbs_patches.h"
#include "mesh_topology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace envcrust::surfaces {
namespace {

using envcrust::testing::bezier_patch;
using envcrust::testing::cylinder_patch;
using envcrust::testing::moebius_patch;
using envcrust::testing::sphere_patch;
using envcrust::testing::transposed;

double distance(const Vector3& a, const Vector3& b) { return std::sqrt((a - b).squared_length()); }

std::string refusal(NurbsPatch patch) {
  try {
    (void)make_nurbs_surface(std::move(patch), "p");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "accepted";
}

TEST(NurbsSurface, the_cylinder_patch_has_the_jet_of_the_builtin_nurbs_cylinder) {
  const auto patch = make_nurbs_surface(cylinder_patch(), "cyl");
  const auto builtin = make_builtin("cylinder-nurbs");
  const ParameterDomain d = patch->domain();
  EXPECT_EQ(d.u_gluing, Gluing::Periodic);
  EXPECT_EQ(d.v_gluing, Gluing::None);
  EXPECT_FALSE(d.v0_is_pole || d.v1_is_pole);
  for (double u : {0.0, 0.1, 0.25, 0.37, 0.8, 1.0}) {
    for (double v : {-1.0, -0.3, 0.6, 1.0}) {
      const SurfaceJet a = patch->evaluate(u, v), b = builtin->evaluate(u, v);
      EXPECT_LT(std::sqrt(CGAL::squared_distance(a.position, b.position)), 1e-14);
      EXPECT_LT(distance(a.du, b.du), 1e-12);
      EXPECT_LT(distance(a.dv, b.dv), 1e-12);
      EXPECT_LT(distance(a.duu, b.duu), 1e-10);
      EXPECT_LT(distance(a.duv, b.duv), 1e-12);
      EXPECT_LT(distance(a.dvv, b.dvv), 1e-12);
    }
  }
  const ExpectedTopology t = patch->expected_topology();
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_loops, 2);
  EXPECT_TRUE(t.is_orientable);
  EXPECT_EQ(t.boundary_knots, (std::vector<std::string>{"unknot", "unknot"}));
  EXPECT_EQ(t.abs_linking_number, 0);
}

TEST(NurbsSurface, a_seam_is_glued_within_1e_5_of_the_diagonal_and_a_slit_is_not) {
  // The cylinder's control net has a diagonal of 2 sqrt(3) = 3.46; its last column repeats
  // the first. Moved out by 1e-5 (3e-6 of the diagonal, a seam written with 6 digits) it is
  // still one seam; moved out by 0.01 the patch is a slit tube: a disc with one loop.
  for (const auto& [shift, glued] : {std::pair{1e-5, true}, std::pair{1e-2, false}}) {
    auto p = cylinder_patch();
    for (std::size_t j = 0; j < 2; ++j) {
      Point3& q = p.control_points[8 + 9 * j];
      q = Point3(q.x() + shift, q.y(), q.z());
    }
    const auto s = make_nurbs_surface(p, "c");
    EXPECT_EQ(s->domain().u_gluing, glued ? Gluing::Periodic : Gluing::None) << shift;
    EXPECT_EQ(s->expected_topology().euler_characteristic, glued ? 0 : 1) << shift;
    EXPECT_EQ(s->expected_topology().boundary_loops, glued ? 2 : 1) << shift;
  }
}

TEST(NurbsSurface, a_rational_jet_matches_central_differences) {
  const auto s = make_nurbs_surface(
      bezier_patch({0, 0.5, -0.2, 0, 0.3, 1.2, 0.8, -0.4, 0.1, -0.9, 1.5, 0.2, 0, 0.4, -0.3, 0},
                   {1, 2, 0.5, 1, 1.5, 0.7, 3, 1, 1, 2.5, 0.6, 1.2, 1, 0.8, 1.4, 1}),
      "bump");
  const double h = 1e-5;
  for (double u : {0.2, 0.5, 0.77}) {
    for (double v : {0.15, 0.45, 0.9}) {
      const SurfaceJet j = s->evaluate(u, v);
      const auto at = [&](double du, double dv) { return s->evaluate(u + du, v + dv).position; };
      EXPECT_LT(distance(j.du, (at(h, 0) - at(-h, 0)) / (2 * h)), 1e-6);
      EXPECT_LT(distance(j.dv, (at(0, h) - at(0, -h)) / (2 * h)), 1e-6);
      const auto ju = [&](double du, double dv) { return s->evaluate(u + du, v + dv).du; };
      const auto jv = [&](double du, double dv) { return s->evaluate(u + du, v + dv).dv; };
      EXPECT_LT(distance(j.duu, (ju(h, 0) - ju(-h, 0)) / (2 * h)), 1e-5);
      EXPECT_LT(distance(j.duv, (ju(0, h) - ju(0, -h)) / (2 * h)), 1e-5);
      EXPECT_LT(distance(j.duv, (jv(h, 0) - jv(-h, 0)) / (2 * h)), 1e-5);
      EXPECT_LT(distance(j.dvv, (jv(0, h) - jv(0, -h)) / (2 * h)), 1e-5);
    }
  }
}

TEST(NurbsSurface, a_polynomial_bezier_patch_interpolates_its_corners_and_is_a_disc) {
  const auto s = make_nurbs_surface(bezier_patch({0.5, 0, 0, 0.25, 0, 1, 1, 0, 0, 1, 1, 0, -0.5, 0, 0, 0.75},
                                                 {1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}),
                                    "bump");
  EXPECT_LT(std::sqrt(CGAL::squared_distance(s->evaluate(0, 0).position, Point3(0, 0, 0.5))), 1e-15);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(s->evaluate(1, 1).position, Point3(3, 3, 0.75))), 1e-15);
  // The centre by de Casteljau's weights (1 3 3 1) / 8 in each direction: z = 9/64 * 4 of
  // the four inner heights 1, plus the corners' and edges' shares.
  double z = 0;
  const double b[4] = {1.0 / 8, 3.0 / 8, 3.0 / 8, 1.0 / 8};
  const double heights[16] = {0.5, 0, 0, 0.25, 0, 1, 1, 0, 0, 1, 1, 0, -0.5, 0, 0, 0.75};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) z += b[i] * b[j] * heights[i + 4 * j];
  EXPECT_NEAR(s->evaluate(0.5, 0.5).position.z(), z, 1e-15);
  const ExpectedTopology t = s->expected_topology();
  EXPECT_EQ(t.euler_characteristic, 1);
  EXPECT_EQ(t.boundary_loops, 1);
  const auto mesh = testing::mesh_topology(tessellate(*s));
  EXPECT_EQ(mesh.euler_characteristic, 1);
  EXPECT_EQ(mesh.boundary_loops, 1u);
}

TEST(NurbsSurface, the_sphere_patch_has_two_poles_and_unit_curvature) {
  const auto s = make_nurbs_surface(sphere_patch(), "sphere");
  const ParameterDomain d = s->domain();
  EXPECT_EQ(d.u_gluing, Gluing::Periodic);
  EXPECT_TRUE(d.v0_is_pole && d.v1_is_pole);
  for (double u : {0.05, 0.4, 0.9}) {
    for (double v : {0.0, 0.2, 0.5, 0.85, 1.0}) {
      const SurfacePoint p = s->point_at(u, v);
      EXPECT_NEAR(std::sqrt(CGAL::squared_distance(p.position, Point3(0, 0, 0))), 1.0, 1e-14);
      // At a pole the curvature is a limit taken from 1e-6 of the range inside.
      const double tolerance = v == 0.0 || v == 1.0 ? 1e-4 : 1e-9;
      EXPECT_NEAR(std::abs(p.k1), 1.0, tolerance);
      EXPECT_NEAR(std::abs(p.k2), 1.0, tolerance);
    }
  }
  EXPECT_EQ(s->expected_topology().euler_characteristic, 2);
  EXPECT_EQ(s->expected_topology().boundary_loops, 0);
  const auto mesh = testing::mesh_topology(tessellate(*s));
  EXPECT_EQ(mesh.euler_characteristic, 2);
  EXPECT_EQ(mesh.boundary_edges, 0u);
  EXPECT_TRUE(mesh.consistently_oriented);
}

TEST(NurbsSurface, u_and_v_are_exchanged_when_the_poles_lie_on_u_edges) {
  const auto s = make_nurbs_surface(transposed(sphere_patch()), "sphere");
  const ParameterDomain d = s->domain();
  EXPECT_EQ(d.u_gluing, Gluing::Periodic);
  EXPECT_TRUE(d.v0_is_pole && d.v1_is_pole);
  const auto original = make_nurbs_surface(sphere_patch(), "sphere");
  const SurfaceJet a = s->evaluate(0.3, 0.7), b = original->evaluate(0.3, 0.7);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(a.position, b.position)), 1e-14);
  EXPECT_LT(distance(a.duv, b.duv), 1e-12);
  EXPECT_EQ(testing::mesh_topology(tessellate(*s)).euler_characteristic, 2);
}

TEST(NurbsSurface, a_band_whose_ruling_turns_half_round_is_glued_with_a_flip) {
  for (const auto& patch : {moebius_patch(), transposed(moebius_patch())}) {
    const auto s = make_nurbs_surface(patch, "band");
    EXPECT_EQ(s->domain().u_gluing, Gluing::PeriodicFlipped);
    const ExpectedTopology t = s->expected_topology();
    EXPECT_EQ(t.euler_characteristic, 0);
    EXPECT_EQ(t.boundary_loops, 1);
    EXPECT_FALSE(t.is_orientable);
    EXPECT_EQ(t.boundary_knots, std::vector<std::string>{"unknot"});
    const auto mesh = testing::mesh_topology(tessellate(*s));
    EXPECT_EQ(mesh.euler_characteristic, 0);
    EXPECT_EQ(mesh.boundary_loops, 1u);
    EXPECT_EQ(mesh.non_manifold_edges, 0u);
    EXPECT_NE(s->description().find("with a flip"), std::string::npos) << s->description();
  }
}

/// The unit square with a circular hole of radius 0.25 at its centre.
NurbsPatch holed_square() {
  NurbsPatch p = envcrust::testing::square_patch();
  p.trim_loops = {{envcrust::testing::trim_polyline({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}})},
                  {envcrust::testing::trim_circle(0.5, 0.5, 0.25)}};
  return p;
}

TEST(NurbsSurface, a_trimmed_square_with_a_hole_is_an_annulus_sampled_outside_the_hole) {
  const auto s = make_nurbs_surface(holed_square(), "holed");
  EXPECT_NE(s->description().find("trimmed by 2 loops"), std::string::npos) << s->description();
  const ExpectedTopology t = s->expected_topology();
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_EQ(t.boundary_loops, 2);
  EXPECT_EQ(t.boundary_knots, (std::vector<std::string>{"unknot", "unknot"}));
  const Point3 centre(0.5, 0.5, 0);
  SampleOptions o;
  o.count = 4000;
  for (const Point3& p : sample_surface(*s, o).points) EXPECT_GE(std::sqrt(CGAL::squared_distance(p, centre)), 0.25 - 1e-9);
  EXPECT_NEAR(area(*s), 1 - std::numbers::pi / 16, 2e-3);
  // The hole's boundary: on the circle, conormals pointing into the hole (out of the surface).
  const auto curves = boundary_curves(*s, 0.01);
  ASSERT_EQ(curves.size(), 2u);
  std::size_t corners = 0;
  for (const auto& v : curves[0].vertices) corners += v.is_corner ? 1 : 0;
  EXPECT_EQ(corners, 4u);  // the square's
  for (const auto& v : curves[1].vertices) {
    const Vector3 to_centre = centre - v.position;
    EXPECT_NEAR(std::sqrt(to_centre.squared_length()), 0.25, 1e-5);
    EXPECT_GT(v.conormal * to_centre / 0.25, 0.999);
  }
  const auto mesh = testing::mesh_topology(tessellate(*s));
  EXPECT_EQ(mesh.euler_characteristic, 0);
  EXPECT_EQ(mesh.boundary_loops, 2u);
  EXPECT_EQ(mesh.non_manifold_edges, 0u);
  EXPECT_EQ(mesh.degenerate_triangles, 0u);
  EXPECT_TRUE(mesh.consistently_oriented);
}

TEST(NurbsSurface, bad_trim_loops_are_refused_with_the_reason) {
  auto p = holed_square();
  p.trim_loops[0][0].points[4] = {0, 0.1};  // the square no longer closes
  EXPECT_EQ(refusal(p), "NURBS surface: trim loop 0 does not close up");
  p = holed_square();
  p.trim_loops[1][0] = envcrust::testing::trim_circle(0.9, 0.5, 0.25);
  EXPECT_EQ(refusal(p).rfind("NURBS surface: trim loop 1 leaves the parameter domain at (", 0), 0u) << refusal(p);
  p = holed_square();
  p.trim_loops[0][0].knots[2] = -1;
  EXPECT_EQ(refusal(p), "NURBS surface: trim loop 0, curve 0: NURBS curve: knots must be non-decreasing");
  auto cylinder = cylinder_patch();
  cylinder.trim_loops = holed_square().trim_loops;
  EXPECT_EQ(refusal(cylinder),
            "NURBS surface: trimming a patch that closes up (a seam or an edge collapsed to a point) is not supported");
}

TEST(NurbsSurface, malformed_patches_are_refused_with_the_reason) {
  auto p = cylinder_patch();
  p.degree_u = 9;
  EXPECT_EQ(refusal(p), "NURBS surface: degree in u must be 1 to 8, got 9");
  p = cylinder_patch();
  p.knots_v.pop_back();
  EXPECT_EQ(refusal(p), "NURBS surface: 3 knots in v, expected 4 (control points + degree + 1)");
  p = cylinder_patch();
  p.knots_u[4] = 0.1;
  EXPECT_EQ(refusal(p), "NURBS surface: knots in u decrease at index 4 (0.25 then 0.1)");
  p = cylinder_patch();  // the circle's knot 0.25 three times: a quadratic torn apart
  p.knots_u = {0, 0, 0, 0.25, 0.25, 0.25, 0.5, 0.75, 0.75, 1, 1, 1};
  EXPECT_EQ(refusal(p), "NURBS surface: knot 0.25 in u is repeated 3 times, more than the degree 2: the surface is torn apart there");
  p = cylinder_patch();
  p.weights[10] = 0;
  EXPECT_EQ(refusal(p), "NURBS surface: the weight of control point (1, 1) is 0, weights must be finite and > 0");
  p = cylinder_patch();
  p.control_points.pop_back();
  EXPECT_EQ(refusal(p), "NURBS surface: 17 control points and 18 weights, expected 18 (9 x 2)");
  p = cylinder_patch();
  p.parameter_range = std::array<double, 4>{0, 2, -1, 1};
  EXPECT_EQ(refusal(p), "NURBS surface: parameter range [0, 2] x [-1, 1] is empty or outside the knots' [0, 1] x [-1, 1]");
  p = cylinder_patch();
  for (auto& q : p.control_points) q = Point3(1, 2, 3);
  EXPECT_EQ(refusal(p), "NURBS surface: all control points coincide");
}

TEST(NurbsSurface, degenerate_gluings_and_folds_are_refused) {
  // A bilinear 4 x 3 net whose first and last columns agree (closed in u) and whose last row
  // is the first reversed (closed in v with a flip): a Klein bottle.
  NurbsPatch klein;
  klein.degree_u = klein.degree_v = 1;
  klein.count_u = 4;
  klein.count_v = 3;
  klein.knots_u = {0, 0, 1.0 / 3, 2.0 / 3, 1, 1};
  klein.knots_v = {0, 0, 0.5, 1, 1};
  const Point3 a(0, 0, 0), c(1, 0, 0), e(2, 0, 0), b(0, 1, 0), m(1, 1, 1), n(2, 1, -1);
  klein.control_points = {a, c, e, a, b, m, n, b, a, e, c, a};
  klein.weights.assign(12, 1.0);
  EXPECT_EQ(refusal(klein), "NURBS surface: its edges are glued into a Klein bottle, which cannot be embedded in space");
  // A flat patch folded onto itself: the middle column of control points repeats the first,
  // so the surface turns back and S_u x S_v vanishes along the fold.
  NurbsPatch fold;
  fold.degree_u = 2;
  fold.degree_v = 1;
  fold.count_u = 3;
  fold.count_v = 2;
  fold.knots_u = {0, 0, 0, 1, 1, 1};
  fold.knots_v = {0, 0, 1, 1};
  fold.control_points = {Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 0, 0),
                         Point3(0, 1, 0), Point3(1, 1, 0), Point3(0, 1, 0)};
  fold.weights.assign(6, 1.0);
  EXPECT_EQ(refusal(fold).rfind("NURBS surface: the patch folds back on itself between (u, v) = (", 0), 0u)
      << refusal(fold);
}

}  // namespace
}  // namespace envcrust::surfaces
