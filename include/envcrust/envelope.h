// The rho-envelope E = {x : d(x, M) = rho} of a surface M with boundary: choice of rho from the
// reach of M, and a uniform sample of E tagged with what generated each point (docs/method.md §4-5).
#pragma once

#include "envcrust/types.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::envelope {

/// Samples of M with unit normal lines (their sign carries no meaning) and its boundary.
struct SurfaceSamples {
  std::vector<Point3> points;
  std::vector<Vector3> normals;        ///< one unit normal line per point
  std::vector<BoundaryCurve> boundary; ///< closed boundary loops with frames (t, n, c)
  /// Sharp creases of M (a mesh's edges bent by more than 80 degrees), as segments; empty
  /// for a smooth M. M has no reach there: the reach estimates leave out the pairs that may
  /// span a crease, and the sheet is joined across them (SheetOptions::crease_fold_min_angle_deg).
  std::vector<CreaseSegment> creases;
};

/// Envelope samples generated within this many rho of a crease: on the concave side the
/// offsets of the two sides meet there (candidates closer than rho to M are expected, not a
/// fold of the envelope), and samples either side of M make less than the sheet's angle
/// (extract::SheetOptions::crease_fold_reach_rel_rho). A crease bent by b moves the samples
/// of a generator up to rho / tan((180 - b) / 2) from it closer than rho to the other side:
/// 2 rho covers bends up to 127 degrees.
inline constexpr double kCreaseReachRelRho = 2.0;

/// Distance from a point to the nearest crease segment (a CGAL AABB tree); infinite when
/// there are none. Built eagerly: queries are safe from several threads at once.
class CreaseDistance {
 public:
  explicit CreaseDistance(const std::vector<CreaseSegment>& creases);
  ~CreaseDistance();
  CreaseDistance(const CreaseDistance&) = delete;
  CreaseDistance& operator=(const CreaseDistance&) = delete;
  [[nodiscard]] bool empty() const { return tree_ == nullptr; }
  [[nodiscard]] double operator()(const Point3& p) const;
  /// The wedge bisector of the segment nearest p (CreaseSegment::wedge). @pre !empty()
  [[nodiscard]] Vector3 nearest_wedge(const Point3& p) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

/// Estimate of the reach R of M (distance from M to its medial axis) by Federer's formula
/// R = inf |q - p|^2 / (2 dist(q - p, Tan_p)) over sample pairs (docs/method.md §4.1).
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
  /// point clouds with noise want a small positive quantile (docs/method.md §4.3: 5th percentile).
  /// Points that no pair constrains count as infinite (the flat, convex part): measured on a
  /// 10k-point file of the square, leaving them out took the quantile among the few rim
  /// points left and gave rho 0.031 instead of the cap 0.141.
  double quantile = 0.0;
  /// Pairs closer than this are ignored. Estimated normals are off by a few degrees, and a
  /// pair at distance d then reads d / (2 error) whatever the curvature: skip pairs shorter
  /// than a few sample spacings. 0 for exact normals.
  double min_pair_distance = 0.0;
  /// A pair of length L counts only when L >= this times the value R it reads. A circle of
  /// radius R has chords of every length up to 2R, all reading R, so 0.5 keeps the curvature
  /// (chords from R/2 to 2R) while a wiggle of amplitude a, which reads L^2 / (2a), counts
  /// only for chords shorter than 4a: the noise of an estimated boundary curve or of the
  /// samples (a ~ sigma) stops setting the reach, whatever the density. Range [0, 2]; 0 off.
  double min_chord_rel_value = 0.5;
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

/// Options of estimate_local_reach.
struct LocalReachOptions {
  /// Pairs farther apart than this are not examined (absolute units, > 0). A pair at distance
  /// d reads at least d / 2, so values above radius / 2 are not seen: pass twice the largest
  /// reach that matters (adaptive rho: 2 rho_max / rho_rel_lfs).
  double search_radius = 1.0;
  /// Shorter pairs are skipped unless they cross to another sheet (see crossing_min_cos):
  /// estimated normals and noise make short same-sheet pairs read far too small (see
  /// ReachOptions::min_pair_distance). Absolute units, >= 0.
  double min_pair_distance = 0.0;
  /// A short pair still counts when |(q - p) . n_p| >= this * |q - p|: a chord nearly along the
  /// normal goes to a facing sheet (a gap between toes), which is the feature to resolve, and
  /// reads at most |q - p| / (2 * this). Same-sheet neighbours have |cos| ~ the normal error.
  /// Range (0, 1]. 0.7: 45 degrees.
  double crossing_min_cos = 0.7;
  /// The per-sample value is the median over this many nearest samples (itself included) of
  /// their smallest pair values, which drops single outlier pairs. >= 1.
  int smoothing_neighbors = 8;
};

/// Per-sample local reach (feature size): Federer's value |q - p|^2 / (2 |(q - p) . n_p|)
/// minimised over the samples q within the search radius (docs/method.md §4.4), median-smoothed over
/// neighbours; infinite where no pair reads below half the search radius (a flat piece, or a
/// reach beyond what was asked for). One value per point.
/// @throws InvalidInput on mismatched sizes; InvalidOptions on an option out of range.
std::vector<double> estimate_local_reach(const SurfaceSamples& samples, const LocalReachOptions& options = {});

/// Options of adaptive_rho.
struct AdaptiveRhoOptions {
  double rho_rel_lfs = 0.5;      ///< alpha of rho(p) = alpha lfs(p) (docs/method.md §4.4), (0, 1)
  double rho_min = 0.0;          ///< lower clamp (absolute, >= 0)
  double rho_max = 1.0;          ///< upper clamp (absolute, > 0, >= rho_min)
  /// Lipschitz constant L of the result over the k-nearest-neighbour graph: rho(p) <=
  /// rho(q) + L |p - q| (docs/method.md §4.4: 0.3; |grad rho| < 1 keeps M the inner medial axis).
  /// Range [0, 1).
  double lipschitz = 0.3;
  int neighbors = 12;            ///< k of the graph the Lipschitz bound is enforced on, >= 1
};

/// rho(p) = clamp(alpha lfs(p), rho_min, rho_max), then made L-Lipschitz by a Dijkstra pass
/// rho(p) <- min_q rho(q) + L |p - q| over the kNN graph (it only lowers values; the result
/// stays >= rho_min). With a `floor` (one value per point, e.g. what the local sample gaps
/// need), rho is then raised to the smallest L-Lipschitz function above the floor where that
/// is larger (also beyond rho_max): the result stays L-Lipschitz.
/// @param lfs one value per point (infinite allowed).
/// @throws InvalidInput on mismatched sizes; InvalidOptions on an option out of range.
std::vector<double> adaptive_rho(const std::vector<Point3>& points, const std::vector<double>& lfs,
                                 const AdaptiveRhoOptions& options = {}, const std::vector<double>& floor = {});

/// How rho is chosen along M.
enum class RhoMode : std::uint8_t {
  Uniform,   ///< one rho everywhere (EnvelopeOptions::rho or automatic)
  Adaptive   ///< rho(p) from the local reach, at most the uniform rho (the paper's foot, §4.2)
};

/// Which part of E a sample lies on.
enum class EnvelopePart : std::uint8_t {
  Sheet,   ///< p +- rho n(p)
  Rim,     ///< half-tube b + rho (cos theta n + sin theta c) around a boundary point b
  Corner   ///< spherical lune at a convex boundary corner
};

/// One envelope sample with its tags (what the extraction relies on, docs/method.md §5.1).
struct EnvelopeSample {
  Point3 position;
  Point3 generator;      ///< g in M with position = g + rho * direction
  Vector3 direction;     ///< unit offset direction u
  EnvelopePart part = EnvelopePart::Sheet;
  int curve = -1;        ///< boundary curve id for Rim/Corner samples
};

/// Options of sample_envelope.
struct EnvelopeOptions {
  /// Envelope radius; nullopt: 0.5 * reach (docs/method.md §2.2: lfs of E is then rho everywhere).
  std::optional<double> rho;
  /// Fraction of the reach used when rho is chosen automatically. Range (0, 1).
  double rho_rel_reach = 0.5;
  /// Automatic rho is at least this many times the estimated noise (estimate_noise): the
  /// envelope of noisy samples keeps its sheets only where rho clears the noise. Measured on
  /// the trefoil ribbon at 10k points and sigma 0.25% of the diagonal: rho = 2.9 sigma left
  /// no sheet, 3.0 and 4.2 sigma gave the right topology. Range >= 0 (0 disables).
  double min_rho_rel_noise = 4.0;
  /// Automatic rho is at least this quantile of the samples' r_k (distance to the 8th
  /// nearest other sample) divided by 2.5, the widest gap an envelope of rho bridges: below
  /// that the envelope of the sparser samples falls apart into holes, and its samples (which
  /// grow as 1 / rho^2) can outnumber the input fiftyfold. The reach bound (rho <= reach / 2)
  /// is then given up where the two conflict: an input too sparse for its own thin parts
  /// gets folds there (handles, cross-caps: SheetOptions' cuts repair them) instead of holes
  /// everywhere. A quantile, not the largest gap: one stray sample would set it. Measured:
  /// 0.99 raises the automatic rho of the lion head (0.014 -> 0.025) and of the face scan
  /// and of no other scan of the development set nor any built-in surface at 10k samples.
  /// Range [0, 1]; 0 disables.
  double gap_quantile = 0.99;
  /// Cap of the reach used for automatic rho, as a fraction of the bounding-box diagonal
  /// (a flat square has infinite reach; the envelope must still resolve the shape).
  double max_reach_rel_diag = 0.1;
  /// Cap of the reach used for automatic rho, as a multiple of the surface's half-width (the
  /// largest distance from a sample to its boundary curves; no cap without curves): the sheet
  /// of a strip narrower than a few envelope spacings cannot be extracted, however flat it
  /// is (its reach is infinite). Measured on a 100 x 0.5 strip of 20,000 random samples
  /// (half-width 0.25): rho 0.05 to 1.5 gave the strip as one disc, 2.5 tore it into 20
  /// pieces, and the automatic rho was 5 (half of 10% of the diagonal) before this cap; at
  /// 2 the automatic rho is at most the half-width, 8 envelope spacings across the strip.
  /// Range > 0.
  double max_reach_rel_half_width = 2.0;
  /// Quantile of the per-sample reach values used for automatic rho: 0 (the minimum) for
  /// exact normals; estimated normals want 0.05 (docs/method.md §4.3). Range [0, 1).
  double reach_quantile = 0.0;
  /// Pairs closer than this many average sample spacings are ignored by the automatic reach
  /// (ReachOptions::min_pair_distance): noise of sigma makes a pair at distance d read about
  /// d^2 / (2 sigma), and a normal error e reads d / (2 e), whatever the curvature. Chords
  /// longer than that still see the curvature exactly. Range >= 0.
  double reach_min_pair_rel_spacing = 4.0;
  /// Poisson-disk radius h of the envelope samples as a fraction of rho. The extraction
  /// needs cells spanning the shell with small lateral offset: 0.33 worked, 0.5 broke
  /// (docs/method.md §5.2); 0.25 gives a sheet error of rho/64 (§2.4). Range (0, 4]: above 1 the
  /// envelope is sampled sparser than its own radius, which only experiments ask for (the
  /// unknot-radius sweep at a fixed absolute spacing).
  double spacing_rel_rho = 0.25;
  /// Drop samples that come closer than this fraction of rho to the input samples: they are
  /// not on the envelope (docs/method.md §5.3: 0.9 for sheets; rims use `rim_clearance`).
  double sheet_clearance = 0.9;
  double rim_clearance = 0.97;   ///< same for rim and corner samples
  /// Warn that rho may be too large when more than this fraction of the sheet candidates come
  /// closer to the input than sheet_clearance rho minus 3 times the estimated noise. A rho
  /// beyond the reach folds a whole side of the envelope (about half the candidates: 50% on a
  /// cylinder at rho 1.5, a torus at rho 0.45), or part of it (unknot ribbon at 1.5 times its
  /// reach: 6.6%, output 5.7% off); normal errors at sharp features drop a few percent with a
  /// sound result (foot mesh: 2.3%; foot scan 4.0%). Range (0, 1].
  double fold_warning_fraction = 0.05;
  std::uint64_t seed = 1;        ///< shuffling of the Poisson-disk thinning
  /// Uniform, or Adaptive: the uniform rho (given or automatic) becomes rho_max, and each
  /// sample gets adaptive_rho(estimate_local_reach) clamped to [adaptive_min_rel_rho rho_max,
  /// rho_max] (and above the noise floor); spacing, rims and clearance follow the local rho.
  RhoMode rho_mode = RhoMode::Uniform;
  /// Adaptive mode: lower clamp as a fraction of rho_max, (0, 1]. 0.25: the extraction needs
  /// envelope samples at 0.25 rho, so a smaller rho costs (rho_max / rho)^2 more samples.
  double adaptive_min_rel_rho = 0.25;
  /// Adaptive mode: alpha and L of adaptive_rho (docs/method.md §4.4: 0.5 and 0.3).
  double adaptive_rho_rel_lfs = 0.5;
  double adaptive_lipschitz = 0.3;
  /// Adaptive mode: rho also grows with the local spacing, to at least the median over each
  /// sample's 9 nearest of r_k / 2.5 (the gap the envelope must bridge there; adaptive_rho's
  /// floor), also beyond the uniform rho: an input whose density varies keeps its envelope
  /// closed where it is sparse. False: rho only shrinks with the local feature size.
  bool adaptive_gap_floor = true;
};

/// The sampled envelope.
struct EnvelopeSamples {
  std::vector<EnvelopeSample> samples;
  double rho = 0.0;                ///< the uniform rho; in adaptive mode the largest local rho
  double spacing = 0.0;            ///< Poisson-disk radius h actually used (at rho)
  /// Adaptive mode: rho per surface sample (same order as SurfaceSamples::points); empty in
  /// uniform mode. The envelope sample made from sample i lies at local_rho[i] from M.
  std::vector<double> local_rho;
  double rho_min = 0.0;            ///< smallest local rho (= rho in uniform mode)
  ReachEstimate reach;             ///< when rho was chosen automatically
  double noise = 0.0;              ///< estimate_noise of the samples
  bool is_rho_noise_bound = false; ///< automatic rho was raised to min_rho_rel_noise * noise
  bool is_rho_gap_bound = false;   ///< automatic rho was raised to bridge the input's gaps (gap_quantile)
  /// Automatic rho was set by the surface's half-width (max_reach_rel_half_width), not by the
  /// reach or the diagonal (then raised for noise or gaps, if one of those flags is set).
  bool is_rho_width_bound = false;
  /// Automatic rho: the largest distance from a sample to the nearest boundary-curve vertex
  /// (infinite without curves; 0 when rho was given).
  double half_width = 0.0;
  /// Automatic rho, raised for gaps or noise, came out above max_reach_rel_diag of the
  /// diagonal: the envelope cannot resolve the input's shape (a warning says so).
  bool is_input_too_sparse = false;
  std::size_t candidates = 0;      ///< before thinning
  std::size_t dropped_too_close = 0;  ///< candidates nearer than the clearance to M
  double input_coverage = 0.0;     ///< largest gap of the input samples seen by the sheets
  /// Per input sample, the distance to its 8th nearest other sample (r_k of the sheet
  /// candidates; input_coverage is the largest). The extraction reuses it.
  std::vector<double> input_neighbour_distance;
  /// Per input sample, the distance to its nearest other sample (same search as r_k); the
  /// extraction's component filter reuses it.
  std::vector<double> input_nearest_distance;
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
