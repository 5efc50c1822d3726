// Poisson-disk thinning: keep a maximal subset of points at pairwise distance >= radius.
#pragma once

#include "envcrust/types.h"

#include <cstdint>
#include <vector>

namespace envcrust::envelope {

/// Indices of the kept points, in increasing order. Points are visited in a seeded random
/// order, and a point is kept when no kept point lies within `radius` (hash grid of cell
/// radius / sqrt 3, so a cell holds at most one kept point).
std::vector<std::size_t> poisson_disk_thin(const std::vector<Point3>& points, double radius,
                                           std::uint64_t seed);

/// Variable radius: a point is kept when no kept point lies within its own radius (one per
/// point, > 0 for points to be kept). Equal radii give the same subset as the overload above
/// only in distribution, not point for point (different grid).
std::vector<std::size_t> poisson_disk_thin(const std::vector<Point3>& points, const std::vector<double>& radii,
                                           std::uint64_t seed);

}  // namespace envcrust::envelope
