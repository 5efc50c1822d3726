// Hausdorff distance between closed polylines (boundary loop matching).
#include "envcrust/distance.h"

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

double directed(const std::vector<Point3>& points, const Polyline& target) {
  std::vector<Segment> segments;
  for (std::size_t i = 0; i < target.size(); ++i) {
    const Segment s(target[i], target[(i + 1) % target.size()]);
    if (!s.is_degenerate()) segments.push_back(s);
  }
  if (segments.empty()) {  // all points of the target coincide
    double worst = 0.0;
    for (const Point3& p : points) worst = std::max(worst, CGAL::squared_distance(p, target.front()));
    return std::sqrt(worst);
  }
  SegmentTree tree(segments.begin(), segments.end());
  tree.accelerate_distance_queries();
  double worst = 0.0;
  for (const Point3& p : points) worst = std::max(worst, tree.squared_distance(p));
  return std::sqrt(worst);
}

}  // namespace

double closed_polyline_hausdorff(const Polyline& a, const Polyline& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  const double step = std::max(1e-12, std::min(mean_edge(a), mean_edge(b)) / 8.0);
  return std::max(directed(densify(a, step), b), directed(densify(b, step), a));
}

}  // namespace envcrust::distance
