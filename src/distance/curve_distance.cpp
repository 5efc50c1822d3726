// Hausdorff distance between closed polylines (boundary loop matching).
#include "envcrust/distance.h"
#include "envcrust/errors.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace envcrust::distance {
namespace {

double mean_edge(const Polyline& c) {
  double sum = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i)
    sum += std::sqrt(CGAL::squared_distance(c[i], c[(i + 1) % c.size()]));
  return c.empty() ? 0.0 : sum / static_cast<double>(c.size());
}

std::vector<Point3> densify(const Polyline& c, double step) {
  std::vector<Point3> out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Point3& p = c[i];
    const Point3& q = c[(i + 1) % c.size()];
    const double len = std::sqrt(CGAL::squared_distance(p, q));
    const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
    for (int k = 0; k < n; ++k) out.push_back(p + (static_cast<double>(k) / n) * (q - p));
  }
  return out;
}

using Segment = Kernel::Segment_3;
using SegmentPrimitive = CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, SegmentPrimitive>>;

// Distance of each point to the nearest segment of the closed polyline `target`.
std::vector<double> directed(const std::vector<Point3>& points, const Polyline& target) {
  std::vector<Segment> segments;
  for (std::size_t i = 0; i < target.size(); ++i) {
    const Segment s(target[i], target[(i + 1) % target.size()]);
    if (!s.is_degenerate()) segments.push_back(s);
  }
  std::vector<double> out;
  out.reserve(points.size());
  if (segments.empty()) {  // all points of the target coincide
    for (const Point3& p : points) out.push_back(std::sqrt(CGAL::squared_distance(p, target.front())));
    return out;
  }
  SegmentTree tree(segments.begin(), segments.end());
  tree.accelerate_distance_queries();
  for (const Point3& p : points) out.push_back(std::sqrt(tree.squared_distance(p)));
  return out;
}

// The smallest d with at least `fraction` of the values <= d.
double quantile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(
      std::clamp(std::ceil(fraction * static_cast<double>(values.size())) - 1.0, 0.0,
                 static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace

double closed_polyline_hausdorff(const Polyline& a, const Polyline& b) {
  return closed_polyline_partial_hausdorff(a, b, 1.0);
}

double closed_polyline_partial_hausdorff(const Polyline& a, const Polyline& b, double fraction) {
  if (!(fraction > 0 && fraction <= 1))
    throw InvalidInput("closed_polyline_partial_hausdorff: fraction must be in (0, 1]");
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  // Each curve gets at most about kMaxPoints points between its vertices: a curve of tiny
  // edges beside a long one (a boundary given as a point grid) would otherwise ask billions.
  constexpr double kMaxPoints = 200000.0;
  const double step = std::min(mean_edge(a), mean_edge(b)) / 8.0;
  auto step_along = [&](const Polyline& c) {
    return std::max({step, mean_edge(c) * static_cast<double>(c.size()) / kMaxPoints, 1e-12});
  };
  return std::max(quantile(directed(densify(a, step_along(a)), b), fraction),
                  quantile(directed(densify(b, step_along(b)), a), fraction));
}

}  // namespace envcrust::distance
