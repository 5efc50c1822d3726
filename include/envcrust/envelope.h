// The rho-envelope E = {x : d(x, M) = rho} of a surface M with boundary: choice of rho from the
// reach of M, and a uniform sample of E tagged with what generated each point (METHOD.md §2-3).
#pragma once

#include "envcrust/types.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::envelope {

/// Samples of M with unit normal lines (their sign carries no meaning) and its boundary.
struct SurfaceSamples {
  std::vector<Point3> points;
  std::vector<Vector3> normals;        ///< one unit normal line per point
  std::vector<BoundaryCurve> boundary; ///< closed boundary loops with frames (t, n, c)
};

/// Estimate of the reach R of M (distance from M to its medial axis) by Federer's formula
/// R = inf |q - p|^2 / (2 dist(q - p, Tan_p)) over sample pairs (METHOD.md §2).
struct ReachEstimate {
  double reach = 0.0;              ///< R-hat
  double curvature_radius = 0.0;   ///< smallest value over near pairs (~ 1 / kappa_max)
  double bottleneck = 0.0;         ///< smallest value over far pairs (~ Delta / 2)
  std::size_t pairs_examined = 0;
};

/// Options of estimate_reach.
struct ReachOptions {
  std::size_t max_points = 4000;  ///< random subsample size (pairs are examined all-to-all)
  /// Quantile of the per-point values taken as R-hat: 0 takes the minimum (exact samples);
  /// point clouds with noise want a small positive quantile (METHOD.md §2: 5th percentile).
  double quantile = 0.0;
  /// Pairs closer than this are ignored. Estimated normals are off by a few degrees, and a
  /// pair at distance d then reads d / (2 error) whatever the curvature: skip pairs shorter
  /// than a few sample spacings. 0 for exact normals.
  double min_pair_distance = 0.0;
  std::uint64_t seed = 1;
};

/// Values are infinite when no pair constrains them (a flat convex piece has infinite reach).
/// @throws InvalidInput when points and normals differ in size or fewer than 3 points.
ReachEstimate estimate_reach(const SurfaceSamples& samples, const ReachOptions& options = {});

/// Options of estimate_noise.
struct NoiseOptions {
  int neighbors = 16;             ///< points per plane fit (the point itself included), >= 4
  std::size_t max_points = 4000;  ///< fits on an even stride of at most this many points
};

/// Noise level sigma-hat of a sample: the median over points of the RMS distance of their
/// k nearest neighbours to the plane fitted through them. Gaussian noise of sigma along the
/// normal reads about 0.8 sigma with k = 16 (the fit absorbs 3 of the 16 degrees of freedom,
/// and the median lies below the mean); exact samples read the curvature term
/// ~ kappa r^2 / 8 over a neighbourhood of radius r (tiny at usual densities).
/// @throws InvalidOptions on neighbors < 4; InvalidInput with fewer than 4 points.
double estimate_noise(const std::vector<Point3>& points, const NoiseOptions& options = {});

/// Which part of E a sample lies on.
enum class EnvelopePart : std::uint8_t {
  Sheet,   ///< p +- rho n(p)
  Rim,     ///< half-tube b + rho (cos theta n + sin theta c) around a boundary point b
  Corner   ///< spherical lune at a convex boundary corner
};

/// One envelope sample with its tags (what METHOD.md §5c1 relies on).
struct EnvelopeSample {
  Point3 position;
  Point3 generator;      ///< g in M with position = g + rho * direction
  Vector3 direction;     ///< unit offset direction u
  EnvelopePart part = EnvelopePart::Sheet;
  int curve = -1;        ///< boundary curve id for Rim/Corner samples
};

/// Options of sample_envelope.
struct EnvelopeOptions {
  /// Envelope radius; nullopt: 0.5 * reach (METHOD.md F2: lfs of E is then rho everywhere).
  std::optional<double> rho;
  /// Fraction of the reach used when rho is chosen automatically. Range (0, 1).
  double rho_rel_reach = 0.5;
  /// Automatic rho is at least this many times the estimated noise (estimate_noise): the
  /// envelope of noisy samples keeps its sheets only where rho clears the noise. Measured on
  /// the trefoil ribbon at 10k points and sigma 0.25% of the diagonal: rho = 2.9 sigma left
  /// no sheet, 3.0 and 4.2 sigma gave the right topology. Range >= 0 (0 disables).
  double min_rho_rel_noise = 4.0;
  /// Cap of the reach used for automatic rho, as a fraction of the bounding-box diagonal
  /// (a flat square has infinite reach; the envelope must still resolve the shape).
  double max_reach_rel_diag = 0.1;
  /// Quantile of the per-sample reach values used for automatic rho: 0 (the minimum) for
  /// exact normals; estimated normals want 0.05 (METHOD.md §2). Range [0, 1).
  double reach_quantile = 0.0;
  /// Pairs closer than this many average sample spacings are ignored by the automatic reach
  /// (ReachOptions::min_pair_distance): noise of sigma makes a pair at distance d read about
  /// d^2 / (2 sigma), and a normal error e reads d / (2 e), whatever the curvature. Chords
  /// longer than that still see the curvature exactly. Range >= 0.
  double reach_min_pair_rel_spacing = 4.0;
  /// Poisson-disk radius h of the envelope samples as a fraction of rho. The extraction
  /// needs cells spanning the shell with small lateral offset: 0.33 worked, 0.5 broke
  /// (METHOD.md §3.2); 0.25 gives a sheet error of rho/64 (F4). Range (0, 1].
  double spacing_rel_rho = 0.25;
  /// Drop samples that come closer than this fraction of rho to the input samples: they are
  /// not on the envelope (METHOD.md probe: 0.9 for sheets; rims use `rim_clearance`).
  double sheet_clearance = 0.9;
  double rim_clearance = 0.97;   ///< same for rim and corner samples
  std::uint64_t seed = 1;        ///< shuffling of the Poisson-disk thinning
};

/// The sampled envelope.
struct EnvelopeSamples {
  std::vector<EnvelopeSample> samples;
  double rho = 0.0;
  double spacing = 0.0;            ///< Poisson-disk radius h actually used
  ReachEstimate reach;             ///< when rho was chosen automatically
  double noise = 0.0;              ///< estimate_noise of the samples
  bool is_rho_noise_bound = false; ///< automatic rho was raised to min_rho_rel_noise * noise
  std::size_t candidates = 0;      ///< before thinning
  std::size_t dropped_too_close = 0;  ///< candidates nearer than the clearance to M
  double input_coverage = 0.0;     ///< largest gap of the input samples seen by the sheets
  /// Smallest rho whose envelope bridges the largest gap (input_coverage / 2.5); a smaller rho
  /// leaves holes, and a warning says which rho or which input spacing would work.
  double min_rho_for_gaps = 0.0;
  std::vector<std::string> warnings;
  [[nodiscard]] std::vector<Point3> points() const;
};

/// Sample the rho-envelope of M from its samples and boundary curves: sheet candidates
/// p +- rho n, rim half-circles, corner lunes, then one global Poisson-disk thinning.
/// @throws InvalidInput on mismatched sizes or an empty sample.
/// @throws InvalidOptions on an option out of range (names field and value).
EnvelopeSamples sample_envelope(const SurfaceSamples& surface, const EnvelopeOptions& options = {});

}  // namespace envcrust::envelope
