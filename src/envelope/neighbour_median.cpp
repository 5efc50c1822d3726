// median_over_neighbours: one kd-tree, one k-nearest search per point.
#include "neighbour_median.h"

#include "envcrust/nearest_index.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace envcrust::envelope {

std::vector<double> median_over_neighbours(const std::vector<Point3>& points, const std::vector<double>& values,
                                           unsigned k) {
  std::vector<double> out(points.size(), 0.0);
  if (points.empty()) return out;
  const NearestIndex index(points);
  k = static_cast<unsigned>(std::min<std::size_t>(k, points.size()));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 256), [&](const auto& range) {
    std::vector<double> around;
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      around.clear();
      for (const auto& [j, d] : index.nearest(points[i], k)) around.push_back(values[j]);
      const auto mid = around.begin() + static_cast<std::ptrdiff_t>(around.size() / 2);
      std::nth_element(around.begin(), mid, around.end());
      out[i] = *mid;
    }
  });
  return out;
}

}  // namespace envcrust::envelope
