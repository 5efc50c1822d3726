// Average sample spacing from an even stride of the points (the envelope's scale for pairs).
#pragma once

#include "envcrust/types.h"

#include <vector>

namespace envcrust::envelope {

/// CGAL::compute_average_spacing's value (per point the sum of the distances to its k nearest
/// other points over k + 1, averaged), averaged over an even stride of at most `max_points`
/// points instead of all: at 1M input points the full version took a fifth of the envelope stage.
double strided_average_spacing(const std::vector<Point3>& points, unsigned k, std::size_t max_points = 20000);

}  // namespace envcrust::envelope
