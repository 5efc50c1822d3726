// Validation and clean-up of the closed polylines given to identify_knot and linking_number.
#pragma once

#include "envcrust/types.h"

namespace envcrust::knots::detail {

/// @throws InvalidInput "a closed polyline needs at least 3 points (got N)" or
///         "polyline point I has a non-finite coordinate".
void validate_closed_polyline(const Polyline& closed);

/// The same closed curve without consecutive repeated points (including last == first).
Polyline remove_repeated_points(const Polyline& closed);

/// Diagonal of the axis-aligned bounding box of all points of all loops.
double bbox_diagonal(const std::vector<Polyline>& loops);

}  // namespace envcrust::knots::detail
