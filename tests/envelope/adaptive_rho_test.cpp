// Tests of the local reach and the adaptive rho on two flat sheets that face each other
// closely over half of their extent (a gap between toes, generated in code).
#include "envcrust/envelope.h"
#include "envcrust/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace envcrust;

namespace {

constexpr double kGap = 0.1;  // sheet B lies kGap above sheet A
constexpr std::uint64_t kSeed = 7;

// Sheet A: [0, 2] x [0, 1] at z = 0 (6000 points); sheet B: [0, 1] x [0, 1] at z = kGap
// (3000 points). Exact normals (0, 0, 1). Over x < 1 the local reach is kGap / 2; beyond
// x ~ 1.5 only the far edge of B constrains it (>= 1).
envelope::SurfaceSamples two_close_sheets() {
  std::mt19937_64 rng(kSeed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  envelope::SurfaceSamples s;
  for (int i = 0; i < 6000; ++i) {
    s.points.emplace_back(2.0 * u(rng), u(rng), 0.0);
    s.normals.emplace_back(0, 0, 1);
  }
  for (int i = 0; i < 3000; ++i) {
    s.points.emplace_back(u(rng), u(rng), kGap);
    s.normals.emplace_back(0, 0, 1);
  }
  return s;
}

bool is_under_sheet_b(const Point3& p) { return p.z() == 0.0 && p.x() > 0.1 && p.x() < 0.9 && p.y() > 0.1 && p.y() < 0.9; }
bool is_far_from_sheet_b(const Point3& p) { return p.z() == 0.0 && p.x() > 1.6; }

// Lipschitz over every pair closer than 0.05 (a superset of the graph's short edges is not
// guaranteed, but paths through the dense kNN graph are nearly straight here).
void expect_lipschitz(const std::vector<Point3>& points, const std::vector<double>& rho, double lipschitz) {
  for (std::size_t i = 0; i < points.size(); i += 37)
    for (std::size_t j = 0; j < points.size(); ++j) {
      const double d = std::sqrt(CGAL::squared_distance(points[i], points[j]));
      if (d < 0.05) { EXPECT_LE(std::abs(rho[i] - rho[j]), 1.5 * lipschitz * d + 1e-12) << i << " " << j; }
    }
}

// Adaptive rho options clamped to [0.01, 0.1], defaults otherwise.
envelope::AdaptiveRhoOptions clamped_to_0_01_and_0_1() {
  envelope::AdaptiveRhoOptions o;
  o.rho_min = 0.01;
  o.rho_max = 0.1;
  return o;
}

// The local reach of the two sheets, with pairs shorter than the gap admitted only when they
// cross to the facing sheet.
std::vector<double> sheets_local_reach(const envelope::SurfaceSamples& s) {
  envelope::LocalReachOptions o;
  o.search_radius = 1.0;
  o.min_pair_distance = 0.2;
  return envelope::estimate_local_reach(s, o);
}

}  // namespace

TEST(LocalReach, facing_sheets_read_half_their_gap_and_open_parts_read_far_more) {
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  const auto s = two_close_sheets();
  envelope::LocalReachOptions o;
  o.search_radius = 1.0;
  o.min_pair_distance = 0.2;  // the gap (0.1) is shorter: only the crossing test admits it
  const auto lfs = envelope::estimate_local_reach(s, o);
  ASSERT_EQ(lfs.size(), s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    if (is_under_sheet_b(s.points[i])) { EXPECT_NEAR(lfs[i], kGap / 2, 0.005) << "point " << i; }
    if (is_far_from_sheet_b(s.points[i])) { EXPECT_GT(lfs[i], 0.5) << "point " << i; }
  }
}

TEST(LocalReach, rejects_a_non_positive_search_radius) {
  envelope::LocalReachOptions o;
  o.search_radius = 0.0;
  try {
    envelope::estimate_local_reach(two_close_sheets(), o);
    FAIL() << "no exception";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "LocalReachOptions::search_radius out of range (got 0)");
  }
}

TEST(AdaptiveRho, follows_the_gap_within_its_clamps_and_is_lipschitz) {
  const auto s = two_close_sheets();
  const auto lfs = sheets_local_reach(s);
  const envelope::AdaptiveRhoOptions o = clamped_to_0_01_and_0_1();
  const auto rho = envelope::adaptive_rho(s.points, lfs, o);
  ASSERT_EQ(rho.size(), s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    EXPECT_GE(rho[i], o.rho_min);
    EXPECT_LE(rho[i], o.rho_max);
    if (is_under_sheet_b(s.points[i])) { EXPECT_NEAR(rho[i], o.rho_rel_lfs * kGap / 2, 0.003) << "point " << i; }
    // From x = 1 to 1.6 the bound rises by 0.3 * 0.6 = 0.18 > rho_max.
    if (is_far_from_sheet_b(s.points[i])) { EXPECT_DOUBLE_EQ(rho[i], o.rho_max) << "point " << i; }
  }
  expect_lipschitz(s.points, rho, o.lipschitz);
}

// A floor of 0.2 beyond x = 1.8 (a sparse stretch needing a wider envelope) lifts rho there
// above rho_max, falls off at slope L towards it, and leaves rho alone farther away.
TEST(AdaptiveRho, a_floor_lifts_rho_to_the_smallest_lipschitz_function_above_it) {
  const auto s = two_close_sheets();
  const auto lfs = sheets_local_reach(s);
  const envelope::AdaptiveRhoOptions o = clamped_to_0_01_and_0_1();
  std::vector<double> floor(s.points.size(), 0.0);
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (s.points[i].x() > 1.8) floor[i] = 0.2;
  const auto plain = envelope::adaptive_rho(s.points, lfs, o);
  const auto rho = envelope::adaptive_rho(s.points, lfs, o, floor);
  ASSERT_EQ(rho.size(), s.points.size());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const double x = s.points[i].x();
    EXPECT_GE(rho[i], floor[i]);
    EXPECT_GE(rho[i], plain[i]);
    if (x > 1.8) { EXPECT_DOUBLE_EQ(rho[i], 0.2) << "point " << i; }
    // 0.1 below the floor's value at slope 0.3 along paths: 0.1 / 0.3 = 0.33 from x = 1.8.
    if (x < 1.8 - 0.4) { EXPECT_DOUBLE_EQ(rho[i], plain[i]) << "point " << i; }
  }
  expect_lipschitz(s.points, rho, o.lipschitz);
  try {
    envelope::adaptive_rho(s.points, lfs, o, {1.0});
    FAIL() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "adaptive rho: 9000 points but 1 floor values");
  }
}

TEST(AdaptiveRho, rejects_rho_min_above_rho_max) {
  envelope::AdaptiveRhoOptions o;
  o.rho_min = 2.0;
  o.rho_max = 1.0;
  try {
    envelope::adaptive_rho({Point3(0, 0, 0)}, {1.0}, o);
    FAIL() << "no exception";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "AdaptiveRhoOptions::rho_min out of range (got 2)");
  }
}

TEST(Envelope, adaptive_rho_keeps_the_envelope_of_close_sheets_from_folding) {
  const auto s = two_close_sheets();
  envelope::EnvelopeOptions uniform;
  uniform.rho = 0.1;  // twice half the gap: the sheets' offsets cross each other
  uniform.spacing_rel_rho = 0.33;
  const auto folded = envelope::sample_envelope(s, uniform);
  EXPECT_TRUE(folded.local_rho.empty());
  EXPECT_GT(folded.dropped_too_close, folded.candidates / 10);

  envelope::EnvelopeOptions adaptive = uniform;
  adaptive.rho_mode = envelope::RhoMode::Adaptive;
  const auto e = envelope::sample_envelope(s, adaptive);
  ASSERT_EQ(e.local_rho.size(), s.points.size());
  EXPECT_DOUBLE_EQ(e.rho, 0.1);
  EXPECT_GE(e.rho_min, 0.25 * 0.1 - 1e-12);
  EXPECT_LT(e.rho_min, 0.03);
  for (const auto& w : e.warnings) EXPECT_EQ(w.find("may be too large"), std::string::npos) << w;
  // Every sample between the sheets keeps clear of both: its own rho is below half the gap.
  std::size_t between = 0;
  for (const auto& x : e.samples) {
    const double rho = std::sqrt(CGAL::squared_distance(x.position, x.generator));
    EXPECT_GE(rho, e.rho_min - 1e-12);
    EXPECT_LE(rho, e.rho + 1e-12);
    if (x.position.z() > 0.0 && x.position.z() < kGap && x.position.x() < 0.9) {
      ++between;
      EXPECT_LT(rho, kGap / 2);
    }
  }
  EXPECT_GT(between, 100u);
}
