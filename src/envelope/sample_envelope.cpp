// sample_envelope: rho, candidates, clearance filter, one global Poisson-disk pass.
#include "envcrust/envelope.h"
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"

#include "envelope_candidates.h"
#include "input_tree.h"
#include "neighbour_median.h"
#include "poisson_disk.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace envcrust::envelope {
namespace {

constexpr double kCandidatesPerH2 = 12.0;  // docs/method.md §5.1: at least 10 per h^2
// Gaps of the input up to this many rho are bridged by the envelope's sheets. Measured on
// 2,000 cylinder samples (largest gap 0.241): holes join the inner and outer medial axes and
// the result is empty at rho = gap / 2.97, but not at gap / 2.98 or gap / 2.84 and above;
// 2.5 keeps a margin.
constexpr double kGapsPerRho = 2.5;
constexpr double kMaxRimCandidates = 1e7;  // measured: 7.9M (2,000 cylinder samples, rho 0.0009) peaked at 2.3 GB
constexpr double kRimStepRelH = 1.0 / 3.3;  // rims resampled so that ~10 candidates fall per h^2

std::string format(double x) {
  std::ostringstream s;
  s.precision(4);
  s << x;
  return s.str();
}

void validate(const SurfaceSamples& s, const EnvelopeOptions& o) {
  if (s.points.empty()) throw InvalidInput("envelope: no surface samples");
  if (s.points.size() != s.normals.size())
    throw InvalidInput("envelope: " + std::to_string(s.points.size()) + " points but " +
                       std::to_string(s.normals.size()) + " normals");
  auto check = [](bool ok, const std::string& field, double value) {
    if (!ok) throw InvalidOptions("EnvelopeOptions::" + field + " out of range (got " + format(value) + ")");
  };
  if (o.rho) check(*o.rho > 0 && std::isfinite(*o.rho), "rho", *o.rho);
  check(o.rho_rel_reach > 0 && o.rho_rel_reach < 1, "rho_rel_reach", o.rho_rel_reach);
  check(o.max_reach_rel_diag > 0, "max_reach_rel_diag", o.max_reach_rel_diag);
  check(o.max_reach_rel_half_width > 0, "max_reach_rel_half_width", o.max_reach_rel_half_width);
  check(o.spacing_rel_rho > 0 && o.spacing_rel_rho <= 4, "spacing_rel_rho", o.spacing_rel_rho);
  check(o.sheet_clearance > 0 && o.sheet_clearance <= 1, "sheet_clearance", o.sheet_clearance);
  check(o.rim_clearance > 0 && o.rim_clearance <= 1, "rim_clearance", o.rim_clearance);
  check(o.fold_warning_fraction > 0 && o.fold_warning_fraction <= 1, "fold_warning_fraction",
        o.fold_warning_fraction);
  check(o.min_rho_rel_noise >= 0, "min_rho_rel_noise", o.min_rho_rel_noise);
  check(o.reach_quantile >= 0 && o.reach_quantile < 1, "reach_quantile", o.reach_quantile);
  check(o.gap_quantile >= 0 && o.gap_quantile <= 1, "gap_quantile", o.gap_quantile);
  check(o.reach_min_pair_rel_spacing >= 0, "reach_min_pair_rel_spacing", o.reach_min_pair_rel_spacing);
  check(o.adaptive_min_rel_rho > 0 && o.adaptive_min_rel_rho <= 1, "adaptive_min_rel_rho", o.adaptive_min_rel_rho);
  check(o.adaptive_rho_rel_lfs > 0 && o.adaptive_rho_rel_lfs < 1, "adaptive_rho_rel_lfs", o.adaptive_rho_rel_lfs);
  check(o.adaptive_lipschitz >= 0 && o.adaptive_lipschitz < 1, "adaptive_lipschitz", o.adaptive_lipschitz);
}

// The gap the envelope must bridge around each sample: the median over its 9 nearest
// samples (itself included) of r_k / 2.5, so a stray sample's wide r_k does not count.
std::vector<double> gap_floor(const std::vector<Point3>& points, const std::vector<double>& rk) {
  std::vector<double> floor = median_over_neighbours(points, rk, 9);
  for (double& f : floor) f /= kGapsPerRho;
  return floor;
}

// Adaptive mode: rho per sample from the local reach, between the floor and rho_max. Pairs
// shorter than the automatic reach's minimum pair length count only when they cross to a
// facing sheet (LocalReachOptions::crossing_min_cos).
std::vector<double> local_rho(const SurfaceSamples& surface, const EnvelopeOptions& o, double rho_max,
                              double noise, double spacing, const std::vector<double>& floor) {
  LocalReachOptions reach;
  reach.search_radius = 2.0 * rho_max / o.adaptive_rho_rel_lfs;
  reach.min_pair_distance = o.reach_min_pair_rel_spacing * spacing;
  const auto lfs = estimate_local_reach(surface, reach);
  AdaptiveRhoOptions a;
  a.rho_rel_lfs = o.adaptive_rho_rel_lfs;
  a.lipschitz = o.adaptive_lipschitz;
  a.rho_max = rho_max;
  a.rho_min = std::min(rho_max, std::max(o.adaptive_min_rel_rho * rho_max, o.min_rho_rel_noise * noise));
  return adaptive_rho(surface.points, lfs, a, floor);
}

// The largest distance from a sample to the nearest boundary-curve vertex (infinite without
// curves), over at most kMaxWidthQueries samples evenly strided: a strip of width w reads
// about w / 2, a disc its radius. `curve_tree` holds the curves' vertices.
double surface_half_width(const std::vector<Point3>& points, const PointTree& curve_tree) {
  constexpr std::size_t kMaxWidthQueries = 100000;
  if (curve_tree.size() == 0) return std::numeric_limits<double>::infinity();
  const std::size_t stride = std::max<std::size_t>(1, points.size() / kMaxWidthQueries);
  const double widest2 = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, (points.size() + stride - 1) / stride, 1024), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double widest) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
          widest = std::max(widest, PointSearch(curve_tree, points[i * stride], 1).begin()->second);
        return widest;
      },
      [](double a, double b) { return std::max(a, b); });
  return std::sqrt(widest2);
}

}  // namespace

std::vector<Point3> EnvelopeSamples::points() const {
  std::vector<Point3> out;
  out.reserve(samples.size());
  for (const auto& s : samples) out.push_back(s.position);
  return out;
}

EnvelopeSamples sample_envelope(const SurfaceSamples& surface, const EnvelopeOptions& options) {
  validate(surface, options);
  EnvelopeSamples out;
  const double diag = mesh::bbox_diagonal(surface.points);
  // One kd-tree of the input for the noise, the spacing, r_k and the clearance test.
  PointTree input_tree(surface.points.begin(), surface.points.end());
  input_tree.build();
  out.noise = surface.points.size() >= 4 ? estimate_noise(surface.points, input_tree, NoiseOptions{}) : 0.0;
  const double average_spacing = strided_average_spacing(surface.points, input_tree, 6);
  auto distances = neighbour_distances(surface.points, input_tree);
  out.input_neighbour_distance = std::move(distances.rk);
  out.input_nearest_distance = std::move(distances.nearest);
  // One kd-tree of the boundary curves' vertices for the half-width and the clearance test.
  std::vector<Point3> curve_points;
  for (const auto& c : surface.boundary)
    for (const auto& b : c.vertices) curve_points.push_back(b.position);
  PointTree curve_tree(curve_points.begin(), curve_points.end());
  // Built now, before the parallel queries (a search would build it, racing). A closed surface
  // has no curve: CGAL asserts on building an empty tree, and every query checks for one.
  if (!curve_points.empty()) curve_tree.build();
  if (options.rho) {
    out.rho = *options.rho;
  } else {
    out.reach = estimate_reach(surface, ReachOptions{.quantile = options.reach_quantile,
                     .min_pair_distance = options.reach_min_pair_rel_spacing * average_spacing,
                     .seed = options.seed});
    // The envelope must resolve the shape: the reach is capped by the size and by the width.
    out.half_width = surface_half_width(surface.points, curve_tree);
    const double size_cap = options.max_reach_rel_diag * diag;
    const double width_cap = options.max_reach_rel_half_width * out.half_width;
    const double resolvable = std::min(size_cap, width_cap);
    const double capped = std::min(out.reach.reach, resolvable);
    out.rho = options.rho_rel_reach * capped;
    out.is_rho_width_bound = width_cap < std::min(out.reach.reach, size_cap);
    if (options.min_rho_rel_noise * out.noise > out.rho) {
      out.rho = options.min_rho_rel_noise * out.noise;
      out.is_rho_noise_bound = true;
      if (out.rho > capped)
        out.warnings.push_back("the noise (sigma ~ " + format(out.noise) + ") needs rho >= " + format(out.rho) +
                               ", more than the estimated reach " + format(capped) +
                               ": the envelope may fold onto itself; denoise or sample denser");
    }
    double bridging = 0.0;  // the rho that bridges the gaps of gap_quantile of the samples
    if (options.gap_quantile > 0 && !out.input_neighbour_distance.empty()) {
      std::vector<double> rk = out.input_neighbour_distance;
      const auto at = std::min(rk.size() - 1, static_cast<std::size_t>(options.gap_quantile * static_cast<double>(rk.size())));
      std::nth_element(rk.begin(), rk.begin() + static_cast<std::ptrdiff_t>(at), rk.end());
      bridging = rk[at] / kGapsPerRho;
      if (bridging > out.rho) {
        out.warnings.push_back("rho raised from " + format(out.rho) +
                               (out.is_rho_noise_bound ? " (" + format(options.min_rho_rel_noise) + " times the noise)"
                                                         : std::string(" (half the estimated reach)")) + " to " +
                               format(bridging) + " to bridge the gaps between " +
                               format(100.0 * options.gap_quantile) +
                               "% of the samples and their 8th neighbours; above half the reach the envelope "
                               "may fold where the input is thin (handles, cross-caps)");
        out.rho = bridging;
        out.is_rho_gap_bound = true;
        out.is_rho_noise_bound = false;
      }
    }
    // Raised past the cap the reach itself respects, rho blurs shapes of the input's own
    // size: the envelope of 40 points on a square is a pillow whose medial sheet closes. A
    // sparse input also reads as noisy (its plane fits span curved patches), so the count of
    // samples that would do is given whenever the gaps alone need too large a rho.
    if (out.rho > resolvable && (out.is_rho_gap_bound || out.is_rho_noise_bound)) {
      out.is_input_too_sparse = true;
      const bool is_sparse = bridging > resolvable;
      const double denser = static_cast<double>(surface.points.size()) * (bridging / resolvable) * (bridging / resolvable);
      const std::string what = std::string(!is_sparse ? "noisy" : out.is_rho_gap_bound ? "sparse" : "sparse (or noisy)");
      if (width_cap < size_cap)
        out.warnings.push_back("the input is too " + what + " for its width: rho " + format(out.rho) + " is more than " +
                               format(options.max_reach_rel_half_width) + " times the surface's half-width " +
                               format(out.half_width) + " (the largest distance from a sample to its boundary "
                               "curves; the envelope resolves shapes down to about 2 rho): the result may be torn, "
                               "rounded or empty" +
                               (is_sparse ? "; about " + format(std::ceil(denser)) + " samples, evenly spread, would "
                                            "bridge the gaps with rho at that bound"
                                          : std::string()));
      else
        out.warnings.push_back("the input is too " + what + " for its size: rho " + format(out.rho) + " is " +
                               format(100.0 * out.rho / diag) +
                               "% of its diagonal (the envelope resolves shapes down to about 2 rho; at most " +
                               format(100.0 * options.max_reach_rel_diag) + "% is trusted): the result may be "
                               "rounded, closed or empty" +
                               (is_sparse ? "; about " + format(std::ceil(denser)) + " samples, evenly spread, would "
                                            "bridge the gaps with rho at " + format(100.0 * options.max_reach_rel_diag) + "%"
                                          : std::string()));
    }
  }
  out.spacing = options.spacing_rel_rho * out.rho;
  out.rho_min = out.rho;

  std::vector<double> rho(surface.points.size(), out.rho);
  if (options.rho_mode == RhoMode::Adaptive) {
    const std::vector<double> floor = options.adaptive_gap_floor
                                          ? gap_floor(surface.points, out.input_neighbour_distance)
                                          : std::vector<double>{};
    out.local_rho = local_rho(surface, options, out.rho, out.noise, average_spacing, floor);
    rho = out.local_rho;
    out.rho_min = *std::min_element(rho.begin(), rho.end());
    out.rho = *std::max_element(rho.begin(), rho.end());  // above the uniform rho where sparse
  }
  std::vector<std::vector<double>> rim_rho;
  if (options.rho_mode == RhoMode::Adaptive && !surface.boundary.empty()) {
    const NearestIndex index(surface.points);
    for (const auto& c : surface.boundary) {
      rim_rho.emplace_back();
      for (const auto& b : c.vertices) rim_rho.back().push_back(rho[index.nearest(b.position).first]);
    }
  } else {
    for (const auto& c : surface.boundary) rim_rho.emplace_back(c.vertices.size(), out.rho);
  }

  // The rims' candidates grow as the curves' length over rho (the sheets' are at most 128
  // per input sample): refuse a rho they could not be stored for, before making them.
  if (const double rims = rim_candidate_count(surface.boundary, rim_rho, options.spacing_rel_rho, kRimStepRelH);
      rims > kMaxRimCandidates) {
    // The count grows as 1 / (spacing^2 rho): a larger rho makes room, and so does a larger
    // spacing where it was set below the default (above it the envelope thins out). The
    // rounding of the tube's steps makes the spacing's share a few % less than its square.
    const double spacing_needed = 1.05 * options.spacing_rel_rho * std::sqrt(rims / kMaxRimCandidates);
    const bool spacing_helps = spacing_needed <= EnvelopeOptions{}.spacing_rel_rho;
    throw DegenerateInput("rho " + format(out.rho) + " at a sample spacing of " + format(options.spacing_rel_rho) +
                          " rho is too small for the boundary curves: their half-tubes would take " + format(rims) +
                          " envelope candidates (at most " + format(kMaxRimCandidates) + "); " +
                          (spacing_helps ? "a spacing of " + format(spacing_needed) + " rho or more, or " : "") +
                          "rho >= " + format(out.rho * rims / kMaxRimCandidates) + " would fit");
  }
  std::vector<EnvelopeSample> candidates = sheet_candidates(surface, rho, options.spacing_rel_rho, kCandidatesPerH2,
                                                            options.seed, out.input_neighbour_distance);
  out.input_coverage = out.input_neighbour_distance.empty()
                           ? 0.0
                           : *std::max_element(out.input_neighbour_distance.begin(), out.input_neighbour_distance.end());
  const auto rims = rim_candidates(surface.boundary, rim_rho, options.spacing_rel_rho, kRimStepRelH);
  candidates.insert(candidates.end(), rims.begin(), rims.end());
  out.candidates = candidates.size();

  // Clearance: a candidate nearer than the clearance to M is not on its envelope (the
  // envelope of a sampled surface, or a self-intersecting envelope when rho is too large).
  // The distance to the input and its boundary curves: the input's tree and the curves'.
  auto nearest_distance2 = [&](const Point3& q) {
    double d2 = std::numeric_limits<double>::infinity();
    if (!surface.points.empty()) d2 = PointSearch(input_tree, q, 1).begin()->second;
    if (!curve_points.empty()) d2 = std::min(d2, PointSearch(curve_tree, q, 1).begin()->second);
    return d2;
  };
  std::vector<char> keep(candidates.size(), 1);
  std::vector<char> folds(candidates.size(), 0);
  const CreaseDistance creases(surface.creases);
  const double noise_allowance = 3.0 * out.noise;
  const bool is_adaptive = options.rho_mode == RhoMode::Adaptive;
  // Queried along a Hilbert curve of the candidates (each test is independent of the order;
  // in generation order each query missed the cache: 1M-point cylinder file, 2.3 -> 0.8 s).
  std::vector<Point3> candidate_positions;
  candidate_positions.reserve(candidates.size());
  for (const auto& c : candidates) candidate_positions.push_back(c.position);
  const std::vector<std::size_t> order = mesh::hilbert_order(candidate_positions);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, candidates.size(), 4096), [&](const auto& r) {
    for (std::size_t at = r.begin(); at != r.end(); ++at) {
      const std::size_t i = order[at];
      const double d = std::sqrt(nearest_distance2(candidates[i].position));
      const double clearance =
          candidates[i].part == EnvelopePart::Sheet ? options.sheet_clearance : options.rim_clearance;
      // The candidate's own rho: the distance to its generator.
      const double rho_i = is_adaptive
                               ? std::sqrt(CGAL::squared_distance(candidates[i].position, candidates[i].generator))
                               : out.rho;
      if (d < clearance * rho_i) keep[i] = 0;
      folds[i] = candidates[i].part == EnvelopePart::Sheet && d < clearance * rho_i - noise_allowance &&
                 !(creases(candidates[i].generator) <= kCreaseReachRelRho * rho_i);
    }
  });
  std::size_t sheet_total = 0, sheet_folded = 0;
  std::vector<EnvelopeSample> kept_candidates;
  kept_candidates.reserve(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (candidates[i].part == EnvelopePart::Sheet) {
      ++sheet_total;
      sheet_folded += folds[i];
    }
    if (keep[i]) kept_candidates.push_back(candidates[i]);
  }
  out.dropped_too_close = candidates.size() - kept_candidates.size();
  if (sheet_total > 0 &&
      static_cast<double>(sheet_folded) > options.fold_warning_fraction * static_cast<double>(sheet_total)) {
    out.warnings.push_back("rho " + format(out.rho) + " may be too large: " + std::to_string(sheet_folded) +
                           " of " + std::to_string(sheet_total) + " sheet candidates come closer than " +
                           format(options.sheet_clearance) + " rho" +
                           (noise_allowance > 0 ? " - 3 noise" : std::string()) +
                           " to the surface (the envelope folds onto itself)");
  }
  if (options.rho && out.rho > 0.25 * diag)
    out.warnings.push_back("rho " + format(out.rho) + " is more than a quarter of the input's diagonal (" +
                           format(diag) + "): the envelope rounds off the whole shape, and the result may not "
                           "resemble the input (the automatic rho follows the reach)");

  std::vector<Point3> positions;
  positions.reserve(kept_candidates.size());
  for (const auto& c : kept_candidates) positions.push_back(c.position);
  if (is_adaptive) {
    std::vector<double> radii;
    radii.reserve(kept_candidates.size());
    for (const auto& c : kept_candidates)
      radii.push_back(options.spacing_rel_rho * std::sqrt(CGAL::squared_distance(c.position, c.generator)));
    for (std::size_t index : poisson_disk_thin(positions, radii, options.seed))
      out.samples.push_back(kept_candidates[index]);
  } else {
    for (std::size_t index : poisson_disk_thin(positions, out.spacing, options.seed))
      out.samples.push_back(kept_candidates[index]);
  }
  out.min_rho_for_gaps = out.input_coverage / kGapsPerRho;
  if (out.rho < out.min_rho_for_gaps) {
    // How many samples see such a gap tells a sparse region from a few stray points.
    const auto wide = std::count_if(out.input_neighbour_distance.begin(), out.input_neighbour_distance.end(),
                                    [&](double gap) { return gap > kGapsPerRho * out.rho; });
    out.warnings.push_back("the input has gaps of up to " + format(out.input_coverage) + " at " + std::to_string(wide) +
                           " of " + std::to_string(surface.points.size()) + " samples (rho is " + format(out.rho) +
                           "): the envelope may have holes there; rho >= " + format(out.min_rho_for_gaps) +
                           " or input with gaps below " + format(kGapsPerRho * out.rho) + " would work");
  }
  return out;
}

}  // namespace envcrust::envelope
