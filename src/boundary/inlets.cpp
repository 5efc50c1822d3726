// Narrow inlets of a detected curve closed across their mouths: a random void in the samples
// next to the rim is flagged like the rim, and the ordered band runs into it and back out.
#include "boundary_detail.h"

#include <optional>

namespace envcrust::boundary::detail {

namespace {

// An inlet's mouth is at most this fraction of the way around it: a semicircular bay's is
// 0.64, a gently curved stretch of rim's nearly 1.
constexpr double kMaxMouthRelArc = 0.7;

// The conormals on either side of an inlet's mouth must agree this well (cos 60 degrees).
constexpr double kMinMouthConormalDot = 0.5;

// The section's vertices lie on average at least this fraction of the mouth in from it (a
// semicircular bay's read 0.32): a stretch of a tube's rim, whose conormals all point along
// the tube, is no inlet however round it runs.
constexpr double kMinMeanDepthRelMouth = 0.15;

struct Inlet {
  std::size_t first = 0;  ///< the mouth's two vertices: first, and first + span (cyclic)
  std::size_t span = 0;
  double arc = 0.0;
};

// The mean conormal of the mouth vertex k and the two vertices outside the section beside it
// (before it, or after it), unit length.
Vector3 side_conormal(const BoundaryCurve& curve, std::size_t k, std::size_t m, bool after) {
  Vector3 sum(0, 0, 0);
  for (std::size_t d = 0; d < 3; ++d) sum = sum + curve.vertices[after ? (k + d) % m : (k + m - d) % m].conormal;
  return unit(sum);
}

// The longest inlet of the curve, if any.
std::optional<Inlet> longest_inlet(const BoundaryCurve& curve, double max_loop_length) {
  const std::size_t m = curve.vertices.size();
  std::vector<double> edge(m);
  double total = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    edge[k] = length(curve.vertices[(k + 1) % m].position - curve.vertices[k].position);
    total += edge[k];
  }
  std::optional<Inlet> best;
  for (std::size_t i = 0; i < m; ++i) {
    const Point3& a = curve.vertices[i].position;
    double arc = 0.0;
    for (std::size_t span = 1; span < m; ++span) {
      arc += edge[(i + span - 1) % m];
      if (arc > 0.5 * total || arc >= max_loop_length) break;
      if (span < 3 || (best && arc <= best->arc)) continue;
      const Point3& b = curve.vertices[(i + span) % m].position;
      const double mouth = length(b - a);
      if (mouth > kMaxMouthRelArc * arc || arc + mouth >= max_loop_length) continue;
      // The curve on either side of the mouth runs the same way (conormals within 60 degrees:
      // not the two sides of a narrow hole, not a corner), and the section goes in from it,
      // against that conormal (a void beside the rim, not a tongue of the surface).
      const Vector3 before = side_conormal(curve, i, m, false), after = side_conormal(curve, (i + span) % m, m, true);
      if (dot(before, after) <= kMinMouthConormalDot) continue;
      const Vector3 out = unit(before + after);
      const Point3 mid = a + 0.5 * (b - a);
      double depth = 0.0;
      for (std::size_t d = 1; d < span; ++d) depth -= dot(curve.vertices[(i + d) % m].position - mid, out);
      if (depth >= kMinMeanDepthRelMouth * mouth * static_cast<double>(span - 1)) best = Inlet{i, span, arc};
    }
  }
  return best;
}

}  // namespace

Polyline close_inlets(const BoundaryCurve& curve, double max_loop_length, std::size_t& closed) {
  BoundaryCurve out = curve;
  while (out.vertices.size() > 6) {
    const auto inlet = longest_inlet(out, max_loop_length);
    if (!inlet) break;
    const std::size_t m = out.vertices.size();
    const Point3 a = out.vertices[inlet->first].position;
    const Point3 b = out.vertices[(inlet->first + inlet->span) % m].position;
    // The section's inner vertices replaced by points along the mouth, about as far apart as
    // the curve's vertices.
    const double step = inlet->arc / static_cast<double>(inlet->span);
    const auto inner = static_cast<std::size_t>(std::max(0.0, std::ceil(length(b - a) / step) - 1));
    std::vector<BoundaryVertex> kept;
    kept.reserve(m - inlet->span + 1 + inner);
    for (std::size_t d = inlet->span; d <= m; ++d) kept.push_back(out.vertices[(inlet->first + d) % m]);
    for (std::size_t q = 1; q <= inner; ++q) {
      BoundaryVertex v = out.vertices[inlet->first];
      v.position = a + (static_cast<double>(q) / static_cast<double>(inner + 1)) * (b - a);
      kept.push_back(v);
    }
    out.vertices = std::move(kept);  // starts at the mouth's far end, ends before its near end
    ++closed;
  }
  return out.polyline();
}

}  // namespace envcrust::boundary::detail
