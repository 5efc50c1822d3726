// Ground truth and scores of boundary detection on the built-in surfaces: samples, exact
// boundary curves, nearest-truth queries, loop matching (Hausdorff) and flag statistics.
#pragma once

#include "envcrust/boundary.h"
#include "envcrust/distance.h"
#include "envcrust/normals.h"
#include "envcrust/surfaces.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <boost/iterator/counting_iterator.hpp>

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace envcrust::test {

/// Nearest vertex of a set of exact boundary curves.
class TruthIndex {
 public:
  explicit TruthIndex(const std::vector<BoundaryCurve>& curves) {
    for (std::size_t c = 0; c < curves.size(); ++c) {
      for (const BoundaryVertex& v : curves[c].vertices) {
        points_.push_back(v.position);
        vertices_.push_back(v);
      }
    }
    // A closed surface has no curve: no map or tree (both take the first element).
    if (points_.empty()) return;
    map_ = CGAL::make_property_map(std::as_const(points_));
    tree_ = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
                                   boost::counting_iterator<std::size_t>(points_.size()),
                                   Tree::Splitter(), Traits(map_));
    tree_->build();
  }
  [[nodiscard]] bool empty() const { return points_.empty(); }
  /// Nearest exact boundary vertex and its distance.
  [[nodiscard]] std::pair<const BoundaryVertex*, double> nearest(const Point3& q) const {
    if (points_.empty()) return {nullptr, std::numeric_limits<double>::infinity()};
    Search search(*tree_, q, 1, 0, true, Search::Distance(map_));
    const auto& [i, d2] = *search.begin();
    return {&vertices_[i], std::sqrt(d2)};
  }

 private:
  using Map = CGAL::Pointer_property_map<Point3>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Map, CGAL::Search_traits_3<Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = Search::Tree;
  std::vector<Point3> points_;
  std::vector<BoundaryVertex> vertices_;
  Map map_;
  std::unique_ptr<Tree> tree_;
};

/// Scores of one detection run against the exact boundary.
struct Score {
  std::size_t true_loops = 0, detected_loops = 0, dropped = 0;
  double worst_hausdorff = 0;   ///< over true loops, to the nearest detected loop, in s
  double min_conormal_dot = 1;  ///< over detected vertices, against the nearest true vertex
  double good_conormal_fraction = 1;  ///< detected vertices with c . c_true > 0.7
  double mean_offset = 0;       ///< mean (detected - true) . c_true, in s (< 0: inside)
  double recall = 0;            ///< flagged among samples within 0.5 s of the boundary
  double false_positive = 0;    ///< flagged among samples farther than 3 s from it
  std::size_t false_positive_count = 0;
  double spacing = 0;
};

struct Run {
  PointSet samples;
  boundary::BoundaryDetection detection;
  std::vector<BoundaryCurve> truth;
  Score score;
};

inline Run run_detection(const std::string& name, std::size_t count, double noise,
                         std::uint64_t seed = 11, const boundary::BoundaryOptions& options = {}) {
  Run run;
  const auto surface = surfaces::make_builtin(name);
  surfaces::SampleOptions sample_options;
  sample_options.count = count;
  sample_options.noise_rel_diag = noise;
  sample_options.seed = seed;
  run.samples = surfaces::sample_surface(*surface, sample_options);
  const auto normal_lines = normals::estimate_normal_lines(run.samples.points);
  run.detection = boundary::detect_boundary(run.samples.points, normal_lines, options);
  const double s = run.detection.spacing;
  Score& score = run.score;
  score.spacing = s;
  run.truth = surface->expected_topology().boundary_loops > 0
                  ? surfaces::boundary_curves(*surface, s / 8)
                  : std::vector<BoundaryCurve>{};
  score.true_loops = run.truth.size();
  score.detected_loops = run.detection.curves.size();
  score.dropped = run.detection.dropped_loops;
  for (const BoundaryCurve& t : run.truth) {
    double best = std::numeric_limits<double>::infinity();
    for (const BoundaryCurve& d : run.detection.curves) {
      best = std::min(best, distance::closed_polyline_hausdorff(t.polyline(), d.polyline()));
    }
    score.worst_hausdorff = std::max(score.worst_hausdorff, best / s);
  }
  const TruthIndex truth(run.truth);
  std::size_t vertices = 0, good = 0;
  double offset = 0;
  for (const BoundaryCurve& d : run.detection.curves) {
    for (const BoundaryVertex& v : d.vertices) {
      const auto [t, dist] = truth.nearest(v.position);
      if (t == nullptr) continue;
      const double c = CGAL::scalar_product(v.conormal, t->conormal);
      score.min_conormal_dot = std::min(score.min_conormal_dot, c);
      if (c > 0.7) ++good;
      offset += CGAL::scalar_product(v.position - t->position, t->conormal);
      ++vertices;
    }
  }
  if (vertices > 0) {
    score.good_conormal_fraction = static_cast<double>(good) / static_cast<double>(vertices);
    score.mean_offset = offset / static_cast<double>(vertices) / s;
  }
  std::size_t near = 0, near_flagged = 0, interior = 0;
  for (std::size_t i = 0; i < run.samples.size(); ++i) {
    const double d = truth.nearest(run.samples.points[i]).second / s;
    const bool flagged = run.detection.is_boundary_point[i];
    if (d < 0.5) {
      ++near;
      if (flagged) ++near_flagged;
    } else if (d > 3) {
      ++interior;
      if (flagged) ++score.false_positive_count;
    }
  }
  score.recall = near > 0 ? static_cast<double>(near_flagged) / static_cast<double>(near) : 1.0;
  score.false_positive =
      interior > 0 ? static_cast<double>(score.false_positive_count) / static_cast<double>(interior)
                   : 0.0;
  return run;
}

}  // namespace envcrust::test
