// Tests of the two-sided mesh distances against analytic answers.
#include "envcrust/distance.h"
#include "envcrust/errors.h"
#include "fixtures/shapes.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace envcrust;

namespace {

TriangleMesh scaled(TriangleMesh m, double s) {
  for (auto& p : m.vertices) p = Point3(s * p.x(), s * p.y(), s * p.z());
  return m;
}

Polyline circle(double r, int n, double z = 0) {
  Polyline c;
  for (int i = 0; i < n; ++i)
    c.emplace_back(r * std::cos(fixtures::kTwoPi * i / n), r * std::sin(fixtures::kTwoPi * i / n), z);
  return c;
}

}  // namespace

TEST(Distance, coarse_cylinder_is_within_its_chord_error_of_a_fine_one) {
  const auto coarse = fixtures::open_cylinder(16, 4);
  const auto fine = fixtures::open_cylinder(512, 4);
  distance::DistanceOptions o;
  o.samples = 20000;
  const auto r = distance::compare_to_mesh(coarse, fine, o);
  const double sagitta = 1 - std::cos(std::numbers::pi / 16);  // deepest point of a chord
  // Chord midpoints are a sagitta inside the fine circle, and the fine circle's points there
  // a sagitta outside the chords (less the fine mesh's own sagitta).
  const double fine_sagitta = 1 - std::cos(std::numbers::pi / 512);
  EXPECT_NEAR(r.mesh_to_reference.max, sagitta - fine_sagitta, 0.02 * sagitta);
  EXPECT_NEAR(r.reference_to_mesh.max, sagitta, 0.02 * sagitta);
  EXPECT_LT(r.mesh_to_reference.mean, r.mesh_to_reference.max);
  EXPECT_NEAR(r.reference_diagonal, std::sqrt(12.0), 1e-3);
  EXPECT_DOUBLE_EQ(r.hausdorff, std::max(r.mesh_to_reference.max, r.reference_to_mesh.max));
}

TEST(Distance, scaled_octahedron_is_offset_by_the_scale_difference_at_vertices) {
  const auto a = fixtures::octahedron();
  const auto b = scaled(a, 1.1);
  const auto r = distance::compare_to_mesh(a, b);
  // The outer octahedron's vertices lie 0.1 beyond the inner one's vertices, and that is the
  // farthest any point of b is from a; a's face centres are 0.1/sqrt(3) inside b's faces.
  EXPECT_NEAR(r.reference_to_mesh.max, 0.1, 1e-9);
  EXPECT_NEAR(r.mesh_to_reference.max, 0.1 / std::sqrt(3.0), 1e-9);
}

TEST(Distance, point_reference_measures_both_ways) {
  const auto m = fixtures::square(4);
  std::vector<Point3> pts = {{0, 0, 0.5}, {1, 1, 0}, {0.5, 0.5, 0}};
  distance::DistanceOptions o;
  o.samples = 1000;
  const auto r = distance::compare_to_points(m, pts, o);
  EXPECT_NEAR(r.reference_to_mesh.max, 0.5, 1e-12);
  EXPECT_EQ(r.reference_to_mesh.samples, 3u);
  // The corners (1,0) and (0,1) are sqrt(0.5) from (0.5,0.5,0), nearer than any other sample.
  EXPECT_NEAR(r.mesh_to_reference.max, std::sqrt(0.5), 1e-12);
}

TEST(Distance, concentric_circles_are_their_radius_difference_apart) {
  EXPECT_NEAR(distance::closed_polyline_hausdorff(circle(1, 400), circle(1.1, 400)), 0.1, 1e-9);
  EXPECT_NEAR(distance::closed_polyline_hausdorff(circle(1, 400), circle(1, 400, 0.3)), 0.3, 1e-9);
}

// A curve of tiny edges beside a long one: steps of 1/8 of the tiny edges along the long
// curve would be 8e9 points (it ran out of memory on a boundary given as a point grid); each
// curve is stepped at 1/200,000 of its length at the finest.
TEST(Distance, a_tiny_curve_against_a_long_one_is_stepped_along_its_own_length) {
  const Polyline tiny = {Point3(0, 0, 0), Point3(1e-9, 0, 0), Point3(0, 1e-9, 0)};
  const Polyline square = {Point3(-1, -1, 0), Point3(1, -1, 0), Point3(1, 1, 0), Point3(-1, 1, 0)};
  EXPECT_NEAR(distance::closed_polyline_hausdorff(tiny, square), std::sqrt(2.0), 1e-6);  // the corners
}

// Samples at the corners of a unit square leave the midpoints of its sides 0.5 from the
// nearest one; the midpoints are no vertex of the curve, so only the steps along the sides find
// them. Samples inside the square (at the centre) are farther.
TEST(Distance, a_boundary_is_as_far_from_its_samples_as_its_emptiest_stretch) {
  const Polyline square{Point3(0, 0, 0), Point3(1, 0, 0), Point3(1, 1, 0), Point3(0, 1, 0)};
  const std::vector<Point3> corners(square.begin(), square.end());
  const auto gap = distance::curves_to_points({square}, corners, 0.01);
  EXPECT_NEAR(gap.max, 0.5, 1e-12);
  EXPECT_EQ(gap.samples, 400u);
  EXPECT_NEAR(distance::curves_to_points({square}, corners, 2.0).max, 0.0, 1e-12);  // vertices only
  EXPECT_NEAR(distance::curves_to_points({square}, {Point3(0.5, 0.5, 0)}, 0.01).max, std::sqrt(0.5), 1e-12);
  EXPECT_THROW(distance::curves_to_points({square}, corners, 0.0), InvalidInput);
}

TEST(Distance, empty_inputs_are_refused) {
  try {
    distance::compare_to_points(fixtures::square(2), {});
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "the reference point set is empty");
  }
  try {
    distance::compare_to_mesh(TriangleMesh{}, fixtures::square(2));
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "the mesh has no triangles");
  }
}
