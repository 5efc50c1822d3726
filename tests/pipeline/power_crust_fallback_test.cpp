// Tests of reconstruct's Power Crust fallback: when the envelope's result of an input without
// trusted boundary curves fails its check, the direct Power Crust runs too and the result with
// fewer defects is kept.
#include "fixtures/shapes.h"
#include "fixtures/surface_samples.h"

#include "envcrust/pipeline.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace envcrust {
namespace {

// Distance of p from the built-in torus (major radius 1, minor radius 0.4, around z).
double torus_distance(const Point3& p) {
  const double ring = std::hypot(p.x(), p.y()) - 1.0;
  return std::abs(std::hypot(ring, p.z()) - 0.4);
}

TEST(SampleGroups, CountsSetsJoinedByNeighboursWithinTheReach) {
  std::vector<Point3> points;  // two 10 x 10 grids of spacing 0.1, 0.12 apart
  for (int g = 0; g < 2; ++g)
    for (int i = 0; i < 10; ++i)
      for (int j = 0; j < 10; ++j) points.emplace_back(0.1 * i + 1.02 * g, 0.1 * j, 0.0);
  EXPECT_EQ(pipeline::sample_groups(points, 0.11), 2u);
  EXPECT_EQ(pipeline::sample_groups(points, 0.13), 1u);
  EXPECT_EQ(pipeline::sample_groups(points, 0.05), 200u);  // no two points that close
  EXPECT_EQ(pipeline::sample_groups({}, 1.0), 0u);
}

// A unit square mesh and samples of it, plus a patch of 20 samples 0.5 above it and 3 strays
// 0.5 below: with rho 0.05 the patch is left out (the strays are too few to count); with rho
// 0.3 (2 rho = 0.6) everything is near the square.
TEST(UncoveredPatches, CountsPartsOfTheSampleFarFromTheResult) {
  const TriangleMesh square = fixtures::square(10);
  std::vector<Point3> points;
  for (int i = 0; i <= 20; ++i)
    for (int j = 0; j <= 20; ++j) points.emplace_back(0.05 * i, 0.05 * j, 0.0);
  for (int i = 0; i < 20; ++i) points.emplace_back(0.5 + 0.01 * (i % 5), 0.5 + 0.01 * (i / 5), 0.5);
  for (int i = 0; i < 3; ++i) points.emplace_back(0.2 + 0.01 * i, 0.2, -0.5);
  EXPECT_EQ(pipeline::uncovered_patches(square, points, 0.05), 1u);
  EXPECT_EQ(pipeline::uncovered_patches(square, points, 0.3), 0u);
  EXPECT_EQ(pipeline::uncovered_patches(TriangleMesh{}, points, 0.05), 0u);
}

TEST(RunDefects, PiecesBeyondTheSampleGroupsAreDefects) {
  pipeline::RunDefects d;
  d.genus = 0;
  d.missing_curves = 1;
  d.extra_pieces = 5;
  EXPECT_EQ(d.count(std::nullopt), 6u);
  d.uncovered_patches = 2;
  EXPECT_EQ(d.count(std::nullopt), 8u);
  d.uncovered_patches = 0;
  pipeline::RunDefects closed;  // the Power Crust of the same samples: one curve closed, a handle
  closed.genus = 1;
  closed.missing_curves = 1;
  EXPECT_TRUE(closed.is_better_than(d, std::nullopt));
}

// 300 samples of the torus (about 0.5 minor radii apart) are too sparse for any envelope:
// the sheet falls apart and the run comes out empty, uniform and adaptive alike. The direct
// Power Crust gives the torus, and is kept.
TEST(PowerCrustFallback, KeepsTheDirectPowerCrustOfASparseClosedSample) {
  const auto samples = fixtures::builtin_samples("torus", 300);
  pipeline::ReconstructOptions options;
  options.use_adaptive_retry = true;
  const auto without = pipeline::reconstruct(samples, options);
  EXPECT_TRUE(without.mesh.triangles.empty());
  EXPECT_FALSE(without.power_crust_fallback.has_value());
  EXPECT_EQ(without.method, pipeline::Method::Envelope);

  options.use_power_crust_fallback = true;
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.power_crust_fallback.has_value());
  const auto& fallback = *result.power_crust_fallback;
  EXPECT_TRUE(fallback.envelope.is_empty);
  EXPECT_EQ(fallback.power_crust.genus, 1);
  EXPECT_EQ(fallback.power_crust.extra_pieces, 0u);
  EXPECT_EQ(fallback.sample_groups, 1u);
  EXPECT_TRUE(fallback.kept_power_crust);
  EXPECT_EQ(result.method, pipeline::Method::PowerCrust);
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.is_closed());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 0);
  double farthest = 0;
  for (const auto& v : result.mesh.vertices) farthest = std::max(farthest, torus_distance(v));
  // The crust's vertices are power-diagram vertices: with samples about 0.23 apart (0.6
  // minor radii), up to 0.6 spacings off the surface (0.14 measured). Half the minor radius:
  // the torus, not a blob around it.
  EXPECT_LT(farthest, 0.2);
}

TEST(PowerCrustFallback, DoesNotRunWhenTheEnvelopePasses) {
  const auto samples = fixtures::builtin_samples("torus", 4000);
  pipeline::ReconstructOptions options;
  options.use_adaptive_retry = true;
  options.use_power_crust_fallback = true;
  const auto result = pipeline::reconstruct(samples, options);
  EXPECT_FALSE(result.power_crust_fallback.has_value());
  EXPECT_EQ(result.method, pipeline::Method::Envelope);
  EXPECT_EQ(topology::analyze_topology(result.mesh).euler_characteristic, 0);
}

// The cylinder at rho 0.02, a fifth of what its 1,000 samples' gaps need: the envelope's run
// is empty. Its own (trusted) curves keep the fallback out. Said to be detected, the curves
// might be false ones, and the direct Power Crust runs; it closes both ends with caps 1.0
// (the radius) from the nearest sample, far beyond the samples' gap size: the curves were
// real holes, and the envelope's (empty) run stays.
TEST(PowerCrustFallback, KeepsNoCapAcrossADetectedHole) {
  const auto samples = fixtures::builtin_samples("cylinder", 1000);
  pipeline::ReconstructOptions options;
  options.envelope.rho = 0.02;
  options.use_power_crust_fallback = true;
  const auto trusted = pipeline::reconstruct(samples, options);
  EXPECT_FALSE(trusted.power_crust_fallback.has_value());
  EXPECT_TRUE(trusted.mesh.triangles.empty());

  options.are_curves_detected = true;
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.power_crust_fallback.has_value());
  const auto& fallback = *result.power_crust_fallback;
  EXPECT_TRUE(fallback.envelope.is_empty);
  EXPECT_EQ(fallback.power_crust.missing_curves, 2u);
  EXPECT_GT(fallback.crust_farthest_from_samples, 0.8);
  EXPECT_GT(fallback.crust_allowed_distance, 0.05);
  EXPECT_LT(fallback.crust_allowed_distance, 0.3);
  EXPECT_FALSE(fallback.kept_power_crust);
  EXPECT_TRUE(result.mesh.triangles.empty());
  EXPECT_EQ(result.method, pipeline::Method::Envelope);
}

// The sparse torus with a false curve "detected" on it (a small loop on the outer equator):
// the Power Crust closes it, stays near the samples everywhere, and is kept.
TEST(PowerCrustFallback, ClosesAFalseDetectedCurve) {
  auto samples = fixtures::builtin_samples("torus", 300);
  BoundaryCurve loop;
  for (int k = 0; k < 32; ++k) {
    const double a = 2 * std::numbers::pi * k / 32, r = 1.0 + 0.4 * std::cos(0.3 * std::sin(a));
    BoundaryVertex v;
    v.position = Point3(r * std::cos(0.3 * std::cos(a)), r * std::sin(0.3 * std::cos(a)), 0.4 * std::sin(0.3 * std::sin(a)));
    loop.vertices.push_back(v);
  }
  samples.boundary.push_back(loop);
  pipeline::ReconstructOptions options;
  options.use_adaptive_retry = true;
  options.use_power_crust_fallback = true;
  options.are_curves_detected = true;
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.power_crust_fallback.has_value());
  const auto& fallback = *result.power_crust_fallback;
  EXPECT_EQ(fallback.power_crust.missing_curves, 1u);
  EXPECT_LE(fallback.crust_farthest_from_samples, fallback.crust_allowed_distance);
  EXPECT_TRUE(fallback.kept_power_crust);
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_closed());
  EXPECT_EQ(t.euler_characteristic, 0);
}

// A flat square sampled without its curve and with normal lines lying in its plane: the
// envelope's offsets land on the square and its run is empty, which fails the check; the
// direct Power Crust refuses coplanar samples, which counts as an empty run and is said.
TEST(PowerCrustFallback, SurvivesAPowerCrustThatRefusesTheSamples) {
  auto samples = fixtures::builtin_samples("square", 2000);
  samples.boundary.clear();
  for (auto& n : samples.normals) n = Vector3(1, 0, 0);
  pipeline::ReconstructOptions options;
  options.use_power_crust_fallback = true;
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.power_crust_fallback.has_value());
  const auto& fallback = *result.power_crust_fallback;
  EXPECT_TRUE(fallback.envelope.is_empty);
  EXPECT_TRUE(fallback.power_crust.is_empty);
  EXPECT_EQ(fallback.power_crust_failure, "all 2000 points are coplanar: nothing to reconstruct");
  EXPECT_FALSE(fallback.kept_power_crust);
  EXPECT_EQ(result.method, pipeline::Method::Envelope);
  EXPECT_TRUE(result.mesh.triangles.empty());
}

// options_for_input turns the fallback on with automatic rho, and trusts a mesh's curves.
TEST(PowerCrustFallback, IsOnForInputsWithAutomaticRho) {
  pipeline::InputKind points;
  points.is_builtin = false;
  points.are_normals_estimated = true;
  points.is_boundary_detected = true;
  const auto o = pipeline::options_for_input(points);
  EXPECT_TRUE(o.use_power_crust_fallback);
  EXPECT_TRUE(o.are_curves_detected);
  pipeline::ReconstructOptions given;
  given.envelope.rho = 0.1;
  EXPECT_FALSE(pipeline::options_for_input(points, given).use_power_crust_fallback);
  pipeline::InputKind mesh;
  mesh.is_builtin = false;
  mesh.is_orientable = true;
  EXPECT_FALSE(pipeline::options_for_input(mesh).are_curves_detected);
}

}  // namespace
}  // namespace envcrust
