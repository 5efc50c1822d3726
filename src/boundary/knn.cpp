// kd-tree wrapper with index-valued k-nearest and radius queries.
#include "knn.h"

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <iterator>

namespace envcrust::boundary::detail {

PointIndex::PointIndex(const std::vector<Point3>& points)
    : points_(&points), map_(CGAL::make_property_map(points)) {
  tree_ = std::make_unique<Tree>(boost::counting_iterator<std::size_t>(0),
                                 boost::counting_iterator<std::size_t>(points.size()),
                                 Tree::Splitter(), Traits(map_));
  tree_->build();
}

std::vector<std::size_t> PointIndex::nearest(const Point3& q, std::size_t k) const {
  std::vector<std::size_t> out;
  if (points_->empty() || k == 0) return out;
  Search search(*tree_, q, static_cast<unsigned int>(std::min(k, points_->size())), 0, true,
                Search::Distance(map_));
  out.reserve(k);
  for (const auto& [index, d2] : search) out.push_back(index);
  return out;
}

std::vector<std::size_t> PointIndex::within(const Point3& q, double r) const {
  std::vector<std::size_t> out;
  if (points_->empty()) return out;
  CGAL::Fuzzy_sphere<Traits> sphere(q, r, 0.0, Traits(map_));
  tree_->search(std::back_inserter(out), sphere);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace envcrust::boundary::detail
