// Delaunay triangulation of the envelope samples and selection of the shell-crossing edges.
#include "voronoi_sheet.h"

#include "envcrust/errors.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace envcrust::extract {
namespace {

using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<Index, Kernel,
                                                     CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

constexpr Index kUnused = std::numeric_limits<Index>::max();

}  // namespace

RawSheet voronoi_sheet(const envelope::EnvelopeSamples& envelope, double min_angle_deg) {
  const auto& samples = envelope.samples;
  if (samples.size() < 5) throw DegenerateInput("envelope has fewer than 5 samples");
  std::vector<std::pair<Point3, Index>> input;
  input.reserve(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
    input.emplace_back(samples[i].position, static_cast<Index>(i));
  Delaunay dt(input.begin(), input.end());
  if (dt.dimension() < 3) throw DegenerateInput("envelope samples are coplanar");

  Index next_cell = 0;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) c->info() = next_cell++;
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
    if (dt.is_infinite(c)) c->info() = kUnused;

  const double max_dot = std::cos(min_angle_deg * std::numbers::pi / 180.0);
  RawSheet sheet;
  std::vector<Vector3> midpoint_sum(next_cell, Vector3(0, 0, 0));
  std::vector<std::uint32_t> midpoint_count(next_cell, 0);
  std::vector<Index> cells;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    ++sheet.delaunay_edges;
    const auto cell = e->first;
    const Index p = cell->vertex(e->second)->info();
    const Index q = cell->vertex(e->third)->info();
    const double dot = samples[p].direction * samples[q].direction;
    if (dot > max_dot) continue;
    ++sheet.crossing_edges;
    cells.clear();
    bool bounded = true;
    auto circulator = dt.incident_cells(*e);
    const auto start = circulator;
    do {
      if (circulator->info() == kUnused) {
        bounded = false;
        break;
      }
      cells.push_back(circulator->info());
    } while (++circulator != start);
    if (!bounded || cells.size() < 3) continue;
    const Vector3 mid = 0.5 * ((samples[p].position - CGAL::ORIGIN) + (samples[q].position - CGAL::ORIGIN));
    for (Index c : cells) {
      midpoint_sum[c] = midpoint_sum[c] + mid;
      ++midpoint_count[c];
    }
    sheet.polygons.push_back(cells);
    sheet.polygon_dot.push_back(dot);
  }
  // Compact: only cells on some polygon become vertices. Adjacent cells with the same
  // selected edges get the same position; they become one vertex (their Voronoi edge has
  // length zero), so that no face of the sheet has a zero-length side.
  std::vector<Index> vertex_of(next_cell, kUnused);
  std::map<Point3, Index> vertex_at;
  for (Index c = 0; c < next_cell; ++c) {
    if (midpoint_count[c] == 0) continue;
    const Point3 at = CGAL::ORIGIN + midpoint_sum[c] / static_cast<double>(midpoint_count[c]);
    const auto [it, is_new] = vertex_at.try_emplace(at, static_cast<Index>(sheet.vertices.size()));
    if (is_new) sheet.vertices.push_back(at);
    vertex_of[c] = it->second;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < sheet.polygons.size(); ++i) {
    auto& polygon = sheet.polygons[i];
    std::vector<Index> distinct;
    for (Index c : polygon)
      if (distinct.empty() || distinct.back() != vertex_of[c]) distinct.push_back(vertex_of[c]);
    while (distinct.size() > 1 && distinct.back() == distinct.front()) distinct.pop_back();
    if (distinct.size() < 3) continue;  // collapsed to an edge
    sheet.polygons[kept] = std::move(distinct);
    sheet.polygon_dot[kept] = sheet.polygon_dot[i];
    ++kept;
  }
  sheet.polygons.resize(kept);
  sheet.polygon_dot.resize(kept);
  return sheet;
}

}  // namespace envcrust::extract
