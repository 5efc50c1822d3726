// Normal lines of a point cloud by PCA (CGAL's plane fit) or CGAL's jet fitting over the k
// nearest neighbours.
#include "envcrust/normals.h"

#include "input_checks.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <CGAL/jet_estimate_normals.h>
#include <CGAL/linear_least_squares_fitting_3.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace envcrust::normals {
namespace {

using PointNormal = std::pair<Point3, Vector3>;

void validate(const NormalOptions& options) {
  if (options.neighbors < 6) {
    throw InvalidOptions("normal estimation: neighbors must be >= 6 (got " +
                         std::to_string(options.neighbors) + ")");
  }
  if (options.jet_degree < 1 || options.jet_degree > 4) {
    throw InvalidOptions("normal estimation: jet_degree must be in 1..4 (got " +
                         std::to_string(options.jet_degree) + ")");
  }
  if (options.method != NormalMethod::Jet && options.method != NormalMethod::Pca) {
    throw InvalidOptions("normal estimation: unknown method " +
                         std::to_string(static_cast<int>(options.method)));
  }
}

Vector3 unit_or_throw(const Vector3& n) {
  const double len = std::sqrt(n.squared_length());
  if (!(len > 0) || !std::isfinite(len)) {
    throw NumericalFailure("normal estimation failed at a point (all neighbours collinear?)");
  }
  return n / len;
}

void check_points(const std::vector<Point3>& points) {
  detail::require_finite(points);
  if (points.size() < 3) {
    throw DegenerateInput("normal estimation needs at least 3 points (got " +
                          std::to_string(points.size()) + ")");
  }
}

}  // namespace

std::vector<Vector3> estimate_normal_lines(const std::vector<Point3>& points,
                                           const NormalOptions& options) {
  validate(options);
  check_points(points);
  if (options.method == NormalMethod::Pca) {
    return estimate_normal_lines(points, NeighbourTable(points, static_cast<unsigned>(options.neighbors)), options);
  }
  // The fits run along a Hilbert curve (mesh::hilbert_order: consecutive neighbour queries
  // visit the same part of CGAL's tree); the normals go back to the input order below.
  const std::vector<std::size_t> order = mesh::hilbert_order(points);
  std::vector<PointNormal> data;
  data.reserve(points.size());
  for (const std::size_t i : order) data.emplace_back(points[i], Vector3(0, 0, 0));
  const auto k = static_cast<unsigned int>(
      std::min<std::size_t>(static_cast<std::size_t>(options.neighbors), points.size()));
  const auto params = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<PointNormal>())
                          .normal_map(CGAL::Second_of_pair_property_map<PointNormal>());
  // Each point's fit is independent of the others: the result does not depend on threads.
  CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(
      data, k, params.degree_fitting(static_cast<unsigned int>(options.jet_degree)));
  std::vector<Vector3> out(points.size());
  for (std::size_t r = 0; r < data.size(); ++r) out[order[r]] = unit_or_throw(data[r].second);
  return out;
}

std::vector<Vector3> estimate_normal_lines(const std::vector<Point3>& points, const NeighbourTable& table,
                                           const NormalOptions& options) {
  validate(options);
  if (options.method != NormalMethod::Pca) return estimate_normal_lines(points, options);
  check_points(points);
  // As CGAL::pca_estimate_normals fits: the point and its k nearest others (CGAL asks its
  // tree for k + 1, the point itself first), all points when there are fewer.
  const auto others = static_cast<unsigned>(std::min<std::size_t>(options.neighbors, points.size() - 1));
  if (table.size() != points.size() || table.k() < others) {
    throw InvalidOptions("normal estimation: a neighbour table of " + std::to_string(table.size()) + " rows of " +
                         std::to_string(table.k()) + " for " + std::to_string(points.size()) + " points and " +
                         std::to_string(options.neighbors) + " neighbours");
  }
  std::vector<Vector3> out(points.size());
  const std::vector<std::size_t>& order = table.order();
  // Each point's fit is independent of the others: the result does not depend on threads.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256), [&](const auto& range) {
    std::vector<Point3> near;
    for (std::size_t r = range.begin(); r != range.end(); ++r) {
      const std::size_t i = order[r];
      near.assign(1, points[i]);
      for (const std::uint32_t j : table.of(i).first(others)) near.push_back(points[j]);
      Kernel::Plane_3 plane;
      CGAL::linear_least_squares_fitting_3(near.begin(), near.end(), plane, CGAL::Dimension_tag<0>());
      out[i] = plane.orthogonal_vector();
    }
  });
  for (auto& n : out) n = unit_or_throw(n);
  return out;
}

}  // namespace envcrust::normals
