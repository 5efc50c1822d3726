// Area-uniform sampling: determinism, exactness, uniformity by area, noise and option checks.
#include "envcrust/errors.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace envcrust::surfaces {
namespace {

double radius(const Point3& p) { return std::sqrt((p - CGAL::ORIGIN).squared_length()); }

TEST(Sampling, same_seed_gives_same_points_and_other_seeds_differ) {
  const auto torus = make_builtin("torus");
  const PointSet a = sample_surface(*torus, {500, 0.0, false, 7});
  const PointSet b = sample_surface(*torus, {500, 0.0, false, 7});
  const PointSet c = sample_surface(*torus, {500, 0.0, false, 8});
  ASSERT_EQ(a.size(), 500u);
  EXPECT_FALSE(a.has_normals());
  EXPECT_EQ(a.points, b.points);
  EXPECT_NE(a.points, c.points);
}

TEST(Sampling, points_lie_on_the_sphere_with_outward_radial_normals) {
  const PointSet s = sample_surface(*make_builtin("sphere"), {2000, 0.0, true, 3});
  ASSERT_EQ(s.normals.size(), s.points.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_NEAR(radius(s.points[i]), 1.0, 1e-12);
    EXPECT_NEAR(s.normals[i] * (s.points[i] - CGAL::ORIGIN), 1.0, 1e-12);
  }
}

TEST(Sampling, nurbs_cylinder_is_uniform_by_area_not_by_parameter) {
  // |C'(u)| varies by ~17% along each quarter arc; by area, each octant of angle holds 1/8.
  const PointSet s = sample_surface(*make_builtin("cylinder-nurbs"), {40000, 0.0, false, 11});
  int first_octant = 0;
  for (const Point3& p : s.points) {
    const double angle = std::atan2(p.y(), p.x());
    if (angle >= 0 && angle < std::numbers::pi / 4) ++first_octant;
  }
  EXPECT_NEAR(first_octant / 40000.0, 0.125, 0.006);
}

TEST(Sampling, hemisphere_cap_above_half_height_holds_half_the_points) {
  // Archimedes: the zone z in [0.5, 1] has area pi = half of the hemisphere's 2 pi.
  const PointSet s = sample_surface(*make_builtin("hemisphere"), {40000, 0.0, false, 5});
  int upper = 0;
  for (const Point3& p : s.points) upper += p.z() > 0.5 ? 1 : 0;
  EXPECT_NEAR(upper / 40000.0, 0.5, 0.01);
}

TEST(Sampling, noise_has_the_requested_sigma) {
  const auto sphere = make_builtin("sphere");
  const double sigma = 0.001 * std::sqrt(12.0);
  const PointSet s = sample_surface(*sphere, {20000, 0.001, false, 9});
  double sum_squares = 0;
  for (const Point3& p : s.points) sum_squares += (radius(p) - 1) * (radius(p) - 1);
  // The radial component of isotropic noise has the full sigma.
  EXPECT_NEAR(std::sqrt(sum_squares / 20000.0), sigma, 0.03 * sigma);
}

TEST(Sampling, every_builtin_samples_finite_points) {
  for (const std::string& name : builtin_names()) {
    const PointSet s = sample_surface(*make_builtin(name), {200, 0.0, true, 1});
    ASSERT_EQ(s.size(), 200u) << name;
    for (std::size_t i = 0; i < s.size(); ++i) {
      EXPECT_TRUE(std::isfinite(s.points[i].x()) && std::isfinite(s.points[i].z())) << name;
      EXPECT_NEAR(s.normals[i].squared_length(), 1.0, 1e-12) << name;
    }
  }
}

TEST(Sampling, rejects_zero_count_and_negative_noise) {
  const auto square = make_builtin("square");
  try {
    (void)sample_surface(*square, {0, 0.0, false, 1});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "sample count must be >= 1 (got 0)");
  }
  try {
    (void)sample_surface(*square, {10, -0.1, false, 1});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "noise must be in [0, 1], a fraction of the diagonal (got -0.1)");
  }
  try {
    (void)sample_surface(*square, {10, 1e300, false, 1});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "noise must be in [0, 1], a fraction of the diagonal (got 1e+300)");
  }
}

}  // namespace
}  // namespace envcrust::surfaces
