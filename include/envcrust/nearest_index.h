// Nearest-neighbour queries that return indices into a point vector (CGAL kd-tree).
#pragma once

#include "envcrust/types.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <numeric>
#include <vector>

namespace envcrust {

/// kd-tree over indices of an external point vector (which must outlive it).
class NearestIndex {
 public:
  explicit NearestIndex(const std::vector<Point3>& points)
      : points_(points), map_(points.data()) {
    std::vector<std::size_t> ids(points.size());
    std::iota(ids.begin(), ids.end(), std::size_t{0});
    tree_ = std::make_unique<Tree>(ids.begin(), ids.end(), Splitter(), Traits(map_));
    // Built now, so that parallel queries only read it. CGAL asserts on building an empty
    // tree; the queries below answer for no points without it.
    if (!points.empty()) tree_->build();
  }
  [[nodiscard]] bool empty() const { return points_.empty(); }
  /// Index of the nearest point and its distance. @pre !empty()
  std::pair<std::size_t, double> nearest(const Point3& q) const {
    Search search(*tree_, q, 1, 0, true, Distance(map_));
    const auto it = search.begin();
    return {it->first, std::sqrt(it->second)};
  }
  /// Whether some point lies within distance r of q (a range query that stops at the first
  /// hit: much cheaper than nearest() for a q far from every point, where the kd-tree may have
  /// to visit many leaves at about the same distance, such as a point on a cylinder's axis).
  [[nodiscard]] bool any_within(const Point3& q, double r) const {
    if (points_.empty()) return false;
    const CGAL::Fuzzy_sphere<Traits> sphere(q, r, 0.0, Traits(map_));
    return tree_->search_any_point(sphere).has_value();
  }
  /// The k nearest points (index, distance), nearest first.
  std::vector<std::pair<std::size_t, double>> nearest(const Point3& q, unsigned k) const {
    std::vector<std::pair<std::size_t, double>> out;
    if (points_.empty()) return out;
    Search search(*tree_, q, k, 0, true, Distance(map_));
    for (const auto& hit : search) out.emplace_back(hit.first, std::sqrt(hit.second));
    return out;
  }
  /// The indices of the k nearest points (all if fewer), nearest first; ties are broken by
  /// the tree, which is deterministic for a given input.
  [[nodiscard]] std::vector<std::size_t> nearest_indices(const Point3& q, std::size_t k) const {
    std::vector<std::size_t> out;
    if (points_.empty() || k == 0) return out;
    Search search(*tree_, q, static_cast<unsigned>(std::min(k, points_.size())), 0, true, Distance(map_));
    out.reserve(k);
    for (const auto& hit : search) out.push_back(hit.first);
    return out;
  }
  /// The indices of all points within distance r of q, in increasing order.
  [[nodiscard]] std::vector<std::size_t> within(const Point3& q, double r) const {
    std::vector<std::size_t> out;
    if (points_.empty()) return out;
    const CGAL::Fuzzy_sphere<Traits> sphere(q, r, 0.0, Traits(map_));
    tree_->search(std::back_inserter(out), sphere);
    std::sort(out.begin(), out.end());
    return out;
  }
  [[nodiscard]] std::size_t size() const { return points_.size(); }

 private:
  using Map = CGAL::Pointer_property_map<Point3>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Map, CGAL::Search_traits_3<Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = Search::Tree;
  using Splitter = Search::Splitter;
  using Distance = Search::Distance;
  const std::vector<Point3>& points_;
  Map map_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace envcrust
