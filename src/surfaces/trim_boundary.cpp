// The boundary curves of a trimmed surface: each trim loop of the parameter plane mapped onto
// the surface, resampled by arc length, with the outward conormal pointing out of the kept
// region and corners where the loop turns sharply.
#include "builtin.h"
#include "vector_ops.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace envcrust::surfaces {

namespace {

using Uv = std::array<double, 2>;

/// A turn of the mapped loop sharper than this between consecutive fine segments is a corner.
constexpr double kCornerDegrees = 30;

/// Frame at `q` on a piece running along the parameter-plane direction `along`.
BoundaryFrame frame_at(const Surface& surface, const Uv& q, const Uv& along, double probe) {
  const SurfaceJet jet = surface.evaluate(q[0], q[1]);
  BoundaryFrame f;
  f.position = jet.position;
  f.tangent = normalized(along[0] * jet.du + along[1] * jet.dv);
  f.normal = unit_normal_at(surface, q[0], q[1]);
  // Of the two parameter-plane normals to the loop, the outward one leaves the kept region.
  Uv out{along[1], -along[0]};
  const double length = std::hypot(out[0], out[1]);
  if (length > 0) out = {out[0] / length, out[1] / length};
  if (surface.contains(q[0] + probe * out[0], q[1] + probe * out[1])) out = {-out[0], -out[1]};
  Vector3 c = out[0] * jet.du + out[1] * jet.dv;
  c = c - dot(c, f.tangent) * f.tangent;
  c = c - dot(c, f.normal) * f.normal;
  f.conormal = normalized(c);
  return f;
}

}  // namespace

std::vector<BoundaryCurve> trim_boundary_curves(const Surface& surface, double max_spacing) {
  const ParameterDomain d = surface.domain();
  const double probe = 1e-7 * std::max(d.u1 - d.u0, d.v1 - d.v0);
  const double corner_cos = std::cos(kCornerDegrees * std::numbers::pi / 180);
  std::vector<BoundaryCurve> curves;
  for (const auto& loop : surface.trim_loops()) {
    const std::size_t m = loop.size();
    if (m < 3) continue;
    std::vector<Point3> mapped(m);
    for (std::size_t k = 0; k < m; ++k) mapped[k] = surface.evaluate(loop[k][0], loop[k][1]).position;
    const auto segment = [&](std::size_t k) { return mapped[(k + 1) % m] - mapped[k]; };
    // Corners split the loop into pieces; without any, one piece from point 0 round to it.
    std::vector<std::size_t> corners;
    for (std::size_t k = 0; k < m; ++k) {
      const Vector3 in = normalized(segment((k + m - 1) % m)), out = normalized(segment(k));
      if (dot(in, out) < corner_cos) corners.push_back(k);
    }
    const bool has_corners = !corners.empty();
    if (!has_corners) corners.push_back(0);
    BoundaryCurve curve;
    for (std::size_t c = 0; c < corners.size(); ++c) {
      const std::size_t start = corners[c];
      const std::size_t steps = ((c + 1 < corners.size() ? corners[c + 1] : corners[0] + m) - start + m - 1) % m + 1;
      std::vector<double> cumulative{0.0};
      for (std::size_t s = 0; s < steps; ++s)
        cumulative.push_back(cumulative.back() + std::sqrt(segment((start + s) % m).squared_length()));
      const double length = cumulative.back();
      const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil(length / max_spacing * (1 - 1e-12))));
      for (std::size_t q = 0; q < count; ++q) {
        const double target = length * static_cast<double>(q) / static_cast<double>(count);
        const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), target);
        const std::size_t s = std::min<std::size_t>(steps - 1, static_cast<std::size_t>(it - cumulative.begin()) - 1);
        const double piece = cumulative[s + 1] - cumulative[s];
        const double t = piece > 0 ? (target - cumulative[s]) / piece : 0.0;
        const Uv& a = loop[(start + s) % m];
        const Uv& b = loop[(start + s + 1) % m];
        const Uv uv{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
        const BoundaryFrame f = frame_at(surface, uv, {b[0] - a[0], b[1] - a[1]}, probe);
        if (has_corners && q == 0) {
          const Uv& before = loop[(start + m - 1) % m];
          const BoundaryFrame incoming = frame_at(surface, a, {a[0] - before[0], a[1] - before[1]}, probe);
          curve.vertices.push_back(boundary_vertex(f, &incoming));
        } else {
          curve.vertices.push_back(boundary_vertex(f));
        }
      }
    }
    curves.push_back(std::move(curve));
  }
  return curves;
}

}  // namespace envcrust::surfaces
