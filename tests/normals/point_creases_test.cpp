// point_creases: sharp creases of a point cloud from normal lines that jump across them.
#include "envcrust/errors.h"
#include "envcrust/normals.h"
#include "envcrust/random.h"
#include "envcrust/surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace envcrust {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// n random points on two unit squares joined along the y axis, A in the plane z = 0 (x <= 0),
// B bent up by `bend_deg` about the fold, with each half's exact normal (its sign random).
PointSet folded_samples(double bend_deg, std::size_t n, std::uint64_t seed) {
  const double b = bend_deg * kDegree;
  std::mt19937_64 rng(seed);
  PointSet out;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = 2.0 * uniform01(rng) - 1.0, y = uniform01(rng);
    const double sign = uniform01(rng) < 0.5 ? -1.0 : 1.0;
    if (s <= 0) {
      out.points.emplace_back(s, y, 0);
      out.normals.emplace_back(0, 0, sign);
    } else {
      out.points.emplace_back(s * std::cos(b), y, s * std::sin(b));
      out.normals.emplace_back(-sign * std::sin(b), 0, sign * std::cos(b));
    }
  }
  return out;
}

TEST(PointCreases, a_fold_of_90_degrees_is_found_on_its_line_with_its_bend_and_wedge) {
  const PointSet fold = folded_samples(90.0, 4000, 1);
  const auto sharp = normals::point_creases(fold.points, fold.normals);
  ASSERT_GT(sharp.count, 20u);
  for (const auto& s : sharp.segments) {
    for (const Point3& end : {s.a, s.b}) {  // on the fold line x = z = 0, exactly
      EXPECT_NEAR(end.x(), 0.0, 1e-9);
      EXPECT_NEAR(end.z(), 0.0, 1e-9);
    }
    // Halfway between A's direction (-1, 0, 0) and B's (0, 0, 1).
    EXPECT_NEAR(s.wedge.x(), -std::sqrt(0.5), 1e-9);
    EXPECT_NEAR(s.wedge.y(), 0.0, 1e-9);
    EXPECT_NEAR(s.wedge.z(), std::sqrt(0.5), 1e-9);
  }
  EXPECT_NEAR(sharp.max_bend_deg, 90.0, 1e-6);
  ASSERT_TRUE(sharp.sharpest.has_value());
  // The fold is 1 long: the spanning forest of the segments' midpoints reads it so, less the
  // stretches at its ends beyond the first and last midpoints.
  EXPECT_GT(sharp.total_length, 0.7);
  EXPECT_LT(sharp.total_length, 1.0);
}

TEST(PointCreases, the_bend_is_read_from_the_positions_so_120_and_60_degree_wedges_differ) {
  // Normal lines of a fold by 120 degrees make 60 degrees, as those of a fold by 60 do: the
  // half-planes through the samples tell them apart.
  const PointSet sharp_fold = folded_samples(120.0, 4000, 2);
  const auto sharp = normals::point_creases(sharp_fold.points, sharp_fold.normals);
  ASSERT_GT(sharp.count, 20u);
  EXPECT_NEAR(sharp.max_bend_deg, 120.0, 1e-6);
  const PointSet mild_fold = folded_samples(60.0, 4000, 2);
  const auto mild = normals::point_creases(mild_fold.points, mild_fold.normals);
  EXPECT_EQ(mild.count, 0u);
  EXPECT_FALSE(mild.sharpest.has_value());
  EXPECT_EQ(mild.total_length, 0.0);
}

TEST(PointCreases, smooth_surfaces_with_exact_or_estimated_normals_have_none) {
  for (const char* name : {"sphere", "torus", "trefoil-ribbon", "moebius"}) {
    const auto surface = surfaces::make_builtin(name);
    surfaces::SampleOptions o;
    o.count = 5000;
    o.with_normals = true;
    const PointSet samples = surfaces::sample_surface(*surface, o);
    EXPECT_EQ(normals::point_creases(samples.points, samples.normals).count, 0u) << name;
    const auto estimated = normals::estimate_normal_lines(samples.points);
    EXPECT_EQ(normals::point_creases(samples.points, estimated).count, 0u) << name << ", estimated normals";
  }
}

TEST(PointCreases, bad_options_are_refused_by_name) {
  const PointSet fold = folded_samples(90.0, 100, 3);
  normals::PointCreaseOptions o;
  o.min_bend_deg = 180;
  EXPECT_THROW(
      {
        try {
          (void)normals::point_creases(fold.points, fold.normals, o);
        } catch (const InvalidOptions& e) {
          EXPECT_STREQ(e.what(), "point creases: min_bend_deg must be in (0, 180) (got 180.000000)");
          throw;
        }
      },
      InvalidOptions);
  o = {};
  o.neighbors = 0;
  EXPECT_THROW((void)normals::point_creases(fold.points, fold.normals, o), InvalidOptions);
  EXPECT_THROW((void)normals::point_creases(fold.points, {}), InvalidOptions);
}

}  // namespace
}  // namespace envcrust
