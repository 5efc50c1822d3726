// Distance to the creases of M: a CGAL AABB tree over their segments.
#include "envcrust/envelope.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <cmath>
#include <limits>

namespace envcrust::envelope {

struct CreaseDistance::Tree {
  using Segment = Kernel::Segment_3;
  using Primitive = CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>;
  using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  std::vector<Segment> segments;
  std::vector<Vector3> wedges;  // per segment
  AabbTree tree;
};

CreaseDistance::CreaseDistance(const std::vector<CreaseSegment>& creases) {
  auto tree = std::make_unique<Tree>();
  for (const auto& c : creases)
    if (c.a != c.b) tree->segments.emplace_back(c.a, c.b), tree->wedges.push_back(c.wedge);
  if (tree->segments.empty()) return;
  tree->tree.insert(tree->segments.cbegin(), tree->segments.cend());
  tree->tree.build();
  tree->tree.accelerate_distance_queries();  // the search structure, built now, not by a first query
  tree_ = std::move(tree);
}

CreaseDistance::~CreaseDistance() = default;

double CreaseDistance::operator()(const Point3& p) const {
  if (!tree_) return std::numeric_limits<double>::infinity();
  return std::sqrt(tree_->tree.squared_distance(p));
}

Vector3 CreaseDistance::nearest_wedge(const Point3& p) const {
  const auto [point, primitive] = tree_->tree.closest_point_and_primitive(p);
  return tree_->wedges[static_cast<std::size_t>(primitive - tree_->segments.cbegin())];
}

}  // namespace envcrust::envelope
