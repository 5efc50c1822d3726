// Shared input checks of the normals module: finite coordinates and number formatting.
#include "input_checks.h"

#include "envcrust/errors.h"

#include <cmath>
#include <sstream>

namespace envcrust::normals::detail {

void require_finite(const std::vector<Point3>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      throw InvalidInput("point " + std::to_string(i) + " has a non-finite coordinate");
    }
  }
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace envcrust::normals::detail
