// Tests of reconstruct's adaptive retry: when a uniform-rho run fails its check, the run is
// repeated with adaptive rho and the one with fewer defects is kept.
#include "fixtures/surface_samples.h"

#include "envcrust/pipeline.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace envcrust {
namespace {

TEST(RunDefects, CountsMismatchesAndHandlesBeyondTheBound) {
  pipeline::RunDefects d;
  d.genus = 3;
  d.missing_curves = 1;
  d.extra_loops = 2;
  EXPECT_EQ(d.count(std::nullopt), 6u);  // unknown genus: every handle counts
  EXPECT_EQ(d.count(1), 5u);
  EXPECT_EQ(d.count(5), 3u);             // fewer handles than allowed count as none
  d.genus.reset();                       // no manifold: worse than any manifold
  EXPECT_EQ(d.count(0), std::numeric_limits<std::size_t>::max());
}

// The face scan's two runs (2026-12-02): 2 extra loops each, the uniform one 6 curves missed
// and genus 1, the adaptive one 7 missed and genus 0. As many defects: the one without the
// handle is better; with the handle allowed (max_genus 1) the uniform one has fewer.
TEST(RunDefects, OnATieFewerHandlesAreBetter) {
  pipeline::RunDefects uniform, adaptive;
  uniform.genus = 1, uniform.missing_curves = 6, uniform.extra_loops = 2;
  adaptive.genus = 0, adaptive.missing_curves = 7, adaptive.extra_loops = 2;
  EXPECT_TRUE(adaptive.is_better_than(uniform, std::nullopt));
  EXPECT_FALSE(uniform.is_better_than(adaptive, std::nullopt));
  EXPECT_TRUE(uniform.is_better_than(adaptive, 1));
  EXPECT_FALSE(adaptive.is_better_than(adaptive, std::nullopt));  // equal: neither
  pipeline::RunDefects broken;                                     // no manifold
  EXPECT_TRUE(uniform.is_better_than(broken, std::nullopt));
  EXPECT_FALSE(broken.is_better_than(broken, std::nullopt));
}

// A torus said to have genus 0 (a wrong bound): the uniform run's genus 1 exceeds it, so the
// run is repeated with adaptive rho; that run has genus 1 as well, no fewer defects, so the
// uniform run is kept, and both runs' checks are reported.
TEST(AdaptiveRetry, KeepsTheUniformRunWhenAdaptiveIsNoBetter) {
  const auto samples = fixtures::builtin_samples("torus", 4000);
  pipeline::ReconstructOptions options;
  options.use_adaptive_retry = true;
  options.max_genus = 0;
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.adaptive_retry.has_value());
  const auto& retry = *result.adaptive_retry;
  EXPECT_EQ(retry.max_genus, 0);
  EXPECT_EQ(retry.uniform.genus, 1);
  EXPECT_EQ(retry.adaptive.genus, 1);
  EXPECT_EQ(retry.uniform.extra_loops, 0u);
  EXPECT_EQ(retry.adaptive.extra_loops, 0u);
  EXPECT_FALSE(retry.kept_adaptive);
  EXPECT_TRUE(result.envelope.local_rho.empty());  // the kept run is the uniform one
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_EQ(t.euler_characteristic, 0);
  EXPECT_TRUE(t.boundary_loops.empty());
  // The check's topology of the kept mesh comes with the result, for the report.
  ASSERT_TRUE(result.topology.has_value());
  EXPECT_EQ(result.topology->euler_characteristic, t.euler_characteristic);
  EXPECT_EQ(result.topology->faces, t.faces);
}

// The same torus with the bound it has (or without a bound, rho not raised for gaps): the
// uniform run passes its check and runs once.
TEST(AdaptiveRetry, RunsOnceWhenTheCheckPasses) {
  const auto samples = fixtures::builtin_samples("torus", 4000);
  pipeline::ReconstructOptions options;
  options.use_adaptive_retry = true;
  options.max_genus = 1;
  EXPECT_FALSE(pipeline::reconstruct(samples, options).adaptive_retry.has_value());
  options.max_genus.reset();
  const auto result = pipeline::reconstruct(samples, options);
  EXPECT_FALSE(result.envelope.is_rho_gap_bound);
  EXPECT_FALSE(result.adaptive_retry.has_value());
}

// 1,000 samples of the cylinder with rho 0.02, a fifth of what their gaps need: the uniform
// envelope falls apart and the run comes out empty (which the retry once skipped, so the CLI
// reported the empty result); adaptive rho, raised where the samples are sparse, gives the
// annulus and is kept.
TEST(AdaptiveRetry, RetriesAnEmptyUniformRun) {
  const auto samples = fixtures::builtin_samples("cylinder", 1000);
  pipeline::ReconstructOptions options;
  options.use_adaptive_retry = true;
  options.envelope.rho = 0.02;
  const auto result = pipeline::reconstruct(samples, options);
  ASSERT_TRUE(result.adaptive_retry.has_value());
  const auto& retry = *result.adaptive_retry;
  EXPECT_TRUE(retry.uniform.is_empty);
  EXPECT_FALSE(retry.uniform.genus.has_value());
  EXPECT_FALSE(retry.adaptive.is_empty);
  EXPECT_TRUE(retry.kept_adaptive);
  const auto topology = topology::analyze_topology(result.mesh);
  EXPECT_EQ(topology.euler_characteristic, 0);
  EXPECT_EQ(topology.boundary_loops.size(), 2u);
}

// A cylinder whose boundary curves are given as they are: its border loops follow them.
// With one curve left out, the result's loop there follows no given curve (a hole the input
// has not), which fails the check.
TEST(CheckResultBoundary, FindsLoopsThatFollowNoCurve) {
  auto samples = fixtures::builtin_samples("cylinder", 4000);
  pipeline::ReconstructOptions options;
  const auto result = pipeline::reconstruct(samples, options);
  const auto t = topology::analyze_topology(result.mesh);
  const auto check = pipeline::check_result_boundary(t, samples, result.envelope);
  EXPECT_TRUE(check.is_consistent());
  EXPECT_DOUBLE_EQ(check.tolerance, 2.0 * result.envelope.rho);
  EXPECT_NEAR(check.min_resolvable_length, 2 * std::numbers::pi * result.envelope.rho, 1e-12);
  // Two more curves on the mantle that the result has no loop along: a hole of radius rho/2
  // (the envelope closes every hole shorter than 2 pi rho: unresolved) and one of radius
  // 2 rho (missing).
  auto with_holes = samples;
  for (const double radius : {0.5 * result.envelope.rho, 2.0 * result.envelope.rho}) {
    BoundaryCurve hole;
    for (int k = 0; k < 64; ++k) {
      const double a = 2 * std::numbers::pi * k / 64, y = radius * std::cos(a), z = radius * std::sin(a);
      BoundaryVertex v;
      v.position = Point3(std::sqrt(1 - y * y), y, z);
      hole.vertices.push_back(v);
    }
    with_holes.boundary.push_back(hole);
  }
  const auto holes = pipeline::check_result_boundary(t, with_holes, result.envelope);
  EXPECT_EQ(holes.unresolved_curves, (std::vector<std::size_t>{2}));
  EXPECT_EQ(holes.missing_curves, (std::vector<std::size_t>{3}));
  samples.boundary.pop_back();
  const auto one_curve = pipeline::check_result_boundary(t, samples, result.envelope);
  EXPECT_TRUE(one_curve.missing_curves.empty());
  EXPECT_EQ(one_curve.extra_loops.size(), 1u);
}

}  // namespace
}  // namespace envcrust
