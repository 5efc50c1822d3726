// Hausdorff distance between closed polylines (boundary loop matching).
#include "envcrust/distance.h"

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

double directed(const std::vector<Point3>& points, const Polyline& target) {
  double worst = 0.0;
  for (const Point3& p : points) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < target.size(); ++i) {
      const Kernel::Segment_3 s(target[i], target[(i + 1) % target.size()]);
      best = std::min(best, s.is_degenerate() ? CGAL::squared_distance(p, s.source())
                                              : CGAL::squared_distance(p, s));
    }
    worst = std::max(worst, best);
  }
  return std::sqrt(worst);
}

}  // namespace

double closed_polyline_hausdorff(const Polyline& a, const Polyline& b) {
  if (a.empty() || b.empty()) return std::numeric_limits<double>::infinity();
  const double step = std::max(1e-12, std::min(mean_edge(a), mean_edge(b)) / 8.0);
  return std::max(directed(densify(a, step), b), directed(densify(b, step), a));
}

}  // namespace envcrust::distance
