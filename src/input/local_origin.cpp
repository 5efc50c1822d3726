// The local origin of a far input, and the moves into and out of its frame.
#include "local_origin.h"

#include "envcrust/input.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace envcrust::input {
namespace {

struct Box {
  std::array<double, 3> low, high;
  [[nodiscard]] double diagonal() const {
    return std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  }
  [[nodiscard]] double centre(std::size_t k) const { return 0.5 * (low[k] + high[k]); }
  // Largest distance of a corner's coordinate from 0.
  [[nodiscard]] double reach() const {
    double r = 0;
    for (std::size_t k = 0; k < 3; ++k) r = std::max({r, std::abs(low[k]), std::abs(high[k])});
    return r;
  }
};

// The bounding box of the finite points; low > high when there are none.
Box finite_box(const std::vector<Point3>& points) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box box{{inf, inf, inf}, {-inf, -inf, -inf}};
  for (const Point3& p : points) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) continue;
    for (int k = 0; k < 3; ++k) {
      box.low[k] = std::min(box.low[k], p[k]);
      box.high[k] = std::max(box.high[k], p[k]);
    }
  }
  return box;
}

}  // namespace

Vector3 local_origin(const std::vector<Point3>& points) {
  const Box box = finite_box(points);
  if (!(box.low[0] <= box.high[0])) return CGAL::NULL_VECTOR;
  const double diagonal = box.diagonal();
  if (!(diagonal > 0) || !(box.reach() > kFarRelDiagonal * diagonal)) return CGAL::NULL_VECTOR;
  const double step = std::pow(10.0, std::ceil(std::log10(diagonal)));
  std::array<double, 3> origin{};
  for (std::size_t k = 0; k < 3; ++k) origin[k] = step * std::round(box.centre(k) / step);
  return {origin[0], origin[1], origin[2]};
}

void subtract_origin(std::vector<Point3>& points, const Vector3& origin) {
  if (origin == CGAL::NULL_VECTOR) return;
  for (Point3& p : points) p = p - origin;
}

void restore_origin(std::vector<Point3>& points, const Vector3& origin) {
  if (origin == CGAL::NULL_VECTOR) return;
  for (Point3& p : points) p = p + origin;
}

std::string origin_note(const std::vector<Point3>& points, const Vector3& origin) {
  const Box box = finite_box(points);
  std::ostringstream s;
  s << std::setprecision(3) << "coordinates taken relative to (" << std::setprecision(15) << origin.x() << ", "
    << origin.y() << ", " << origin.z() << std::setprecision(3) << "): the input lies " << box.reach() / box.diagonal()
    << " diagonals (" << box.diagonal() << ") from (0, 0, 0)";
  return s.str();
}

}  // namespace envcrust::input
