// A kd-tree over a point list answering k-nearest and radius queries by index (CGAL Kd_tree).
#pragma once

#include "envcrust/types.h"

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace envcrust::boundary::detail {

/// Nearest-neighbour queries over a fixed point list (the list must outlive the index).
/// Built eagerly, so queries are safe from several threads at once.
class PointIndex {
 public:
  explicit PointIndex(const std::vector<Point3>& points);
  /// Indices of the k nearest points to q, nearest first (ties broken by the tree, which is
  /// deterministic for a given input).
  [[nodiscard]] std::vector<std::size_t> nearest(const Point3& q, std::size_t k) const;
  /// Indices of all points within distance r of q, in increasing index order.
  [[nodiscard]] std::vector<std::size_t> within(const Point3& q, double r) const;
  [[nodiscard]] std::size_t size() const { return points_->size(); }

 private:
  using Map = CGAL::Pointer_property_map<Point3>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Map, CGAL::Search_traits_3<Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  using Tree = Search::Tree;

  const std::vector<Point3>* points_;
  Map map_;
  std::unique_ptr<Tree> tree_;
};

}  // namespace envcrust::boundary::detail
