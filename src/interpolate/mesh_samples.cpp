// mesh_samples: the guide, the front, the holes, and the used samples as the vertices.
#include "interpolate_detail.h"

#include "envcrust/median.h"
#include "envcrust/nearest_index.h"
#include "envcrust/neighbour_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>

#include <tbb/parallel_for.h>

namespace envcrust::interpolate {
namespace {

constexpr Index kUnused = std::numeric_limits<Index>::max();

}  // namespace

namespace detail {

std::vector<Point3> pull_towards_sheet(const std::vector<Point3>& samples, const std::vector<double>& spacing,
                                       const SheetGuide& guide, const InterpolateOptions& options,
                                       std::vector<char>& is_meshed, InterpolateStats& stats) {
  std::vector<Point3> nearest(samples.size());
  std::vector<double> offset(samples.size(), 0.0);  // in local spacings
  // In the spacing of the samples where the sheet passes by, not the sample's own: a stray's
  // nearest neighbours lie far off, and its own spacing would read it as close.
  const NearestIndex index(samples);
  tbb::parallel_for(std::size_t{0}, samples.size(), [&](std::size_t i) {
    nearest[i] = guide.nearest_point(samples[i]);
    const double there = spacing[index.nearest(nearest[i]).first];
    offset[i] = there > 0 ? std::sqrt(CGAL::squared_distance(samples[i], nearest[i])) / there : 0.0;
  });
  stats.median_offset_rel_spacing = upper_median(offset);
  // Exact samples sit on their sheet but where it rounds a crease or corner off, and there the
  // samples are right: only noisy samples (a median offset of a tenth of a spacing and more)
  // are pulled in.
  const bool is_noisy = stats.median_offset_rel_spacing >= options.min_noise_offset_rel_spacing;
  const double farthest = options.max_meshed_offset_rel_spacing *
                          (is_noisy ? std::max(1.0, stats.median_offset_rel_spacing) : 1.0);
  const double allowed = options.max_sample_offset_rel_spacing;
  std::vector<Point3> out = samples;
  is_meshed.assign(samples.size(), 1);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (offset[i] > farthest) {
      is_meshed[i] = 0;
      ++stats.samples_left_out;
    } else if (is_noisy && offset[i] > allowed) {
      out[i] = nearest[i] + (samples[i] - nearest[i]) * (allowed / offset[i]);
      ++stats.samples_moved;
    }
  }
  return out;
}

std::vector<double> local_spacing(const std::vector<Point3>& samples) {
  constexpr unsigned kNeighbours = 6;
  std::vector<double> out(samples.size(), 0.0);
  if (samples.size() < 2) return out;
  const NeighbourTable table(samples, kNeighbours);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    double sum = 0;
    for (const std::uint32_t j : table.of(i)) sum += std::sqrt(CGAL::squared_distance(samples[i], samples[j]));
    out[i] = sum / static_cast<double>(table.k());
  }
  return out;
}

}  // namespace detail

InterpolateResult mesh_samples(const std::vector<Point3>& samples, const TriangleMesh& sheet,
                               const InterpolateOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  InterpolateResult out;
  if (samples.size() < 3 || sheet.triangles.empty()) return out;
  const std::vector<double> spacing = detail::local_spacing(samples);
  out.stats.spacing = upper_median(spacing);
  const detail::SheetGuide guide(sheet);
  std::vector<char> is_meshed;
  const std::vector<Point3> placed = detail::pull_towards_sheet(samples, spacing, guide, options, is_meshed, out.stats);
  // The front works on the samples it may mesh; `meshed[k]` is the sample of its vertex k.
  std::vector<std::size_t> meshed;
  TriangleMesh mesh;
  std::vector<double> meshed_spacing;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!is_meshed[i]) continue;
    meshed.push_back(i);
    mesh.vertices.push_back(placed[i]);
    meshed_spacing.push_back(spacing[i]);
  }
  if (mesh.vertices.size() < 3) return out;
  mesh.triangles = detail::guided_front(mesh.vertices, meshed_spacing, guide, options, out.stats.candidates_refused);
  detail::close_holes_off_border(mesh, meshed_spacing, sheet, options, out.stats);
  for (auto& t : mesh.triangles)
    for (Index& v : t) v = static_cast<Index>(meshed[v]);
  // The used samples, in their input order.
  std::vector<Index> vertex_of(samples.size(), kUnused);
  for (const auto& t : mesh.triangles)
    for (const Index v : t) vertex_of[v] = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (vertex_of[i] == kUnused) continue;
    vertex_of[i] = static_cast<Index>(out.mesh.vertices.size());
    out.mesh.vertices.push_back(placed[i]);
    out.sample_of.push_back(i);
  }
  out.mesh.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) out.mesh.triangles.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace envcrust::interpolate
