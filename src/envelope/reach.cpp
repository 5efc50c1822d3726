// Reach estimation by Federer's formula over all pairs of a random subsample (docs/method.md §4.1).
#include "envcrust/envelope.h"
#include "envcrust/errors.h"

#include "envcrust/random.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace envcrust::envelope {
namespace {

struct FramedPoint {
  Point3 p;
  Vector3 n;
  Vector3 c;          // outward conormal at boundary points, zero elsewhere
  bool is_boundary = false;
  // Distance to the nearest crease of M: a pair at least this long may span one.
  double crease_distance = std::numeric_limits<double>::infinity();
};

// dist(v, Tan_p): to the tangent plane, or at a boundary point to the half-plane spanned by t
// and -c (vectors pointing outwards, v.c > 0, leave the half-plane).
double distance_to_tangent(const FramedPoint& a, const Vector3& v) {
  const double normal = v * a.n;
  if (!a.is_boundary) return std::abs(normal);
  const double outward = std::max(0.0, v * a.c);
  return std::sqrt(normal * normal + outward * outward);
}

std::vector<FramedPoint> framed_subsample(const SurfaceSamples& s, const ReachOptions& o,
                                          const CreaseDistance& creases) {
  std::vector<std::size_t> order(s.points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937_64 rng(o.seed);
  for (std::size_t i = order.size(); i > 1; --i)
    std::swap(order[i - 1], order[static_cast<std::size_t>(uniform01(rng) * static_cast<double>(i))]);
  std::size_t boundary_count = 0;
  for (const auto& c : s.boundary) boundary_count += c.vertices.size();
  // Boundary vertices take at most a fifth of the budget: the curves matter for kappa_boundary.
  const std::size_t boundary_budget = std::min(boundary_count, o.max_points / 5);
  const std::size_t interior_budget = std::min(order.size(), o.max_points - boundary_budget);
  std::vector<FramedPoint> out;
  out.reserve(interior_budget + boundary_budget);
  for (std::size_t i = 0; i < interior_budget; ++i)
    out.push_back({s.points[order[i]], s.normals[order[i]], Vector3(0, 0, 0), false});
  if (boundary_budget > 0) {
    const double stride = static_cast<double>(boundary_count) / static_cast<double>(boundary_budget);
    std::size_t index = 0;
    double next = 0.0;
    for (const auto& c : s.boundary) {
      for (const auto& b : c.vertices) {
        if (static_cast<double>(index) >= next) {
          out.push_back({b.position, b.normal, b.conormal, true});
          next += stride;
        }
        ++index;
      }
    }
  }
  if (!creases.empty()) {
    tbb::parallel_for(std::size_t{0}, out.size(), [&](std::size_t i) { out[i].crease_distance = creases(out[i].p); });
  }
  return out;
}

}  // namespace

ReachEstimate estimate_reach(const SurfaceSamples& samples, const ReachOptions& options) {
  if (samples.points.size() != samples.normals.size())
    throw InvalidInput("reach: " + std::to_string(samples.points.size()) + " points but " +
                       std::to_string(samples.normals.size()) + " normals");
  if (samples.points.size() < 3) throw InvalidInput("reach: need at least 3 samples");
  if (!(options.min_chord_rel_value >= 0.0 && options.min_chord_rel_value <= 2.0))
    throw InvalidOptions("ReachOptions::min_chord_rel_value must be in [0, 2] (got " +
                         std::to_string(options.min_chord_rel_value) + ")");
  if (!(options.quantile >= 0.0 && options.quantile < 1.0))
    throw InvalidOptions("ReachOptions::quantile must be in [0, 1) (got " +
                         std::to_string(options.quantile) + ")");
  const CreaseDistance creases(samples.creases);
  const auto pts = framed_subsample(samples, options, creases);
  const std::size_t n = pts.size();
  // Per point: the smallest Federer value over its pairs, split by pair length so that the
  // report can say whether curvature or a bottleneck limits the reach.
  const double min_pair2 = options.min_pair_distance * options.min_pair_distance;
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  std::vector<double> best_near(n, std::numeric_limits<double>::infinity());
  std::vector<double> best_far(n, std::numeric_limits<double>::infinity());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        if (i == j) continue;
        const Vector3 v = pts[j].p - pts[i].p;
        const double len2 = v.squared_length();
        if (len2 == 0.0 || len2 < min_pair2) continue;
        // A pair that may span a crease reads the crease (no reach), not M's curvature or a
        // bottleneck: a point at distance e from a right-angled crease and one on the other
        // side read e at best. A bottleneck narrower than a point's distance to the creases
        // is still seen from there.
        if (len2 >= pts[i].crease_distance * pts[i].crease_distance) continue;
        const double d = distance_to_tangent(pts[i], v);
        if (d <= 0.0) continue;
        const double value = len2 / (2.0 * d);
        // A chord shorter than min_chord_rel_value times its value reads noise, not curvature.
        const double min_chord = options.min_chord_rel_value * value;
        if (min_chord * min_chord > len2) continue;
        best[i] = std::min(best[i], value);
        // A pair is "far" when it spans more than its own Federer value: a chord across a
        // bottleneck (|v| ~ 2R), not two neighbours on a curved sheet (|v| << R).
        if (std::sqrt(len2) > value) best_far[i] = std::min(best_far[i], value);
        else best_near[i] = std::min(best_near[i], value);
      }
    }
  });
  auto quantile_of = [&](std::vector<double> values) {
    // Unconstrained points (infinite values) stay in: they are the flat, convex part.
    const auto k = static_cast<std::size_t>(options.quantile * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
  };
  ReachEstimate out;
  out.reach = quantile_of(best);
  out.curvature_radius = quantile_of(best_near);
  out.bottleneck = quantile_of(best_far);
  out.pairs_examined = n * (n - 1);
  return out;  // infinite for a flat, convex piece: the caller caps it by the size
}

}  // namespace envcrust::envelope
