// Holes the front leaves where the sheet goes on: the front stops where CGAL's own criteria
// (a candidate that folds too sharply, a ring it cannot close) find no triangle, a few
// spacings wide. The sheet says whether the surface goes on there: a hole away from its
// border is closed; one along it is the surface's boundary.
#include "interpolate_detail.h"

#include "envcrust/topology.h"

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <set>
#include <tuple>

namespace envcrust::interpolate::detail {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

// The vertices on the sheet's border edges, and the border loop each lies on.
std::vector<Point3> border_points(const TriangleMesh& sheet, std::vector<std::size_t>& loop_of) {
  std::vector<Point3> out;
  const std::vector<topology::BoundaryLoop> loops = topology::boundary_loops(sheet);
  for (std::size_t l = 0; l < loops.size(); ++l)
    for (const Index v : loops[l].vertices) {
      out.push_back(sheet.vertices[v]);
      loop_of.push_back(l);
    }
  return out;
}

// Where a loop of the meshed samples lies against the sheet's border: the median distance of
// its vertices to it, and the sheet border loop most of them lie nearest to.
struct BorderReading {
  double median_distance = 0.0;
  std::size_t sheet_loop = 0;
};

BorderReading read_border(const std::vector<Index>& loop, const TriangleMesh& mesh, const NearestIndex& border,
                          const std::vector<std::size_t>& loop_of) {
  std::vector<double> d;
  d.reserve(loop.size());
  std::map<std::size_t, std::size_t> votes;
  for (const Index v : loop) {
    const auto [nearest, distance] = border.nearest(mesh.vertices[v]);
    d.push_back(distance);
    ++votes[loop_of[nearest]];
  }
  const auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  const auto most = std::max_element(votes.begin(), votes.end(),
                                     [](const auto& a, const auto& b) { return a.second < b.second; });
  return {*mid, most->first};
}

// Triangles over the loop's own vertices, wound to run each loop edge against the face that
// already holds it (a border edge's face runs it one way; the patch must run it the other).
bool close_loop(const std::vector<Index>& loop, TriangleMesh& mesh, const std::set<std::pair<Index, Index>>& directed) {
  std::vector<Point3> points;
  points.reserve(loop.size());
  for (const Index v : loop) points.push_back(mesh.vertices[v]);
  std::vector<std::tuple<int, int, int>> triangles;
  PMP::triangulate_hole_polyline(points, std::back_inserter(triangles),
                                 CGAL::parameters::do_not_use_cubic_algorithm(true));
  if (triangles.size() + 2 != loop.size()) return false;
  // The patch runs loop[i] -> loop[i+1] when its triangles are taken as CGAL gives them (in
  // the polyline's order); the mesh's face on that edge must run it the other way.
  const bool flip = directed.count({loop[0], loop[1]}) > 0;
  for (const auto& [a, b, c] : triangles) {
    std::array<Index, 3> t{loop[static_cast<std::size_t>(a)], loop[static_cast<std::size_t>(b)],
                           loop[static_cast<std::size_t>(c)]};
    if (flip) std::swap(t[1], t[2]);
    mesh.triangles.push_back(t);
  }
  return true;
}

}  // namespace

void close_holes_off_border(TriangleMesh& mesh, const std::vector<double>& spacing, const TriangleMesh& sheet,
                            const InterpolateOptions& options, InterpolateStats& stats) {
  const std::vector<topology::BoundaryLoop> loops = topology::boundary_loops(mesh);
  if (loops.empty()) return;
  std::vector<std::size_t> loop_of;
  const std::vector<Point3> border = border_points(sheet, loop_of);
  const NearestIndex border_index(border);
  // A loop along the sheet's border is the surface's boundary: of the loops along one border
  // loop of the sheet, the closest; the others (a notch the front left beside the rim) are holes.
  std::vector<double> scale(loops.size(), 0.0), distance(loops.size(), 0.0);
  std::vector<bool> is_boundary(loops.size(), false);
  std::map<std::size_t, std::size_t> closest;  // sheet loop -> the loop of `loops` following it
  for (std::size_t l = 0; l < loops.size(); ++l) {
    for (const Index v : loops[l].vertices) scale[l] = std::max(scale[l], spacing[v]);
    if (border.empty()) continue;
    const BorderReading reading = read_border(loops[l].vertices, mesh, border_index, loop_of);
    distance[l] = reading.median_distance;
    if (distance[l] > options.border_reach_rel_spacing * scale[l]) continue;
    const auto [it, is_new] = closest.try_emplace(reading.sheet_loop, l);
    if (!is_new && distance[l] < distance[it->second]) it->second = l;
  }
  for (const auto& [sheet_loop, l] : closest) is_boundary[l] = true;
  std::set<std::pair<Index, Index>> directed;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) directed.insert({t[i], t[(i + 1) % 3]});
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (is_boundary[l]) continue;
    const topology::BoundaryLoop& loop = loops[l];
    std::vector<Index> sorted = loop.vertices;
    std::sort(sorted.begin(), sorted.end());
    const bool is_simple = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
    if (loop.length > options.max_filled_hole_rel_spacing * scale[l] || loop.vertices.size() < 3 || !is_simple ||
        !close_loop(loop.vertices, mesh, directed)) {
      ++stats.holes_left;
      continue;
    }
    ++stats.holes_filled;
  }
}

}  // namespace envcrust::interpolate::detail
