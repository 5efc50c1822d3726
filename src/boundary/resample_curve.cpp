// resample_curve: equal arc-length resampling of a framed boundary curve between its corners,
// with frames interpolated and re-orthonormalised.
#include "boundary_detail.h"

#include "envcrust/errors.h"

#include <algorithm>

namespace envcrust::boundary {
namespace {

using detail::cross;
using detail::dot;
using detail::unit;
using detail::unit_perpendicular;

struct Frame {
  Vector3 t, n, c;
};

/// The frame with which the curve leaves vertex v towards `next`: at a corner the leaving
/// edge's tangent and conormal_next, else the vertex's own frame.
Frame leaving_frame(const BoundaryVertex& v, const Point3& next) {
  if (!v.is_corner) return {v.tangent, v.normal, v.conormal};
  Vector3 t = unit(cross(v.normal, v.conormal_next));
  if (dot(t, next - v.position) < 0) t = -t;
  return {t, v.normal, v.conormal_next};
}

BoundaryVertex interpolate(const BoundaryVertex& a, const Frame& fa, const BoundaryVertex& b,
                           double f, const Vector3& previous_normal) {
  BoundaryVertex out;
  out.position = a.position + f * (b.position - a.position);
  const Vector3 nb = dot(fa.n, b.normal) < 0 ? -b.normal : b.normal;
  const Vector3 cb = dot(fa.c, b.conormal) < 0 ? -b.conormal : b.conormal;
  out.tangent = unit((1 - f) * fa.t + f * b.tangent);
  out.normal = unit_perpendicular((1 - f) * fa.n + f * nb, out.tangent);
  if (dot(out.normal, previous_normal) < 0) out.normal = -out.normal;
  const Vector3 c = unit(cross(out.tangent, out.normal));
  out.conormal = dot(c, (1 - f) * fa.c + f * cb) < 0 ? -c : c;
  return out;
}

}  // namespace

BoundaryCurve resample_curve(const BoundaryCurve& curve, double max_spacing) {
  if (!(max_spacing > 0) || !std::isfinite(max_spacing)) {
    throw InvalidOptions("resample_curve: max_spacing must be > 0 (got " +
                         detail::format_number(max_spacing) + ")");
  }
  const std::size_t m = curve.vertices.size();
  if (m < 2) {
    throw InvalidInput("resample_curve: a curve needs at least 2 vertices (got " +
                       std::to_string(m) + ")");
  }
  // Pieces run from one corner to the next (or once around from vertex 0 without corners).
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < m; ++i) {
    if (curve.vertices[i].is_corner) starts.push_back(i);
  }
  if (starts.empty()) starts.push_back(0);
  BoundaryCurve out;
  for (std::size_t p = 0; p < starts.size(); ++p) {
    const std::size_t first = starts[p];
    const std::size_t last = p + 1 < starts.size() ? starts[p + 1] : starts[0] + m;
    std::vector<double> arc{0.0};
    for (std::size_t i = first; i < last; ++i) {
      arc.push_back(arc.back() + std::sqrt(CGAL::squared_distance(
                                     curve.vertices[i % m].position,
                                     curve.vertices[(i + 1) % m].position)));
    }
    const double total = arc.back();
    const auto count = static_cast<std::size_t>(std::max(1.0, std::ceil(total / max_spacing)));
    out.vertices.push_back(curve.vertices[first]);  // a corner (or vertex 0) as it was
    std::size_t seg = 0;
    for (std::size_t k = 1; k < count; ++k) {
      const double target = total * static_cast<double>(k) / static_cast<double>(count);
      while (seg + 1 < arc.size() - 1 && arc[seg + 1] < target) ++seg;
      const BoundaryVertex& a = curve.vertices[(first + seg) % m];
      const BoundaryVertex& b = curve.vertices[(first + seg + 1) % m];
      const double piece = arc[seg + 1] - arc[seg];
      const double f = piece > 0 ? (target - arc[seg]) / piece : 0.0;
      out.vertices.push_back(interpolate(a, leaving_frame(a, b.position), b, f,
                                         out.vertices.back().normal));
    }
  }
  return out;
}

}  // namespace envcrust::boundary
