// Steps in the sampling density: the rim of a densely sampled region where the same surface
// goes on, sampled more sparsely. Its points' nearest neighbours all lie on the dense side,
// so the angle-gap test flags them like a boundary; looking past those neighbours tells them
// apart.
#include "boundary_detail.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace envcrust::boundary::detail {
namespace {

// How far past its neighbourhood a candidate looks, in neighbourhood radii: steps of up to
// about this factor in spacing are recognised.
constexpr double kLookFactor = 8.0;
// The wedge beyond a candidate: directions within 45 degrees of its conormal in the tangent
// plane, within 30 degrees of that plane, samples with normal lines within 30 degrees.
const double kWedgeCos = std::cos(std::numbers::pi / 4);
const double kOffPlaneTan = std::tan(std::numbers::pi / 6);
constexpr double kSameSheetCos = 0.866;
// Samples across a gap that face back (conormals opposite within 60 degrees) make it a gap:
// a hole or a slot whose far rim is sampled as densely.
constexpr double kFacingBackDot = -0.5;
// A step: past the neighbourhood the samples' own spacing is more than this many times the
// candidate's (`around`: its neighbourhood's) ...
constexpr double kStepSpacingRatio = 2.0;
// ... and there are at least this many of them: the surface goes on, not a stray sample.
constexpr std::size_t kMinSamplesBeyond = 2;

struct WedgeHit {
  double distance;
  std::size_t id;
};

bool is_density_step(std::size_t i, const std::vector<Point3>& points, const std::vector<Vector3>& normals,
                     const NeighbourTable& table, const PointIndex& index, const LocalSpacings& spacings,
                     const Candidates& candidates, std::size_t k) {
  const Point3& p = points[i];
  const Vector3& n = normals[i];
  const Vector3& c = candidates.conormals[i];
  const auto row = table.of(i).first(k);
  const double reach = std::sqrt(CGAL::squared_distance(p, points[row.back()]));
  if (!(reach > 0)) return false;
  const double look = kLookFactor * reach;
  std::vector<WedgeHit> wedge;
  for (const std::size_t j : index.within(p, look)) {
    if (j == i) continue;
    const Vector3 d = points[j] - p;
    const double h = dot(d, n);
    const Vector3 t = d - h * n;
    const double tl = length(t);
    if (!(tl > 0) || dot(t, c) < kWedgeCos * tl || std::abs(h) > kOffPlaneTan * tl) continue;
    if (std::abs(dot(normals[j], n)) < kSameSheetCos) continue;
    wedge.push_back({length(d), j});
  }
  std::sort(wedge.begin(), wedge.end(), [](const WedgeHit& a, const WedgeHit& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.id < b.id);
  });
  const auto first_beyond = std::find_if(wedge.begin(), wedge.end(), [reach](const WedgeHit& w) { return w.distance > reach; });
  if (first_beyond == wedge.end()) return false;  // nothing past the neighbourhood: a rim
  const double gap = first_beyond->distance;
  for (const WedgeHit& w : wedge) {
    if (w.distance > 1.5 * gap) break;
    if (candidates.flagged[w.id] && dot(candidates.conormals[w.id], c) < kFacingBackDot) return false;
  }
  // The spacing past the neighbourhood: the median of the samples' own (a sample next to the
  // dense side has its nearest there, but no nearer than the gap), but for those flagged
  // facing the same way: a rim's samples have their nearest on one side, and their own
  // spacing reads larger than the spacing there.
  const double outer = std::min(3.0 * gap, look);
  std::vector<double> beyond;
  for (auto w = first_beyond; w != wedge.end() && w->distance <= outer; ++w)
    if (!candidates.flagged[w->id] || dot(candidates.conormals[w->id], c) <= 0) beyond.push_back(spacings.own[w->id]);
  if (beyond.size() < kMinSamplesBeyond) return false;
  const auto mid = beyond.begin() + static_cast<std::ptrdiff_t>(beyond.size() / 2);
  std::nth_element(beyond.begin(), mid, beyond.end());
  return *mid > kStepSpacingRatio * spacings.around[i];
}

}  // namespace

std::size_t unflag_density_steps(const std::vector<Point3>& points, const std::vector<Vector3>& normals,
                                 const NeighbourTable& table, const PointIndex& index, const LocalSpacings& spacings,
                                 Candidates& candidates, std::size_t neighbors) {
  const auto ids = flagged_subset(points, candidates).ids;
  std::vector<char> step(ids.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ids.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t a = range.begin(); a != range.end(); ++a)
                        step[a] = is_density_step(ids[a], points, normals, table, index, spacings, candidates, neighbors) ? 1 : 0;
                    });
  return unflag(candidates, ids, step);
}

}  // namespace envcrust::boundary::detail
