// Input checks shared by the knot and linking entry points.
#include "input.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace envcrust::knots::detail {

void validate_closed_polyline(const Polyline& closed) {
  if (closed.size() < 3) {
    throw InvalidInput("a closed polyline needs at least 3 points (got " +
                       std::to_string(closed.size()) + ")");
  }
  for (std::size_t i = 0; i < closed.size(); ++i) {
    const Point3& p = closed[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      throw InvalidInput("polyline point " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
}

Polyline remove_repeated_points(const Polyline& closed) {
  Polyline out;
  out.reserve(closed.size());
  for (const Point3& p : closed) {
    if (out.empty() || out.back() != p) {
      out.push_back(p);
    }
  }
  while (out.size() > 1 && out.back() == out.front()) {
    out.pop_back();
  }
  return out;
}

double bbox_diagonal(const std::vector<Polyline>& loops) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf};
  double hi[3] = {-inf, -inf, -inf};
  bool any = false;
  for (const Polyline& loop : loops) {
    for (const Point3& p : loop) {
      any = true;
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
  }
  if (!any) {
    return 0.0;
  }
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

}  // namespace envcrust::knots::detail
