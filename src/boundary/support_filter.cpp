// Agreement along the curve: hysteresis (weak candidates survive only when linked to strong
// ones) and two-sided support (consistent candidates on both sides along the tangent), which
// isolated interior voids (the angle-gap test's false positives) lack.
#include "boundary_detail.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace envcrust::boundary::detail {

FlaggedSubset flagged_subset(const std::vector<Point3>& points, const Candidates& candidates) {
  FlaggedSubset out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (candidates.flagged[i]) {
      out.ids.push_back(i);
      out.points.push_back(points[i]);
    }
  }
  return out;
}

std::size_t unflag(Candidates& candidates, const std::vector<std::size_t>& ids, const std::vector<char>& drop) {
  std::size_t removed = 0;
  for (std::size_t a = 0; a < ids.size(); ++a) {
    if (!drop[a]) continue;
    candidates.flagged[ids[a]] = 0;
    candidates.strong[ids[a]] = 0;
    candidates.conormals[ids[a]] = Vector3(0, 0, 0);
    ++removed;
  }
  return removed;
}

std::size_t keep_connected_to_strong(const std::vector<Point3>& points, Candidates& candidates,
                                     const LinkReach& reach, double min_dot) {
  const FlaggedSubset subset = flagged_subset(points, candidates);
  const auto& ids = subset.ids;
  const auto links = candidate_links(subset, candidates, reach, min_dot);
  std::vector<char> reached(ids.size(), 0);
  std::vector<std::size_t> queue;
  for (std::size_t a = 0; a < ids.size(); ++a) {
    if (candidates.strong[ids[a]]) {
      reached[a] = 1;
      queue.push_back(a);
    }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    for (const std::size_t b : links[queue[head]]) {
      if (reached[b]) continue;
      reached[b] = 1;
      queue.push_back(b);
    }
  }
  for (char& r : reached) r = !r;  // now: not reached
  return unflag(candidates, ids, reached);
}

std::size_t filter_two_sided_support(const std::vector<Point3>& points,
                                     const std::vector<Vector3>& normals, Candidates& candidates,
                                     double radius, double min_dot) {
  const auto [ids, flagged_points] = flagged_subset(points, candidates);
  if (ids.empty()) return 0;
  const PointIndex index(flagged_points);
  std::vector<char> keep(ids.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t a = range.begin(); a != range.end(); ++a) {
                        const std::size_t i = ids[a];
                        const Vector3& c = candidates.conormals[i];
                        const Vector3 t = cross(normals[i], c);
                        bool ahead = false, behind = false;
                        for (const std::size_t b : index.within(points[i], radius)) {
                          const std::size_t j = ids[b];
                          if (j == i || dot(c, candidates.conormals[j]) <= min_dot) continue;
                          const double side = dot(points[j] - points[i], t);
                          ahead = ahead || side > 0;
                          behind = behind || side < 0;
                        }
                        keep[a] = ahead && behind ? 1 : 0;
                      }
                    });
  for (char& k : keep) k = !k;  // now: to drop
  return unflag(candidates, ids, keep);
}

}  // namespace envcrust::boundary::detail
