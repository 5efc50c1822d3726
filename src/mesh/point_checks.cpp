// Point-set hygiene shared by the Power Crust and the reconstruction's inputs: exact
// duplicates merged, and how many directions the points spread in.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <string>
#include <tuple>

namespace envcrust::mesh {

void check_coordinates(const std::vector<Point3>& points, const std::string& item) {
  double largest = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw InvalidInput(item + " " + std::to_string(i) + " has a non-finite coordinate");
    const double magnitude = std::max({std::abs(p.x()), std::abs(p.y()), std::abs(p.z())});
    if (magnitude > kMaxCoordinate) {
      std::ostringstream s;
      s << item << " " << i << " (from 0) has a coordinate of magnitude " << std::setprecision(3) << magnitude
        << ", beyond " << kMaxCoordinate << ": scale the input down";
      throw InvalidInput(s.str());
    }
    largest = std::max(largest, magnitude);
  }
  const double diagonal = bbox_diagonal(points);
  if (diagonal == 0.0) return;  // one point, repeated: the stages count distinct points
  std::ostringstream s;
  s << std::setprecision(3);
  if (diagonal < kMinExtent) {
    s << "the points span only " << diagonal << " (bounding-box diagonal), below " << kMinExtent
      << ": scale the input up";
    throw InvalidInput(s.str());
  }
  if (diagonal < kMinExtentRelMagnitude * largest) {
    s << "the points span only " << diagonal << " at coordinates up to " << largest
      << ": too few digits are left to tell them apart; move the input near the origin";
    throw InvalidInput(s.str());
  }
}

MergedPoints merge_duplicate_points(const std::vector<Point3>& points) {
  check_coordinates(points);
  // Sorting indices with the index as last key gives each group of equal points its first
  // occurrence as representative, whatever the sort's thread schedule.
  std::vector<Index> order(points.size());
  std::iota(order.begin(), order.end(), Index{0});
  tbb::parallel_sort(order.begin(), order.end(), [&](Index a, Index b) {
    const Point3& p = points[a];
    const Point3& q = points[b];
    return std::make_tuple(p.x(), p.y(), p.z(), a) < std::make_tuple(q.x(), q.y(), q.z(), b);
  });
  std::vector<Index> representative(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const bool same = k > 0 && points[order[k]] == points[order[k - 1]];
    representative[order[k]] = same ? representative[order[k - 1]] : order[k];
  }
  MergedPoints out;
  out.input_to_merged.resize(points.size());
  out.points.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (representative[i] == i) {
      out.input_to_merged[i] = static_cast<Index>(out.points.size());
      out.points.push_back(points[i]);
    } else {
      out.input_to_merged[i] = out.input_to_merged[representative[i]];
    }
  }
  out.duplicates = points.size() - out.points.size();
  return out;
}

int spread_dimension(const std::vector<Point3>& points, double tolerance) {
  if (points.size() < 2) return 0;
  const Point3& a = points.front();
  auto farthest = [&](auto&& distance) {
    std::size_t best = 0;
    double best_distance = -1.0;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (const double d = distance(points[i]); d > best_distance) best = i, best_distance = d;
    return std::make_pair(best, best_distance);
  };
  const auto [b, from_a] = farthest([&](const Point3& p) { return std::sqrt(CGAL::squared_distance(a, p)); });
  if (from_a <= tolerance) return 0;
  const Kernel::Line_3 line(a, points[b]);
  const auto [c, from_line] = farthest([&](const Point3& p) { return std::sqrt(CGAL::squared_distance(line, p)); });
  if (from_line <= tolerance) return 1;
  const Kernel::Plane_3 plane(a, points[b], points[c]);
  const double from_plane = farthest([&](const Point3& p) { return std::sqrt(CGAL::squared_distance(plane, p)); }).second;
  return from_plane <= tolerance ? 2 : 3;
}

}  // namespace envcrust::mesh
