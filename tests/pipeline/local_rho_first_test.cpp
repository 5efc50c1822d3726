// reconstruct's first try for files: one run with rho following the local feature size, kept
// only when its sheet needed no cut and its result passes the retry's check.
#include "fixtures/surface_samples.h"

#include "envcrust/distance.h"
#include "envcrust/mesh.h"
#include "envcrust/pipeline.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace envcrust {
namespace {

pipeline::InputKind point_file() {
  pipeline::InputKind kind;
  kind.is_builtin = false;
  return kind;
}

// A point file's options, its result kept as the sheet (or crust) itself.
pipeline::ReconstructOptions file_options() {
  auto options = pipeline::options_for_input(point_file());
  options.mesh_samples.reset();
  return options;
}

TEST(LocalRhoFirst, IsOnForFilesWithAutomaticRhoOnly) {
  EXPECT_TRUE(pipeline::options_for_input(point_file()).use_local_rho_first);
  EXPECT_TRUE(pipeline::options_for_input(point_file()).use_power_crust_first);
  EXPECT_FALSE(pipeline::options_for_input({}).use_local_rho_first);  // a built-in surface
  EXPECT_FALSE(pipeline::options_for_input({}).use_power_crust_first);
  pipeline::ReconstructOptions given;
  given.envelope.rho = 0.1;
  EXPECT_FALSE(pipeline::options_for_input(point_file(), given).use_local_rho_first);
  EXPECT_FALSE(pipeline::options_for_input(point_file(), given).use_power_crust_first);
}

// A closed file: the direct Power Crust runs before any envelope run and, with no defect, is
// the result (a sphere: one closed piece of genus 0, every sample on it).
TEST(PowerCrustFirst, IsKeptOnAClosedInputWithoutDefectAndNoEnvelopeRuns) {
  const auto samples = fixtures::builtin_samples("sphere", 3000);
  ASSERT_TRUE(samples.boundary.empty());
  const auto result = pipeline::reconstruct(samples, file_options());
  ASSERT_TRUE(result.power_crust_first.has_value());
  const auto& first = *result.power_crust_first;
  EXPECT_TRUE(first.is_kept);
  EXPECT_TRUE(first.failure.empty());
  ASSERT_TRUE(first.defects.genus.has_value());
  EXPECT_EQ(*first.defects.genus, 0);
  EXPECT_EQ(first.defects.count(std::nullopt), 0u);
  EXPECT_GT(first.allowed_distance, 0.0);
  EXPECT_LE(first.farthest_from_samples, first.allowed_distance);
  EXPECT_EQ(result.method, pipeline::Method::PowerCrust);
  EXPECT_FALSE(result.local_rho_first.has_value());
  EXPECT_FALSE(result.adaptive_retry.has_value());
  EXPECT_FALSE(result.power_crust_fallback.has_value());
  EXPECT_TRUE(result.envelope.samples.empty());
  EXPECT_DOUBLE_EQ(result.seconds.power_crust, first.seconds);
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_TRUE(t.is_closed());
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.components.size(), 1u);
  const double diagonal = mesh::bbox_diagonal(samples.points);
  const auto d = distance::distances_to_mesh(samples.points, result.mesh);
  EXPECT_LT(*std::max_element(d.begin(), d.end()), 0.01 * diagonal);
}

// A handle is a defect while the genus is unknown: a torus's Power Crust is not kept and the
// local run follows. With its option off it is not tried.
TEST(PowerCrustFirst, GivesWayToTheLocalRunOnAHandleAndIsNotTriedWhenOff) {
  const auto samples = fixtures::builtin_samples("torus", 3000);
  auto options = file_options();
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.power_crust_first.has_value());
  EXPECT_FALSE(result.power_crust_first->is_kept);
  ASSERT_TRUE(result.power_crust_first->defects.genus.has_value());
  EXPECT_EQ(*result.power_crust_first->defects.genus, 1);
  ASSERT_TRUE(result.local_rho_first.has_value());
  EXPECT_EQ(result.method, pipeline::Method::Envelope);
  EXPECT_GE(result.seconds.power_crust, result.power_crust_first->seconds);
  EXPECT_EQ(topology::total_genus(topology::analyze_topology(result.mesh)).value_or(-1), 1);

  options.use_power_crust_first = false;
  EXPECT_FALSE(pipeline::reconstruct(samples, options).power_crust_first.has_value());
}

// The horn narrows to a tip: one rho must fit the tip, a local one grows along the wide end.
// The local run's sheet is clean there, so it is kept, on fewer envelope samples than the
// uniform run, with the same topology.
TEST(LocalRhoFirst, IsKeptWhereTheSheetIsCleanAndUsesFewerEnvelopeSamples) {
  const auto samples = fixtures::builtin_samples("horn", 4000);
  auto options = file_options();
  const auto local = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(local.local_rho_first.has_value());
  const auto& report = *local.local_rho_first;
  EXPECT_TRUE(report.is_kept);
  EXPECT_EQ(report.orientation_seams, 0u);
  EXPECT_EQ(report.handle_balls, 0u);
  ASSERT_TRUE(report.defects.has_value());
  ASSERT_TRUE(local.sheet_stats.has_value());
  EXPECT_FALSE(local.sheet_stats->stopped_after_cut);
  EXPECT_FALSE(local.adaptive_retry.has_value());
  EXPECT_FALSE(local.power_crust_fallback.has_value());
  const double diagonal = mesh::bbox_diagonal(samples.points);
  EXPECT_NEAR(report.rho_max, pipeline::kLocalRhoCeilingRelDiag * diagonal, 1e-9 * diagonal);
  EXPECT_LT(report.rho_min, report.rho_max);

  options.use_local_rho_first = false;
  const auto uniform = pipeline::reconstruct(samples, options);
  EXPECT_FALSE(uniform.local_rho_first.has_value());
  EXPECT_LT(report.envelope_samples, uniform.envelope.samples.size());

  const auto t = topology::analyze_topology(local.mesh);
  const auto u = topology::analyze_topology(uniform.mesh);
  EXPECT_EQ(t.euler_characteristic, u.euler_characteristic);
  EXPECT_EQ(t.boundary_loops.size(), u.boundary_loops.size());
  EXPECT_TRUE(t.is_manifold());
  // Every sample lies near the result (its sheet is not cut short).
  const auto d = distance::distances_to_mesh(samples.points, local.mesh);
  EXPECT_LT(*std::max_element(d.begin(), d.end()), 0.01 * diagonal);
}

// A run with more handles than the input's known genus fails the check: the local run is not
// kept and the uniform run follows, with the local run's seconds counted.
TEST(LocalRhoFirst, GivesWayToTheUniformRunWhenItsResultFailsTheCheck) {
  const auto samples = fixtures::builtin_samples("torus", 3000);
  pipeline::InputKind kind = point_file();
  kind.genus = 0;  // wrong on purpose: every torus then fails
  auto options = pipeline::options_for_input(kind);
  options.mesh_samples.reset();
  options.use_power_crust_fallback = options.use_power_crust_first = false;
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.local_rho_first.has_value());
  EXPECT_FALSE(result.local_rho_first->is_kept);
  ASSERT_TRUE(result.local_rho_first->defects.has_value());  // its sheet needed no cut
  ASSERT_TRUE(result.local_rho_first->defects->genus.has_value());
  EXPECT_EQ(*result.local_rho_first->defects->genus, 1);
  ASSERT_TRUE(result.adaptive_retry.has_value());  // the uniform run ran, and failed too
  EXPECT_GE(result.seconds.envelope, result.local_rho_first->seconds);
}

}  // namespace
}  // namespace envcrust
