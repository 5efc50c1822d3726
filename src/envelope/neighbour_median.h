// Smoothing a per-sample value by the median over the sample's nearest neighbours.
#pragma once

#include "envcrust/types.h"

#include <vector>

namespace envcrust::envelope {

/// For each point, the median of `values` over its `k` nearest points (itself included; k is
/// capped at the point count): one stray value does not count, a value that all the points
/// around share does. In parallel. @pre values.size() == points.size()
std::vector<double> median_over_neighbours(const std::vector<Point3>& points, const std::vector<double>& values,
                                           unsigned k);

}  // namespace envcrust::envelope
