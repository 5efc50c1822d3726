// Statistics of the input samples from one kd-tree of them, built once per envelope: the
// average spacing, the noise level and each sample's 8th-neighbour distance.
#pragma once

#include "envcrust/envelope.h"
#include "envcrust/types.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <vector>

namespace envcrust::envelope {

using PointSearch = CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_3<Kernel>>;
/// kd-tree of points (it holds copies); call build() before querying from several threads.
using PointTree = PointSearch::Tree;

/// CGAL::compute_average_spacing's value (per point the sum of the distances to its k nearest
/// other points over k + 1, averaged), averaged over an even stride of at most `max_points`
/// points instead of all: at 1M input points the full version took a fifth of the envelope
/// stage. `tree` holds `points`.
double strided_average_spacing(const std::vector<Point3>& points, const PointTree& tree, unsigned k,
                               std::size_t max_points = 20000);

/// estimate_noise with the kd-tree of `points` given.
double estimate_noise(const std::vector<Point3>& points, const PointTree& tree, const NoiseOptions& options);

/// Per sample, from one 9-nearest search (in parallel; `tree` holds `points`): the distance
/// to its nearest other sample and r_k, the distance to its 8th nearest other sample.
struct NeighbourDistances {
  std::vector<double> nearest;
  std::vector<double> rk;
};
NeighbourDistances neighbour_distances(const std::vector<Point3>& points, const PointTree& tree);

}  // namespace envcrust::envelope
