// A strip much narrower than it is long: its reach is infinite (it is flat), so before the
// automatic rho was capped by the surface's half-width it took half of 10% of the diagonal,
// five times the strip's width, and the envelope, a near-round tube around a thin sheet,
// had too few samples across the strip for its medial sheet to come out.
#include "envcrust/envelope.h"
#include "envcrust/nurbs_surface.h"
#include "envcrust/pipeline.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace envcrust {
namespace {

constexpr double kLength = 20.0;
constexpr double kWidth = 0.2;

// The flat strip [0, 20] x [0, 0.2] in z = 0 as a bilinear NURBS patch (exact boundary).
envelope::SurfaceSamples strip_samples(std::size_t count) {
  surfaces::NurbsPatch patch;
  patch.degree_u = patch.degree_v = 1;
  patch.count_u = patch.count_v = 2;
  patch.knots_u = patch.knots_v = {0, 0, 1, 1};
  patch.control_points = {Point3(0, 0, 0), Point3(kLength, 0, 0), Point3(0, kWidth, 0), Point3(kLength, kWidth, 0)};
  patch.weights = {1, 1, 1, 1};
  const auto surface = surfaces::make_nurbs_surface(patch, "strip");
  surfaces::SampleOptions o;
  o.count = count;
  o.with_normals = true;
  o.seed = 2;
  const PointSet ps = surfaces::sample_surface(*surface, o);
  envelope::SurfaceSamples s{ps.points, ps.normals, {}, {}};
  s.boundary = surfaces::boundary_curves(*surface, 0.01);
  return s;
}

// Distance from x to the strip.
double distance_to_strip(const Point3& x) {
  const double dx = std::max({0.0, -x.x(), x.x() - kLength});
  const double dy = std::max({0.0, -x.y(), x.y() - kWidth});
  return std::sqrt(dx * dx + dy * dy + x.z() * x.z());
}

TEST(NarrowStrip, AutomaticRhoIsAtMostTheHalfWidth) {
  const auto samples = strip_samples(10000);
  const auto e = envelope::sample_envelope(samples);
  // The centre line lies 0.1 from both long edges: the half-width reads about that.
  EXPECT_NEAR(e.half_width, 0.5 * kWidth, 0.005);
  EXPECT_TRUE(e.is_rho_width_bound);
  EXPECT_DOUBLE_EQ(e.rho, 0.5 * 2.0 * e.half_width);  // rho_rel_reach * max_reach_rel_half_width * half-width

  envelope::EnvelopeOptions uncapped;
  uncapped.max_reach_rel_half_width = std::numeric_limits<double>::max();
  const auto wide = envelope::sample_envelope(samples, uncapped);
  EXPECT_FALSE(wide.is_rho_width_bound);
  EXPECT_GT(wide.rho, 4.0 * kWidth);  // half of 10% of the diagonal
}

TEST(NarrowStrip, ComesOutAsOneDiscOnTheStrip) {
  const auto samples = strip_samples(10000);
  const auto result = pipeline::reconstruct(samples);
  const auto t = topology::analyze_topology(result.mesh);
  EXPECT_TRUE(t.is_manifold());
  EXPECT_EQ(t.components.size(), 1u);
  EXPECT_EQ(t.euler_characteristic, 1);
  ASSERT_EQ(t.boundary_loops.size(), 1u);
  const double diagonal = std::hypot(kLength, kWidth);
  double farthest = 0.0;
  for (const auto& p : result.mesh.vertices) farthest = std::max(farthest, distance_to_strip(p));
  EXPECT_LT(farthest, 0.005 * diagonal);
}

// Samples too sparse to bridge their gaps at a rho the strip's width allows: the warning
// names the width, not the diagonal, as the bound that was passed.
TEST(NarrowStrip, TooSparseForItsWidthIsReported) {
  const auto samples = strip_samples(150);
  const auto e = envelope::sample_envelope(samples);
  EXPECT_TRUE(e.is_rho_gap_bound);
  EXPECT_TRUE(e.is_input_too_sparse);
  EXPECT_GT(e.rho, 2.0 * e.half_width);
  const auto it = std::find_if(e.warnings.begin(), e.warnings.end(),
                               [](const std::string& w) { return w.rfind("the input is too sparse for its width", 0) == 0; });
  ASSERT_NE(it, e.warnings.end());
  EXPECT_NE(it->find(" is more than 2 times the surface's half-width "), std::string::npos) << *it;
  EXPECT_NE(it->find("samples, evenly spread, would bridge the gaps with rho at that bound"), std::string::npos) << *it;
}

// An unsampled-boundary strip: no curves, so no width and no cap (a closed surface's rho
// follows its reach and diagonal alone).
TEST(NarrowStrip, WithoutBoundaryCurvesTheWidthSetsNoCap) {
  auto samples = strip_samples(2000);
  samples.boundary.clear();
  const auto e = envelope::sample_envelope(samples);
  EXPECT_TRUE(std::isinf(e.half_width));
  EXPECT_FALSE(e.is_rho_width_bound);
}

}  // namespace
}  // namespace envcrust
