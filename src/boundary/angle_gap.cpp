// Angle-gap boundary test: largest circular gap of the neighbours' polar angles in the tangent
// plane, with the outward conormal from the neighbour centroid checked against the gap bisector.
#include "boundary_detail.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <numbers>
#include <span>

namespace envcrust::boundary::detail {
namespace {

struct PointTest {
  bool flagged = false;
  bool strong = false;
  bool unreliable = false;
  Vector3 conormal = Vector3(0, 0, 0);
};

PointTest test_point(std::size_t i, const std::vector<Point3>& points, const Vector3& n,
                     std::span<const std::uint32_t> neighbors, double weak_threshold,
                     double strong_threshold, double min_agreement_cos) {
  // Tangent basis (u, w) of the plane perpendicular to n.
  const Vector3 helper = std::abs(n.x()) < 0.6 ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
  const Vector3 u = unit_perpendicular(helper, n);
  const Vector3 w = cross(n, u);
  std::vector<double> angles;
  angles.reserve(neighbors.size());
  double cu = 0, cw = 0;
  for (const std::size_t j : neighbors) {
    const Vector3 d = points[j] - points[i];
    const double x = dot(d, u), y = dot(d, w);
    if (x == 0 && y == 0) continue;
    angles.push_back(std::atan2(y, x));
    cu += x;
    cw += y;
  }
  PointTest out;
  if (angles.size() < 3) return out;
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * std::numbers::pi - angles.back();
  double gap_start = angles.back();
  for (std::size_t a = 1; a < angles.size(); ++a) {
    if (angles[a] - angles[a - 1] > gap) {
      gap = angles[a] - angles[a - 1];
      gap_start = angles[a - 1];
    }
  }
  if (gap <= weak_threshold) return out;
  const double bisector = gap_start + gap / 2;
  const Vector3 from_gap = std::cos(bisector) * u + std::sin(bisector) * w;
  const Vector3 from_centroid = unit(-cu * u - cw * w);
  if (dot(from_gap, from_centroid) < min_agreement_cos) {
    out.unreliable = true;
    return out;
  }
  out.flagged = true;
  out.strong = gap > strong_threshold;
  out.conormal = unit(from_gap + from_centroid);
  return out;
}

}  // namespace

Candidates angle_gap_candidates(const std::vector<Point3>& points,
                                const std::vector<Vector3>& normals, const NeighbourTable& table,
                                const BoundaryOptions& options) {
  const std::size_t n = points.size();
  const double strong = options.gap_threshold_deg * std::numbers::pi / 180.0;
  const double weak =
      std::min(options.gap_threshold_deg, options.weak_gap_threshold_deg) * std::numbers::pi / 180.0;
  const double min_cos = std::cos(options.conormal_agreement_deg * std::numbers::pi / 180.0);
  const auto k = static_cast<std::size_t>(options.neighbors);
  // Tests along the table's Hilbert curve (consecutive ones read the same points); each is
  // independent of the order, so the result is the same.
  const std::vector<std::size_t>& order = table.order();
  std::vector<PointTest> tests(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t r = range.begin(); r != range.end(); ++r) {
                        const std::size_t i = order[r];
                        tests[i] = test_point(i, points, normals[i], table.of(i).first(k),
                                              weak, strong, min_cos);
                      }
                    });
  Candidates out;
  out.flagged.resize(n, 0);
  out.strong.resize(n, 0);
  out.conormals.assign(n, Vector3(0, 0, 0));
  for (std::size_t i = 0; i < n; ++i) {
    out.flagged[i] = tests[i].flagged ? 1 : 0;
    out.strong[i] = tests[i].strong ? 1 : 0;
    out.conormals[i] = tests[i].conormal;
    if (tests[i].unreliable) ++out.unreliable;
  }
  return out;
}

}  // namespace envcrust::boundary::detail
