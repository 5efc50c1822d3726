// Average spacing of a point cloud: mean distance to the k nearest neighbours (CGAL, parallel).
#include "envcrust/normals.h"

#include "input_checks.h"

#include "envcrust/errors.h"

#include <CGAL/compute_average_spacing.h>

#include <algorithm>

namespace envcrust::normals {

double average_spacing(const std::vector<Point3>& points, int k) {
  if (k < 2) throw InvalidOptions("average spacing: k must be >= 2 (got " + std::to_string(k) + ")");
  detail::require_finite(points);
  if (points.size() < 3) {
    throw DegenerateInput("average spacing needs at least 3 points (got " +
                          std::to_string(points.size()) + ")");
  }
  const auto neighbors = static_cast<unsigned int>(
      std::min<std::size_t>(static_cast<std::size_t>(k), points.size() - 1));
  // Per-point sums are independent; CGAL adds them in input order after the parallel loop.
  return CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(points, neighbors);
}

}  // namespace envcrust::normals
