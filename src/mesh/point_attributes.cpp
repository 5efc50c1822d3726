// Carrying per-point attributes (colours, intensity, ...) from input samples to the vertices
// of a reconstructed mesh: each vertex takes those of its nearest sample.
//
// The nearest sample, not a blend of several: a colour or a class label copied from a real
// sample is one the scan holds (averaging a red and a green sample at an edge of paint would
// make a brown that is nowhere in it), and a user can check the result against the input.
#include "envcrust/attributes.h"

#include "envcrust/nearest_index.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace envcrust::attributes {

std::vector<std::size_t> nearest_sources(const std::vector<Point3>& sources, const std::vector<Point3>& targets) {
  std::vector<std::size_t> nearest;
  if (sources.empty()) return nearest;
  const NearestIndex index(sources);
  nearest.resize(targets.size());
  // Each query reads the built tree only, so the queries run in parallel.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, targets.size(), 256), [&](const auto& range) {
    for (std::size_t t = range.begin(); t != range.end(); ++t) nearest[t] = index.nearest(targets[t]).first;
  });
  return nearest;
}

PointAttributes carry_nearest(const std::vector<Point3>& sources, const PointAttributes& attributes,
                              const std::vector<Point3>& targets) {
  if (attributes.empty() || sources.empty()) return {};
  return attributes.pick(nearest_sources(sources, targets));
}

}  // namespace envcrust::attributes
