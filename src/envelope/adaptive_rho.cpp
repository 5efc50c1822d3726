// Local reach per sample and the adaptive rho built from it (docs/method.md §4.4).
#include "envcrust/envelope.h"
#include "envcrust/errors.h"
#include "envcrust/nearest_index.h"

#include "neighbour_median.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <numeric>
#include <queue>
#include <sstream>

namespace envcrust::envelope {
namespace {

using PointMap = CGAL::Pointer_property_map<Point3>::const_type;
using Traits = CGAL::Search_traits_adapter<std::size_t, PointMap, CGAL::Search_traits_3<Kernel>>;
using Tree = CGAL::Kd_tree<Traits>;
using Sphere = CGAL::Fuzzy_sphere<Traits>;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void require(bool ok, const std::string& field, double value) {
  if (ok) return;
  std::ostringstream s;
  s << field << " out of range (got " << value << ")";
  throw InvalidOptions(s.str());
}

}  // namespace

std::vector<double> estimate_local_reach(const SurfaceSamples& samples, const LocalReachOptions& options) {
  if (samples.points.size() != samples.normals.size())
    throw InvalidInput("local reach: " + std::to_string(samples.points.size()) + " points but " +
                       std::to_string(samples.normals.size()) + " normals");
  require(options.search_radius > 0 && std::isfinite(options.search_radius), "LocalReachOptions::search_radius",
          options.search_radius);
  require(options.min_pair_distance >= 0, "LocalReachOptions::min_pair_distance", options.min_pair_distance);
  require(options.crossing_min_cos > 0 && options.crossing_min_cos <= 1, "LocalReachOptions::crossing_min_cos",
          options.crossing_min_cos);
  require(options.smoothing_neighbors >= 1, "LocalReachOptions::smoothing_neighbors", options.smoothing_neighbors);
  const auto& pts = samples.points;
  const std::size_t n = pts.size();
  std::vector<double> best(n, kInfinity);
  if (n < 2) return best;
  const PointMap map(pts.data());
  std::vector<std::size_t> ids(n);
  std::iota(ids.begin(), ids.end(), std::size_t{0});
  Tree tree(ids.begin(), ids.end(), Tree::Splitter(), Traits(map));
  tree.build();
  const double min_pair2 = options.min_pair_distance * options.min_pair_distance;
  const CreaseDistance creases(samples.creases);
  // A pair reads |q - p|^2 / (2 |(q - p) . n|) < B exactly when q lies inside one of the two
  // balls of radius B tangent to the plane at p (centres p +- B n). So the two balls of radius
  // B = search_radius / 2 hold every pair the search radius can see below B, and only those:
  // the surface grazes them, where the search ball of radius 2B held a whole patch of it
  // (head, 30k samples: 2.1 of 10 s of CPU before). Values B and above are not seen and stay
  // infinite, as documented.
  const double ball = 0.5 * options.search_radius;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 64), [&](const auto& range) {
    std::vector<std::size_t> hits;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      // Pairs that may span a crease read the crease, not the reach (as in estimate_reach).
      const double crease = creases(pts[i]);
      const double max_pair2 = crease * crease;
      const Vector3 normal = samples.normals[i] / std::sqrt(samples.normals[i].squared_length());
      hits.clear();
      tree.search(std::back_inserter(hits), Sphere(pts[i] + ball * normal, ball, 0.0, Traits(map)));
      tree.search(std::back_inserter(hits), Sphere(pts[i] - ball * normal, ball, 0.0, Traits(map)));
      for (std::size_t j : hits) {
        const Vector3 v = pts[j] - pts[i];
        const double len2 = v.squared_length();
        if (len2 == 0.0 || len2 >= max_pair2) continue;
        const double along = std::abs(v * normal);
        if (len2 < min_pair2 && along < options.crossing_min_cos * std::sqrt(len2)) continue;
        if (along <= 0.0) continue;
        best[i] = std::min(best[i], len2 / (2.0 * along));
      }
    }
  });
  // Median over the nearest samples: one stray pair (noise, a wrong normal) does not make a
  // hole in rho, while a real gap is seen by all samples around it.
  return median_over_neighbours(pts, best, static_cast<unsigned>(options.smoothing_neighbors));
}

namespace {

using Graph = std::vector<std::vector<std::pair<std::size_t, double>>>;

// values(p) <- min over graph paths of values(q) + L d(p, q): the largest L-Lipschitz function
// below `values` on the graph. Dijkstra from every sample at once; the result is independent
// of visiting order (it is the unique fixpoint). Works for negative values too.
void lower_to_lipschitz(const Graph& graph, const Graph& reverse, std::vector<double>& values, double lipschitz) {
  using Entry = std::pair<double, std::size_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::size_t i = 0; i < values.size(); ++i) queue.emplace(values[i], i);
  std::vector<char> done(values.size(), 0);
  while (!queue.empty()) {
    const auto [value, i] = queue.top();
    queue.pop();
    if (done[i] || value > values[i]) continue;
    done[i] = 1;
    auto relax = [&](std::size_t j, double d) {
      const double candidate = value + lipschitz * d;
      if (candidate < values[j]) {
        values[j] = candidate;
        queue.emplace(candidate, j);
      }
    };
    for (const auto& [j, d] : graph[i]) relax(j, d);
    for (const auto& [j, d] : reverse[i]) relax(j, d);
  }
}

}  // namespace

std::vector<double> adaptive_rho(const std::vector<Point3>& points, const std::vector<double>& lfs,
                                 const AdaptiveRhoOptions& options, const std::vector<double>& floor) {
  if (points.size() != lfs.size())
    throw InvalidInput("adaptive rho: " + std::to_string(points.size()) + " points but " +
                       std::to_string(lfs.size()) + " feature sizes");
  if (!floor.empty() && floor.size() != points.size())
    throw InvalidInput("adaptive rho: " + std::to_string(points.size()) + " points but " +
                       std::to_string(floor.size()) + " floor values");
  require(options.rho_rel_lfs > 0 && options.rho_rel_lfs < 1, "AdaptiveRhoOptions::rho_rel_lfs", options.rho_rel_lfs);
  require(options.rho_max > 0 && std::isfinite(options.rho_max), "AdaptiveRhoOptions::rho_max", options.rho_max);
  require(options.rho_min >= 0 && options.rho_min <= options.rho_max, "AdaptiveRhoOptions::rho_min", options.rho_min);
  require(options.lipschitz >= 0 && options.lipschitz < 1, "AdaptiveRhoOptions::lipschitz", options.lipschitz);
  require(options.neighbors >= 1, "AdaptiveRhoOptions::neighbors", options.neighbors);
  const std::size_t n = points.size();
  std::vector<double> rho(n);
  for (std::size_t i = 0; i < n; ++i)
    rho[i] = std::clamp(options.rho_rel_lfs * lfs[i], options.rho_min, options.rho_max);
  std::vector<double> raised = floor;
  if (n >= 2 && options.lipschitz > 0) {
    const NearestIndex index(points);
    const auto k = static_cast<unsigned>(std::min<std::size_t>(n, static_cast<std::size_t>(options.neighbors) + 1));
    Graph graph(n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) graph[i] = index.nearest(points[i], k);
    });
    // The kNN relation is not symmetric: add the reverse edges so that a small value spreads
    // to every sample that sees it or is seen by it.
    Graph reverse(n);
    for (std::size_t i = 0; i < n; ++i)
      for (const auto& [j, d] : graph[i]) reverse[j].emplace_back(i, d);
    lower_to_lipschitz(graph, reverse, rho, options.lipschitz);
    // The smallest L-Lipschitz function above the floor: -(the largest below -floor).
    for (double& f : raised) f = -f;
    lower_to_lipschitz(graph, reverse, raised, options.lipschitz);
    for (double& f : raised) f = -f;
  }
  // The maximum of two L-Lipschitz functions is L-Lipschitz.
  for (std::size_t i = 0; i < raised.size(); ++i) rho[i] = std::max(rho[i], raised[i]);
  return rho;
}

}  // namespace envcrust::envelope
