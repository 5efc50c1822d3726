// Random rotations and the crossings of generic projections, with exact 2D orientation tests.
#include "projection.h"

#include "envcrust/random.h"
#include "envcrust/errors.h"
#include "input.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace envcrust::knots::detail {
namespace {

using Point2 = Kernel::Point_2;

constexpr int max_rotations = 200;


struct Projected {
  std::vector<Point3> points;       ///< the original points of all loops, in order
  std::vector<Point2> xy;           ///< their projections
  std::vector<std::uint32_t> next;  ///< end vertex of each (global) segment
};

// Only the first two rows are used: (x, y) = (r0 . p, r1 . p) is a parallel projection along
// r0 x r1, whatever rounding did to the rotation.
Projected project(const std::vector<Polyline>& loops, const Rotation& r) {
  CGAL::Bbox_3 box;
  for (const Polyline& loop : loops) {
    for (const Point3& p : loop) {
      box += p.bbox();
    }
  }
  // Projecting about the centre keeps rounding errors relative to the curve's own size.
  const double cx = 0.5 * (box.xmin() + box.xmax());
  const double cy = 0.5 * (box.ymin() + box.ymax());
  const double cz = 0.5 * (box.zmin() + box.zmax());
  Projected out;
  for (const Polyline& loop : loops) {
    const auto first = static_cast<std::uint32_t>(out.points.size());
    const auto n = static_cast<std::uint32_t>(loop.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = loop[i].x() - cx;
      const double y = loop[i].y() - cy;
      const double z = loop[i].z() - cz;
      out.points.push_back(loop[i]);
      out.xy.emplace_back(r[0] * x + r[1] * y + r[2] * z, r[3] * x + r[4] * y + r[5] * z);
      out.next.push_back(first + (i + 1) % n);
    }
  }
  return out;
}

double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x() - a.x();
  const double dy = b.y() - a.y();
  const double length2 = dx * dx + dy * dy;
  double s = length2 > 0.0 ? ((p.x() - a.x()) * dx + (p.y() - a.y()) * dy) / length2 : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  return std::hypot(p.x() - (a.x() + s * dx), p.y() - (a.y() + s * dy));
}

struct Extent {
  double xmin;
  double xmax;
  double ymin;
  double ymax;
};

Extent extent_of(const Projected& pr, std::uint32_t s, double margin) {
  const Point2& a = pr.xy[s];
  const Point2& b = pr.xy[pr.next[s]];
  return {std::min(a.x(), b.x()) - margin, std::max(a.x(), b.x()) + margin,
          std::min(a.y(), b.y()) - margin, std::max(a.y(), b.y()) + margin};
}

// Visits every pair of segments whose margin-enlarged boxes overlap (sweep along x).
template <typename Visit>
void for_each_close_pair(const Projected& pr, double margin, Visit&& visit) {
  const auto count = static_cast<std::uint32_t>(pr.xy.size());
  std::vector<Extent> extents(count);
  std::vector<std::uint32_t> order(count);
  for (std::uint32_t s = 0; s < count; ++s) {
    extents[s] = extent_of(pr, s, margin);
    order[s] = s;
  }
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return extents[a].xmin < extents[b].xmin; });
  for (std::size_t i = 0; i < order.size(); ++i) {
    const Extent& ei = extents[order[i]];
    for (std::size_t j = i + 1; j < order.size() && extents[order[j]].xmin <= ei.xmax; ++j) {
      const Extent& ej = extents[order[j]];
      if (ej.ymin <= ei.ymax && ei.ymin <= ej.ymax) {
        if (!visit(order[i], order[j])) {
          return;
        }
      }
    }
  }
}

}  // namespace

std::size_t Diagram::loop_of(std::uint32_t segment) const {
  const auto it = std::upper_bound(loop_start.begin(), loop_start.end(), segment);
  return static_cast<std::size_t>(it - loop_start.begin()) - 1;
}

Rotation random_rotation(std::mt19937_64& rng) {
  const double u1 = uniform01(rng);
  const double u2 = uniform01(rng);
  const double u3 = uniform01(rng);
  const double a = std::sqrt(1.0 - u1);
  const double b = std::sqrt(u1);
  const double x = a * std::sin(2.0 * std::numbers::pi * u2);
  const double y = a * std::cos(2.0 * std::numbers::pi * u2);
  const double z = b * std::sin(2.0 * std::numbers::pi * u3);
  const double w = b * std::cos(2.0 * std::numbers::pi * u3);
  return {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
          2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
          2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
}

std::optional<Diagram> project_loops(const std::vector<Polyline>& loops, const Rotation& rotation) {
  const Projected pr = project(loops, rotation);
  const double eps = 1e-9 * bbox_diagonal(loops);
  Diagram diagram;
  std::uint32_t total = 0;
  for (const Polyline& loop : loops) {
    diagram.loop_start.push_back(total);
    total += static_cast<std::uint32_t>(loop.size());
  }
  diagram.loop_start.push_back(total);

  bool generic = true;
  std::vector<Point2> crossing_points;
  for_each_close_pair(pr, eps, [&](std::uint32_t s, std::uint32_t t) {
    const std::uint32_t s1 = pr.next[s];
    const std::uint32_t t1 = pr.next[t];
    // A vertex must keep its distance from every segment it does not bound.
    for (const auto& [v, a, b] : {std::array{s, t, t1}, std::array{s1, t, t1},
                                  std::array{t, s, s1}, std::array{t1, s, s1}}) {
      if (v != a && v != b && distance_to_segment(pr.xy[v], pr.xy[a], pr.xy[b]) <= eps) {
        generic = false;
        return false;
      }
    }
    if (s1 == t || t1 == s) {
      return true;  // adjacent segments only meet at their shared vertex (checked above)
    }
    const Point2& p0 = pr.xy[s];
    const Point2& p1 = pr.xy[s1];
    const Point2& q0 = pr.xy[t];
    const Point2& q1 = pr.xy[t1];
    const CGAL::Orientation o1 = CGAL::orientation(p0, p1, q0);
    const CGAL::Orientation o2 = CGAL::orientation(p0, p1, q1);
    const CGAL::Orientation o3 = CGAL::orientation(q0, q1, p0);
    const CGAL::Orientation o4 = CGAL::orientation(q0, q1, p1);
    if (o1 == o2 || o3 == o4) {
      return true;  // no collinear cases left after the vertex-distance test
    }
    // The strand nearer the viewer follows exactly from the original points: with h the
    // height of s above t at the crossing, h * (d_s x d_t) . z = det(d_s, d_t, s0 - t0), whose
    // sign is orientation(s0, s1, t0, t1). Exact Delta-moves can leave segments arbitrarily
    // close in space, so no floating-point height is trusted here.
    const CGAL::Orientation chirality =
        CGAL::orientation(pr.points[s], pr.points[s1], pr.points[t], pr.points[t1]);
    if (chirality == CGAL::COPLANAR) {
      generic = false;  // the segments meet in space: the curve is not embedded
      return false;
    }
    // sign(d_s x d_t) equals the exact orientation of s0 with respect to t0 -> t1.
    const int s_cross_t = o3 == CGAL::LEFT_TURN ? 1 : -1;
    const bool s_over = (chirality == CGAL::POSITIVE) == (s_cross_t > 0);
    const double dpx = p1.x() - p0.x();
    const double dpy = p1.y() - p0.y();
    const double dqx = q1.x() - q0.x();
    const double dqy = q1.y() - q0.y();
    const double denominator = dpx * dqy - dpy * dqx;
    const double ex = q0.x() - p0.x();
    const double ey = q0.y() - p0.y();
    const double sp = std::clamp((ex * dqy - ey * dqx) / denominator, 0.0, 1.0);
    const double sq = std::clamp((ex * dpy - ey * dpx) / denominator, 0.0, 1.0);
    const Crossing crossing = s_over ? Crossing{s, t, sp, sq, s_cross_t}
                                     : Crossing{t, s, sq, sp, -s_cross_t};
    diagram.crossings.push_back(crossing);
    crossing_points.emplace_back(p0.x() + sp * dpx, p0.y() + sp * dpy);
    return true;
  });
  if (!generic) {
    return std::nullopt;
  }
  // Distinct crossings must stay apart, or their order along a strand is not reliable.
  for (std::size_t i = 0; i < crossing_points.size(); ++i) {
    for (std::size_t j = i + 1; j < crossing_points.size(); ++j) {
      if (std::hypot(crossing_points[i].x() - crossing_points[j].x(),
                     crossing_points[i].y() - crossing_points[j].y()) <= eps) {
        return std::nullopt;
      }
    }
  }
  return diagram;
}

Diagram generic_diagram(const std::vector<Polyline>& loops, std::mt19937_64& rng) {
  for (int attempt = 0; attempt < max_rotations; ++attempt) {
    if (auto diagram = project_loops(loops, random_rotation(rng))) {
      return *std::move(diagram);
    }
  }
  throw NumericalFailure("no generic projection found in " + std::to_string(max_rotations) +
                         " random directions (are the curves self-intersecting?)");
}

Diagram simplest_generic_diagram(const std::vector<Polyline>& loops, std::mt19937_64& rng,
                                 int candidates) {
  Diagram best = generic_diagram(loops, rng);
  for (int k = 1; k < candidates; ++k) {
    Diagram other = generic_diagram(loops, rng);
    if (other.crossings.size() < best.crossings.size()) {
      best = std::move(other);
    }
  }
  return best;
}

}  // namespace envcrust::knots::detail
