// Tests of reach estimation and envelope sampling on built-in surfaces with exact normals.
#include "envcrust/distance.h"
#include "envcrust/envelope.h"
#include "envcrust/errors.h"
#include "envcrust/surfaces.h"
#include "fixtures/surface_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace envcrust;

namespace {

envelope::SurfaceSamples exact_samples(const std::string& name, std::size_t n, std::uint64_t seed = 1) {
  return fixtures::builtin_samples(name, n, 0.0, seed, 0.01);
}

// Distance from x to the open cylinder of radius 1, z in [-1, 1].
double distance_to_cylinder(const Point3& x) {
  const double r = std::hypot(x.x(), x.y());
  const double dz = std::max(0.0, std::abs(x.z()) - 1.0);
  return std::hypot(r - 1.0, dz);
}

}  // namespace

TEST(Reach, sphere_reach_is_its_radius) {
  const auto r = envelope::estimate_reach(exact_samples("sphere", 5000));
  EXPECT_NEAR(r.reach, 1.0, 0.02);
}

TEST(Reach, cylinder_reach_is_limited_by_curvature_one) {
  const auto r = envelope::estimate_reach(exact_samples("cylinder", 5000));
  EXPECT_NEAR(r.reach, 1.0, 0.03);
}

TEST(Reach, trefoil_ribbon_reach_is_limited_by_the_strand_gap) {
  // Strands of the ribbon pass 1.452 - 0.5 = 0.952 apart above each other at the crossings of
  // the projection, so the bottleneck Delta/2 is about 0.476, below the curvature radius 1.
  const auto r = envelope::estimate_reach(exact_samples("trefoil-ribbon", 8000));
  EXPECT_LT(r.reach, 0.5);
  EXPECT_GT(r.reach, 0.4);
  EXPECT_NEAR(r.bottleneck, r.reach, 1e-12);
}

TEST(Reach, wiggles_of_an_estimated_boundary_curve_do_not_set_the_reach) {
  // The cylinder's rims moved out along their conormals by a (1 + sin(2 pi arc / lambda)), as
  // a boundary detected on a dense point file wiggles (out: samples beyond a curve are a true
  // bound on the reach), with the tangents and conormals of the wiggly curve: the wiggle's own
  // curvature radius is lambda^2 / (4 pi^2 a) = 0.46, while the rims' true one is 1. Short
  // chords of the wiggle (L < 8 a) are the only ones that read it.
  auto samples = exact_samples("cylinder", 5000);
  const double a = 0.005, lambda = 0.3;
  for (auto& curve : samples.boundary) {
    auto& v = curve.vertices;
    const std::size_t m = v.size();
    double arc = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      if (k > 0) arc += std::sqrt(CGAL::squared_distance(v[k - 1].position, v[k].position));
      v[k].position = v[k].position + a * (1 + std::sin(2 * std::acos(-1.0) * arc / lambda)) * v[k].conormal;
    }
    for (std::size_t k = 0; k < m; ++k) {
      Vector3 t = v[(k + 1) % m].position - v[(k + m - 1) % m].position;
      t = t / std::sqrt(t.squared_length());
      Vector3 c = CGAL::cross_product(t, v[k].normal);
      if (c * v[k].conormal < 0) c = -c;
      v[k].tangent = t;
      v[k].conormal = c / std::sqrt(c.squared_length());
    }
  }
  const auto r = envelope::estimate_reach(samples);
  EXPECT_GT(r.reach, 0.9);
  EXPECT_LT(r.reach, 1.03);
  envelope::ReachOptions every_chord;
  every_chord.min_chord_rel_value = 0.0;
  EXPECT_LT(envelope::estimate_reach(samples, every_chord).reach, 0.6);
}

TEST(Reach, refuses_a_chord_bound_out_of_range) {
  const auto samples = exact_samples("sphere", 100);
  envelope::ReachOptions o;
  o.min_chord_rel_value = -0.5;
  EXPECT_THROW(envelope::estimate_reach(samples, o), InvalidOptions);
  o.min_chord_rel_value = 2.5;
  EXPECT_THROW(envelope::estimate_reach(samples, o), InvalidOptions);
}

TEST(Envelope, cylinder_samples_lie_on_the_envelope_and_cover_it) {
  const auto s = exact_samples("cylinder", 10000);
  envelope::EnvelopeOptions o;
  o.rho = 0.2;
  const auto e = envelope::sample_envelope(s, o);
  EXPECT_DOUBLE_EQ(e.rho, 0.2);
  EXPECT_DOUBLE_EQ(e.spacing, 0.05);
  ASSERT_GT(e.samples.size(), 1000u);
  double worst = 0.0;
  std::size_t rims = 0;
  for (const auto& x : e.samples) {
    const double err = std::abs(distance_to_cylinder(x.position) - 0.2);
    worst = std::max(worst, err);
    if (x.part == envelope::EnvelopePart::Rim) ++rims;
  }
  // Tangent-disk generators leave the surface by kappa r_k^2 / 2: r_k (8th neighbour of 10k
  // random points) reaches 0.08 here, so up to 0.0032, a little more on the inner sheet.
  EXPECT_LT(worst, 0.03 * 0.2);
  EXPECT_GT(rims, 100u);
  // Coverage: points on the true envelope are within ~h of a sample.
  std::vector<Point3> truth;
  for (int i = 0; i < 400; ++i) {
    const double a = 2 * 3.141592653589793 * i / 400;
    for (int j = 0; j <= 20; ++j) {
      const double z = -1 + 2.0 * j / 20;
      truth.emplace_back(1.2 * std::cos(a), 1.2 * std::sin(a), z);
      truth.emplace_back(0.8 * std::cos(a), 0.8 * std::sin(a), z);
    }
    for (int j = 0; j <= 10; ++j) {  // top rim half-circle
      const double t = 3.141592653589793 * j / 10;
      const double r = 1 + 0.2 * std::cos(t);
      truth.emplace_back(r * std::cos(a), r * std::sin(a), 1 + 0.2 * std::sin(t));
    }
  }
  const auto gap = distance::points_to_points(truth, e.points());
  EXPECT_LT(gap.max, 1.3 * e.spacing);
  // Poisson disk: no two samples closer than h.
  const auto self = e.points();
  for (std::size_t i = 0; i < self.size(); i += 97) {
    for (std::size_t j = 0; j < self.size(); ++j) {
      if (i != j) {
        ASSERT_GE(CGAL::squared_distance(self[i], self[j]), 0.05 * 0.05 * (1 - 1e-12));
      }
    }
  }
  EXPECT_TRUE(e.warnings.empty());
}

TEST(Envelope, automatic_rho_is_half_the_reach_capped_by_the_size) {
  const auto e = envelope::sample_envelope(exact_samples("cylinder", 5000));
  // Reach 1, cap 0.1 * diag = 0.346: rho = 0.173.
  EXPECT_NEAR(e.rho, 0.5 * 0.1 * std::sqrt(12.0), 1e-3);  // diag of the samples
  const auto torus = envelope::sample_envelope(exact_samples("torus", 8000));
  EXPECT_NEAR(torus.rho, 0.5 * 0.4, 0.02);  // torus tube radius 0.4 limits the reach
}

TEST(Envelope, too_large_rho_is_reported) {
  envelope::EnvelopeOptions o;
  o.rho = 1.5;  // beyond the cylinder's reach 1: the inner sheet folds through the axis
  const auto e = envelope::sample_envelope(exact_samples("cylinder", 3000), o);
  ASSERT_FALSE(e.warnings.empty());
  EXPECT_EQ(e.warnings[0].rfind("rho 1.5 may be too large:", 0), 0u) << e.warnings[0];
  // The cylinder's diagonal is 2 sqrt(3) = 3.46: rho 1.5 is more than a quarter of it.
  ASSERT_EQ(e.warnings.size(), 2u);
  EXPECT_EQ(e.warnings[1].rfind("rho 1.5 is more than a quarter of the input's diagonal (3.46", 0), 0u) << e.warnings[1];
  EXPECT_NE(e.warnings[1].find("): the envelope rounds off the whole shape, and the result may not resemble the input"),
            std::string::npos) << e.warnings[1];
  o.rho = 0.8;  // below a quarter: no such warning
  for (const auto& w : envelope::sample_envelope(exact_samples("cylinder", 3000), o).warnings)
    EXPECT_EQ(w.find("quarter"), std::string::npos) << w;
}

TEST(Envelope, bad_options_and_inputs_are_refused) {
  envelope::EnvelopeOptions o;
  o.spacing_rel_rho = 0;
  try {
    envelope::sample_envelope(exact_samples("sphere", 100), o);
    FAIL();
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "EnvelopeOptions::spacing_rel_rho out of range (got 0)");
  }
  envelope::SurfaceSamples bad{{Point3(0, 0, 0)}, {}, {}, {}};
  try {
    envelope::sample_envelope(bad);
    FAIL();
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "envelope: 1 points but 0 normals");
  }
}

// Gaussian noise of sigma along the normal of a plane: each fit over k = 16 neighbours
// removes 3 degrees of freedom (RMS residual sqrt(13/16) sigma = 0.90 sigma on average), and
// the median of the per-point RMS lies below their mean: about 0.8 sigma.
TEST(Noise, reads_the_sigma_of_noise_across_a_plane) {
  std::mt19937_64 rng(7);
  std::printf("seed 7\n");
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 0.004);
  std::vector<Point3> points;
  for (int i = 0; i < 20000; ++i) points.emplace_back(u(rng), u(rng), g(rng));
  const double sigma = envelope::estimate_noise(points);
  EXPECT_GT(sigma, 0.70 * 0.004);
  EXPECT_LT(sigma, 0.90 * 0.004);
}

// Exact samples of a unit sphere: only the curvature term ~ r^2 / 8 over neighbourhoods of
// radius r ~ 0.05 at 10k points is left, far below any noise that matters.
TEST(Noise, is_near_zero_on_exact_samples) {
  const auto s = exact_samples("sphere", 10000);
  EXPECT_LT(envelope::estimate_noise(s.points), 1e-3);
}

TEST(Noise, refuses_bad_options_and_tiny_inputs) {
  const std::vector<Point3> three{Point3(0, 0, 0), Point3(1, 0, 0), Point3(0, 1, 0)};
  try {
    envelope::estimate_noise(three);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_STREQ(e.what(), "noise: need at least 4 points");
  }
  try {
    envelope::estimate_noise(exact_samples("sphere", 100).points, {.neighbors = 3});
    FAIL() << "expected InvalidOptions";
  } catch (const InvalidOptions& e) {
    EXPECT_STREQ(e.what(), "NoiseOptions::neighbors must be at least 4 (got 3)");
  }
}

// The automatic rho clears the noise: at sigma 0.25% of the diagonal the reach of noisy
// pairs alone would give rho below 3 sigma, where the envelope sheets vanish.
TEST(Envelope, automatic_rho_is_at_least_four_times_the_noise) {
  auto s = fixtures::builtin_samples("trefoil-ribbon", 10000, 0.0025, 1);
  s.boundary.clear();  // the noise floor does not depend on the boundary
  const auto env = envelope::sample_envelope(s);
  EXPECT_GE(env.rho, 4.0 * env.noise * (1 - 1e-12));
  const double sigma = 0.0025 * surfaces::bbox_diagonal(*surfaces::make_builtin("trefoil-ribbon"));
  EXPECT_NEAR(env.noise, 0.8 * sigma, 0.1 * sigma);
}

// 300 samples of the cylinder are sparse for rho = 0.173 (half the capped reach): the gaps
// between 1% of them and their 8th neighbours are wider than 2.5 rho, so the automatic rho
// rises to bridge them, to the 99th percentile of r_k over 2.5, computed here by brute force.
TEST(Envelope, automatic_rho_bridges_the_gaps_of_a_sparse_input) {
  const auto s = exact_samples("cylinder", 300);
  std::vector<double> rk;
  for (const auto& p : s.points) {
    std::vector<double> d;
    for (const auto& q : s.points) d.push_back(std::sqrt(CGAL::squared_distance(p, q)));
    std::sort(d.begin(), d.end());
    rk.push_back(d[8]);  // d[0] is the point itself
  }
  std::sort(rk.begin(), rk.end());
  const double expected = rk[static_cast<std::size_t>(0.99 * rk.size())] / 2.5;
  ASSERT_GT(expected, 0.5 * 0.1 * std::sqrt(12.0));
  const auto e = envelope::sample_envelope(s);
  EXPECT_TRUE(e.is_rho_gap_bound);
  EXPECT_DOUBLE_EQ(e.rho, expected);
  ASSERT_FALSE(e.warnings.empty());
  EXPECT_EQ(e.warnings[0].rfind("rho raised from 0.173", 0), 0u) << e.warnings[0];
  EXPECT_NE(e.warnings[0].find("to bridge the gaps between 99% of the samples and their 8th neighbours"), std::string::npos);

  envelope::EnvelopeOptions off;
  off.gap_quantile = 0;
  EXPECT_NEAR(envelope::sample_envelope(s, off).rho, 0.5 * 0.1 * std::sqrt(12.0), 1e-3);
  // Dense samples keep half the reach.
  const auto dense = envelope::sample_envelope(exact_samples("cylinder", 5000));
  EXPECT_FALSE(dense.is_rho_gap_bound);
}

// 60 samples of the cylinder need a rho of about a sixth of its diagonal to bridge their gaps
// (their plane fits also read the curvature as noise): more than the 10% the envelope
// resolves, which the warning says, with a sample count that would do. 1.3 times that count
// is no longer too sparse; 300 samples never were.
TEST(Envelope, an_input_too_sparse_for_its_size_is_reported_with_the_count_that_would_do) {
  const auto sparse = envelope::sample_envelope(exact_samples("cylinder", 60));
  ASSERT_TRUE(sparse.is_input_too_sparse);
  const auto w = std::find_if(sparse.warnings.begin(), sparse.warnings.end(),
                              [](const std::string& s) { return s.rfind("the input is too sparse", 0) == 0; });
  ASSERT_NE(w, sparse.warnings.end()) << sparse.warnings.size() << ": " << sparse.warnings.back();
  EXPECT_NE(w->find("% of its diagonal (the envelope resolves shapes down to about 2 rho; at most 10% is trusted): "
                    "the result may be rounded, closed or empty; about "),
            std::string::npos)
      << *w;
  const auto at = w->find("; about ") + 8;
  const double count = std::stod(w->substr(at));
  EXPECT_NE(w->find(" samples, evenly spread, would bridge the gaps with rho at 10%", at), std::string::npos) << *w;
  EXPECT_GT(count, 60);
  EXPECT_LT(count, 600);
  EXPECT_FALSE(envelope::sample_envelope(exact_samples("cylinder", static_cast<std::size_t>(1.3 * count))).is_input_too_sparse);
  EXPECT_FALSE(envelope::sample_envelope(exact_samples("cylinder", 300)).is_input_too_sparse);
  // A rho given explicitly is the user's choice: no such warning.
  envelope::EnvelopeOptions given;
  given.rho = 0.6;
  EXPECT_FALSE(envelope::sample_envelope(exact_samples("cylinder", 60), given).is_input_too_sparse);
}

TEST(CreaseDistance, is_the_distance_to_the_nearest_segment_and_infinite_without_any) {
  const Vector3 any(0, 0, 1);
  const envelope::CreaseDistance creases({{Point3(0, 0, 0), Point3(1, 0, 0), any},
                                          {Point3(0, 2, 0), Point3(0, 3, 0), any},
                                          {Point3(5, 5, 5), Point3(5, 5, 5), any}});  // a point: left out
  EXPECT_NEAR(creases(Point3(0.5, 0.3, 0.4)), 0.5, 1e-12);  // square to the first segment
  EXPECT_NEAR(creases(Point3(-3, 0, 4)), 5.0, 1e-12);       // beyond its end
  EXPECT_NEAR(creases(Point3(0, 2.5, 0.1)), 0.1, 1e-12);
  EXPECT_NEAR(creases(Point3(5, 5, 5.5)), std::hypot(5.0, 2.0, 5.5), 1e-12);  // to (0, 3, 0)
  const envelope::CreaseDistance none({});
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(std::isinf(none(Point3(0, 0, 0))));
}

TEST(Reach, pairs_across_a_crease_read_the_crease_not_the_reach) {
  // Two flat unit squares meeting at a right angle along the y axis: M's reach is 0 at the
  // crease, and a pair either side of it, at distance e from it, reads about e. Told where the
  // crease is, the estimate keeps only pairs that cannot span it: the faces are flat and the
  // far pairs see no bottleneck, so no pair constrains the reach.
  envelope::SurfaceSamples samples;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 3000; ++i) {
    const double u = unit(rng), v = unit(rng);
    if (i % 2 == 0) {
      samples.points.emplace_back(-u, v, 0.0);
      samples.normals.emplace_back(0, 0, 1);
    } else {
      samples.points.emplace_back(0.0, v, u);
      samples.normals.emplace_back(1, 0, 0);
    }
  }
  const auto blind = envelope::estimate_reach(samples);
  EXPECT_LT(blind.reach, 0.02);
  samples.creases.push_back({Point3(0, 0, 0), Point3(0, 1, 0), Vector3(-std::sqrt(0.5), 0, std::sqrt(0.5))});
  const auto told = envelope::estimate_reach(samples);
  EXPECT_GT(told.reach, 50 * blind.reach);
}
