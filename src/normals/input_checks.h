// Shared input checks of the normals module (finite coordinates, option formatting).
#pragma once

#include "envcrust/types.h"

#include <string>
#include <vector>

namespace envcrust::normals::detail {

/// @throws InvalidInput naming the first point with a non-finite coordinate.
void require_finite(const std::vector<Point3>& points);

/// A number as the messages print it (shortest round-trip form).
std::string format_number(double value);

}  // namespace envcrust::normals::detail
