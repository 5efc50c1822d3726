// Moves a detected curve out to its outermost samples: the fitted centre line of a flagged
// band lies inside the band (the band is a few samples deep), while the true boundary lies
// beyond the outermost samples; then out past any sample still beyond it.
#include "boundary_detail.h"

#include <algorithm>
#include <limits>

namespace envcrust::boundary::detail {

namespace {

// The farthest of a few samples scattered with noise sigma overshoots by about sigma, and the
// scatter measured across the tangent plane reads about 0.8 sigma: the curve stays this many
// scatters inside the farthest sample. Measured on point files of 8 built-in surfaces with
// 0.25% noise, seeds 1 and 3: 1 scatter left the trefoil ribbon 0.54% and the saddle 0.56%
// beyond the surface (the bar is 0.5%), 1.5 none above 0.48%.
constexpr double kNoiseAllowance = 1.5;

// A sample beyond the curve is taken in (take_in_samples_beyond) only where the curve runs
// straight: conormals two vertices either side within 30 degrees. Beside a corner or a sharp
// turn (the mouth of a fjord) the conormal is no direction to move along: moving along it
// there took the clean cylinder's result 0.29% of the diagonal beyond the rim (seed 1).
constexpr double kStraightCos = 0.866;

// ... and when it lies more than this many noise allowances out (3 scatters): 1 (1.5
// scatters) took in the noise's outliers too and left the noisy unknot ribbon's result 0.62%
// of the diagonal beyond the surface (seed 1; 0.33% with 2).
constexpr double kCoverNoise = 2.0;

// ... and when the curve must move at least this many spacings further out for it: smaller
// moves change the result by less than the sampling does, but each changes the envelope's
// samples at the rim, and a scan's sheet can come out differently from them (the lion head
// points: curve moved at most 0.09 spacings, result 4.95% -> 7.43% of the diagonal).
constexpr double kMinTakeIn = 0.25;

// The moves raised so that the curve passes outside every sample beyond it, flagged or not
// (an unflagged sample on the rim beside a void, which the band's median leaves out): per
// vertex, the farthest reach along its conormal of the samples whose nearest vertex it is,
// within `spacing` of its tangent plane and more than `allowance` (noise) beyond its move;
// each raise also lifts the neighbours, by half the distance along the curve less (the curve
// bulges out rather than steps), as far as the conormals stay within 30 degrees.
std::vector<double> take_in_samples_beyond(const BoundaryCurve& curve, const std::vector<Point3>& points,
                                           const PointIndex& index, const std::vector<double>& moves,
                                           double allowance, double spacing, double radius, double max_move) {
  const std::size_t m = curve.vertices.size();
  std::vector<double> beyond(m, -std::numeric_limits<double>::infinity());
  const Polyline line = curve.polyline();
  const PointIndex line_index(line);
  for (std::size_t k = 0; k < m; ++k) {
    const BoundaryVertex& v = curve.vertices[k];
    for (const std::size_t j : index.within(v.position, radius)) {
      const Vector3 d = points[j] - v.position;
      const double along = dot(d, v.conormal);
      if (along <= moves[k] + allowance || std::abs(dot(d, v.normal)) > spacing) continue;
      if (line_index.nearest_indices(points[j], 1).front() != k) continue;
      beyond[k] = std::max(beyond[k], along - allowance);
    }
  }
  std::vector<double> edge(m);
  for (std::size_t k = 0; k < m; ++k) edge[k] = length(line[(k + 1) % m] - line[k]);
  std::vector<double> raised_moves = moves;
  for (std::size_t j = 0; j < m; ++j) {
    if (!(beyond[j] - moves[j] >= kMinTakeIn * spacing) ||
        dot(curve.vertices[(j + m - 2) % m].conormal, curve.vertices[(j + 2) % m].conormal) < kStraightCos)
      continue;
    const double need = std::min(beyond[j], max_move);
    raised_moves[j] = std::max(raised_moves[j], need);
    for (const bool forward : {true, false}) {
      double along_curve = 0.0;
      for (std::size_t d = 1; d < m; ++d) {
        const std::size_t k = forward ? (j + d) % m : (j + m - d) % m;
        along_curve += forward ? edge[(k + m - 1) % m] : edge[k];
        const double raised = need - 0.5 * along_curve;
        if (raised <= -max_move || dot(curve.vertices[k].conormal, curve.vertices[j].conormal) < kStraightCos) break;
        raised_moves[k] = std::max(raised_moves[k], raised);
      }
    }
  }
  return raised_moves;
}

}  // namespace

void fit_to_outer_samples(BoundaryCurve& curve, const std::vector<Point3>& points, const PointIndex& index,
                          const Candidates& candidates, const std::vector<std::size_t>& component,
                          double spacing, double max_move, bool take_in) {
  const std::size_t m = curve.vertices.size();
  if (m < 3 || component.empty() || !(spacing > 0)) return;
  Polyline band;
  band.reserve(component.size());
  for (const std::size_t i : component) band.push_back(points[i]);
  const PointIndex band_index(band);
  // Per vertex: the farthest reach along its conormal of the band's samples beside it (within
  // one spacing along the tangent and of the tangent plane, conormals agreeing, so the other
  // side of a narrow slot, whose conormals face this one's, never counts).
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> reach(m, kNone);
  // The samples' scatter across the tangent plane beside each vertex (RMS about their mean):
  // noise, which scatters them along the conormal as much, so the farthest one overshoots.
  std::vector<double> scatter;
  const double radius = std::hypot(max_move, spacing) + spacing;
  for (std::size_t k = 0; k < m; ++k) {
    const BoundaryVertex& v = curve.vertices[k];
    double sum = 0.0, sum_sq = 0.0;
    int count = 0;
    for (const std::size_t j : band_index.within(v.position, radius)) {
      const Vector3 d = band[j] - v.position;
      if (std::abs(dot(d, v.tangent)) > spacing || std::abs(dot(d, v.normal)) > spacing) continue;
      if (dot(candidates.conormals[component[j]], v.conormal) <= 0.5) continue;
      const double along = dot(d, v.conormal);
      if (std::isnan(reach[k]) || along > reach[k]) reach[k] = along;
      const double height = dot(d, v.normal);
      sum += height;
      sum_sq += height * height;
      ++count;
    }
    if (count >= 3) scatter.push_back(std::sqrt(std::max(0.0, sum_sq / count - (sum / count) * (sum / count))));
  }
  double noise = 0.0;
  if (!scatter.empty()) {
    std::nth_element(scatter.begin(), scatter.begin() + static_cast<std::ptrdiff_t>(scatter.size() / 2), scatter.end());
    noise = scatter[scatter.size() / 2];
  }
  noise *= kNoiseAllowance;
  // The median over each vertex and its two neighbours on either side, so a lone outlying
  // sample, which is the farthest one in two or three windows, moves nothing; limited to
  // max_move either way.
  std::vector<double> moves(m, 0.0);
  for (std::size_t k = 0; k < m; ++k) {
    std::vector<double> near;
    for (std::size_t d = 0; d < 5; ++d) {
      const double r = reach[(k + m + d - 2) % m];
      if (!std::isnan(r)) near.push_back(r);
    }
    if (near.empty()) continue;
    std::sort(near.begin(), near.end());
    const double median = near.size() % 2 ? near[near.size() / 2]
                                          : 0.5 * (near[near.size() / 2 - 1] + near[near.size() / 2]);
    moves[k] = std::clamp(median - noise, -max_move, max_move);
  }
  // Then averaged over the same five vertices: steps between neighbouring moves would turn
  // the tangents (and conormals) of the curve framed from the moved vertices.
  std::vector<double> averaged(m);
  for (std::size_t k = 0; k < m; ++k) {
    double sum = 0.0;
    for (std::size_t d = 0; d < 5; ++d) sum += moves[(k + m + d - 2) % m];
    averaged[k] = sum / 5.0;
  }
  const std::vector<double> final_move =
      take_in ? take_in_samples_beyond(curve, points, index, averaged, kCoverNoise * noise, spacing, radius, max_move)
              : averaged;
  for (std::size_t k = 0; k < m; ++k)
    curve.vertices[k].position = curve.vertices[k].position + final_move[k] * curve.vertices[k].conormal;
}

}  // namespace envcrust::boundary::detail
