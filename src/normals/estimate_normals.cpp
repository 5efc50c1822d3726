// Normal lines of a point cloud by CGAL's PCA or jet fitting over the k nearest neighbours.
#include "envcrust/normals.h"

#include "input_checks.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <CGAL/jet_estimate_normals.h>
#include <CGAL/pca_estimate_normals.h>

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

}  // namespace

std::vector<Vector3> estimate_normal_lines(const std::vector<Point3>& points,
                                           const NormalOptions& options) {
  validate(options);
  detail::require_finite(points);
  if (points.size() < 3) {
    throw DegenerateInput("normal estimation needs at least 3 points (got " +
                          std::to_string(points.size()) + ")");
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
  if (options.method == NormalMethod::Pca) {
    CGAL::pca_estimate_normals<CGAL::Parallel_if_available_tag>(data, k, params);
  } else {
    CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(
        data, k, params.degree_fitting(static_cast<unsigned int>(options.jet_degree)));
  }
  std::vector<Vector3> out(points.size());
  for (std::size_t r = 0; r < data.size(); ++r) {
    const Vector3& n = data[r].second;
    const double len = std::sqrt(n.squared_length());
    if (!(len > 0) || !std::isfinite(len)) {
      throw NumericalFailure("normal estimation failed at a point (all neighbours collinear?)");
    }
    out[order[r]] = n / len;
  }
  return out;
}

}  // namespace envcrust::normals
