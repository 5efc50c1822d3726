// Average sample spacing on an even stride of the points, with a kd-tree of all of them.
#include "input_tree.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace envcrust::envelope {

double strided_average_spacing(const std::vector<Point3>& points, const PointTree& tree, unsigned k,
                               std::size_t max_points) {
  if (points.size() < 2) return 0.0;
  const unsigned neighbors = static_cast<unsigned>(std::min<std::size_t>(k + 1, points.size()));
  const std::size_t stride = std::max<std::size_t>(1, points.size() / std::max<std::size_t>(1, max_points));
  const std::size_t count = (points.size() + stride - 1) / stride;
  const double sum = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<std::size_t>(0, count, 256), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double acc) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          PointSearch search(tree, points[i * stride], neighbors);
          double s = 0.0;
          for (const auto& hit : search) s += std::sqrt(hit.second);
          acc += s / neighbors;
        }
        return acc;
      },
      std::plus<>());
  return sum / static_cast<double>(count);
}

}  // namespace envcrust::envelope
