// Closed-curve utilities of detection: equal-arc-length resampling, cyclic smoothing, and the
// t, n, c frames of a detected curve from the cloud's normal lines and candidate conormals.
#include "boundary_detail.h"

#include <algorithm>

namespace envcrust::boundary::detail {

Polyline resample_closed(const Polyline& curve, double spacing) {
  const std::size_t m = curve.size();
  if (m < 2) return curve;
  std::vector<double> arc(m + 1, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    arc[i + 1] = arc[i] + std::sqrt(CGAL::squared_distance(curve[i], curve[(i + 1) % m]));
  }
  const double total = arc.back();
  const auto count = static_cast<std::size_t>(std::max(3.0, std::ceil(total / spacing)));
  Polyline out;
  out.reserve(count);
  std::size_t seg = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double target = total * static_cast<double>(k) / static_cast<double>(count);
    while (seg + 1 < m && arc[seg + 1] < target) ++seg;
    const double piece = arc[seg + 1] - arc[seg];
    const double f = piece > 0 ? (target - arc[seg]) / piece : 0.0;
    out.push_back(curve[seg] + f * (curve[(seg + 1) % m] - curve[seg]));
  }
  return out;
}

Polyline remove_switchbacks(const Polyline& curve) {
  Polyline out = curve;
  std::size_t i = 0, unchanged = 0;
  // Walk around the loop until a full turn passes without a removal.
  while (out.size() > 3 && unchanged < out.size()) {
    const std::size_t m = out.size();
    i %= m;
    const Point3& prev = out[(i + m - 1) % m];
    const Point3& next = out[(i + 1) % m];
    if (dot(out[i] - prev, next - out[i]) < 0) {
      out.erase(out.begin() + static_cast<std::ptrdiff_t>(i));
      i = (i + m - 2) % (m - 1);  // the predecessor now turns differently: look at it again
      unchanged = 0;
    } else {
      ++i;
      ++unchanged;
    }
  }
  return out;
}

Polyline smooth_closed(const Polyline& curve, int half_window) {
  return smooth_closed(curve, std::vector<int>(curve.size(), half_window));
}

Polyline smooth_closed(const Polyline& curve, const std::vector<int>& half_windows) {
  const std::size_t m = curve.size();
  if (m < 3) return curve;
  const auto most = static_cast<std::ptrdiff_t>((m - 1) / 2);
  Polyline out;
  out.reserve(m);
  const auto sm = static_cast<std::ptrdiff_t>(m);
  for (std::ptrdiff_t i = 0; i < sm; ++i) {
    const std::ptrdiff_t h = std::clamp<std::ptrdiff_t>(half_windows[static_cast<std::size_t>(i)], 0, most);
    Vector3 sum(0, 0, 0);
    for (std::ptrdiff_t d = -h; d <= h; ++d) {
      sum = sum + (curve[static_cast<std::size_t>(((i + d) % sm + sm) % sm)] - CGAL::ORIGIN);
    }
    out.push_back(CGAL::ORIGIN + sum / static_cast<double>(2 * h + 1));
  }
  return out;
}

BoundaryCurve frame_curve(const Polyline& curve, const std::vector<Point3>& points,
                          const std::vector<Vector3>& normals, const PointIndex& index,
                          const Candidates& candidates, const std::vector<std::size_t>& component,
                          std::size_t curve_id, std::vector<std::string>& warnings) {
  constexpr std::size_t normal_neighbors = 8;
  const std::size_t m = curve.size();
  BoundaryCurve out;
  out.vertices.resize(m);
  Polyline component_points;
  for (const std::size_t i : component) component_points.push_back(points[i]);
  const PointIndex component_index(component_points);
  double vote = 0;
  std::vector<double> votes(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    BoundaryVertex& v = out.vertices[i];
    v.position = curve[i];
    v.tangent = unit(curve[(i + 1) % m] - curve[(i + m - 1) % m]);
    // Normal line: sign-aligned average of the nearest points' lines, made perpendicular to t.
    Vector3 sum(0, 0, 0);
    for (const std::size_t j : index.nearest_indices(curve[i], normal_neighbors)) {
      sum = sum + (dot(sum, normals[j]) < 0 ? -normals[j] : normals[j]);
    }
    v.normal = unit_perpendicular(sum, v.tangent);
    if (i > 0 && dot(v.normal, out.vertices[i - 1].normal) < 0) v.normal = -v.normal;
    v.conormal = cross(v.tangent, v.normal);
    const std::size_t nearest = component[component_index.nearest_indices(curve[i], 1).front()];
    votes[i] = dot(v.conormal, candidates.conormals[nearest]);
    vote += votes[i];
  }
  const double sign = vote < 0 ? -1.0 : 1.0;
  std::size_t agree = 0;
  for (std::size_t i = 0; i < m; ++i) {
    out.vertices[i].conormal = sign * out.vertices[i].conormal;
    if (sign * votes[i] > 0) ++agree;
  }
  if (m > 0 && dot(out.vertices.front().normal, out.vertices.back().normal) < 0) {
    warnings.push_back("curve " + std::to_string(curve_id) +
                       ": the normal line flips across the closing vertex (conormals there "
                       "point the wrong way)");
  }
  if (m > 0 && static_cast<double>(agree) < 0.9 * static_cast<double>(m)) {
    warnings.push_back("curve " + std::to_string(curve_id) + ": only " + std::to_string(agree) +
                       " of " + std::to_string(m) +
                       " vertices agree with the detected conormals");
  }
  return out;
}

}  // namespace envcrust::boundary::detail
