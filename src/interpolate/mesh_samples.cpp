// mesh_samples: the guide, the front, the holes, and the used samples as the vertices.
#include "interpolate_detail.h"

#include "envcrust/neighbour_table.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>

namespace envcrust::interpolate {
namespace {

constexpr Index kUnused = std::numeric_limits<Index>::max();

}  // namespace

namespace detail {

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
  std::vector<double> sorted = spacing;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
  out.stats.spacing = sorted[sorted.size() / 2];
  const detail::SheetGuide guide(sheet);
  TriangleMesh mesh;
  mesh.vertices = samples;
  mesh.triangles = detail::guided_front(samples, spacing, guide, options, out.stats.candidates_refused);
  detail::close_holes_off_border(mesh, spacing, sheet, options, out.stats);
  // The used samples, in their input order.
  std::vector<Index> vertex_of(samples.size(), kUnused);
  for (const auto& t : mesh.triangles)
    for (const Index v : t) vertex_of[v] = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (vertex_of[i] == kUnused) continue;
    vertex_of[i] = static_cast<Index>(out.mesh.vertices.size());
    out.mesh.vertices.push_back(samples[i]);
    out.sample_of.push_back(i);
  }
  out.mesh.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) out.mesh.triangles.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
  out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace envcrust::interpolate
