// The crust: power faces between In and Out cells, vertices keyed by cell, oriented by the
// circulation around each In-Out edge, fan-triangulated (docs/method.md §7.7).
#include "incident_cells.h"
#include "robust_centres.h"
#include "stages.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace envcrust::powercrust {
namespace {

using RtCell = Regular::Cell_handle;

// A crust vertex is a power vertex, named by its cell's sorted pole ids: faces share it by
// name, so rounding never merges two cells whose vertices nearly coincide.
using CellKey = std::array<Index, 4>;

// Polygons found by one thread, flattened. Corners are kept as keys only: a power vertex is
// shared by about three polygons, so its point is computed once per key afterwards (at 1M
// samples the points stored per corner, copied once for deduplication, were the crust stage's
// peak memory).
struct PolygonChunk {
  std::vector<std::array<Index, 2>> edges;  ///< {In pole, Out pole}
  std::vector<std::size_t> starts;          ///< into corners; one past the last polygon at the end
  std::vector<CellKey> corners;
  std::size_t unbounded = 0;
};

CellKey key_of(RtCell c) {
  CellKey key{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()};
  std::sort(key.begin(), key.end());
  return key;
}

// The weighted circumcentre computed from the sites in id order, so its bits do not depend on
// the cell's vertex order. The sites are rebuilt exactly as build_power_diagram inserted them.
Point3 corner_point(const CellKey& key, const std::vector<Pole>& poles, const PowerDiagram& diagram) {
  auto weighted = [&](Index id) { return diagram.site(poles, id); };
  return power_vertex(weighted(key[0]), weighted(key[1]), weighted(key[2]), weighted(key[3]));
}

void collect_polygons(const PowerDiagram& diagram, const std::vector<Pole>& poles, Index p,
                      PolygonChunk& chunk, IncidentCells<Regular>& incident, std::vector<CellKey>& corners) {
  const Regular& rt = *diagram.rt;
  const RtVertex v = diagram.vertex_of_pole[p];
  // One representative cell per Out neighbour.
  std::vector<std::pair<Index, RtCell>> edges;
  for (RtCell c : incident(v))
    for (int j = 0; j < 4; ++j) {
      const RtVertex w = c->vertex(j);
      if (w != v && !rt.is_infinite(w) && poles[w->info()].label == PoleLabel::Out)
        edges.emplace_back(w->info(), c);
    }
  std::sort(edges.begin(), edges.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  edges.erase(std::unique(edges.begin(), edges.end(),
                          [](const auto& a, const auto& b) { return a.first == b.first; }),
              edges.end());
  for (const auto& [q, c] : edges) {
    const RtVertex w = diagram.vertex_of_pole[q];
    corners.clear();
    bool bounded = true;
    // The circulator turns positively around the oriented edge In -> Out: a combinatorial
    // orientation, consistent across faces even where rounding folds a tiny polygon (a
    // geometric Newell normal is not).
    auto circulator = rt.incident_cells(c, c->index(v), c->index(w));
    const auto done = circulator;
    do {
      if (rt.is_infinite(circulator)) {
        bounded = false;
        break;
      }
      corners.push_back(key_of(circulator));
    } while (++circulator != done);
    if (!bounded) {
      ++chunk.unbounded;
      continue;
    }
    // Start at the smallest key: the fan then does not depend on where the circulation began.
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    chunk.edges.push_back({p, q});
    chunk.starts.push_back(chunk.corners.size());
    chunk.corners.insert(chunk.corners.end(), corners.begin(), corners.end());
  }
}

// Count edges whose two triangles do not run them in opposite directions.
struct EdgeCheck {
  std::size_t boundary = 0, non_manifold = 0, misoriented = 0;
  [[nodiscard]] bool clean() const { return boundary == 0 && non_manifold == 0 && misoriented == 0; }
};

EdgeCheck check_edges(const TriangleMesh& mesh) {
  std::vector<std::array<Index, 3>> halfedges;  // {min, max, forward}
  halfedges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      halfedges.push_back({std::min(a, b), std::max(a, b), a < b ? Index{1} : Index{0}});
    }
  tbb::parallel_sort(halfedges.begin(), halfedges.end());
  EdgeCheck check;
  for (std::size_t i = 0; i < halfedges.size();) {
    std::size_t j = i;
    while (j < halfedges.size() && halfedges[j][0] == halfedges[i][0] && halfedges[j][1] == halfedges[i][1]) ++j;
    if (j - i == 1) ++check.boundary;
    else if (j - i > 2) ++check.non_manifold;
    else if (halfedges[i][2] == halfedges[i + 1][2]) ++check.misoriented;
    i = j;
  }
  return check;
}

double signed_volume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    const Vector3 a = mesh.vertices[t[0]] - CGAL::ORIGIN, b = mesh.vertices[t[1]] - CGAL::ORIGIN,
                  c = mesh.vertices[t[2]] - CGAL::ORIGIN;
    volume += a * CGAL::cross_product(b, c) / 6.0;
  }
  return volume;
}

// Let CGAL orient the soup; it duplicates vertices where the crust is not a manifold.
void orient_soup(TriangleMesh& mesh, std::vector<std::string>& warnings) {
  std::vector<Point3> points = mesh.vertices;
  std::vector<std::array<std::size_t, 3>> faces(mesh.triangles.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) faces[f][k] = mesh.triangles[f][k];
  if (!CGAL::Polygon_mesh_processing::orient_polygon_soup(points, faces))
    warnings.push_back("the crust is not an oriented manifold: orient_polygon_soup duplicated " +
                       std::to_string(points.size() - mesh.vertices.size()) + " vertices");
  mesh.vertices = std::move(points);
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) mesh.triangles[f][k] = static_cast<Index>(faces[f][k]);
}

}  // namespace

CrustStage extract_crust(const PowerDiagram& diagram, const std::vector<Pole>& poles) {
  std::vector<Index> inner;
  for (std::size_t p = 0; p < poles.size(); ++p)
    if (poles[p].label == PoleLabel::In && !poles[p].is_hidden) inner.push_back(static_cast<Index>(p));

  tbb::enumerable_thread_specific<PolygonChunk> chunks;
  tbb::enumerable_thread_specific<std::pair<IncidentCells<Regular>, std::vector<CellKey>>> scratch;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, inner.size(), 256),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      auto& chunk = chunks.local();
                      auto& [incident, corners] = scratch.local();
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        collect_polygons(diagram, poles, inner[i], chunk, incident, corners);
                    });

  // Gather polygons in (In, Out) order: the output does not depend on the thread schedule.
  struct Ref { std::array<Index, 2> edge; const PolygonChunk* chunk; std::size_t index; };
  std::vector<Ref> refs;
  CrustStage out;
  for (auto& chunk : chunks) {
    chunk.starts.push_back(chunk.corners.size());
    out.unbounded_faces += chunk.unbounded;
    for (std::size_t i = 0; i + 1 < chunk.starts.size(); ++i) refs.push_back({chunk.edges[i], &chunk, i});
  }
  tbb::parallel_sort(refs.begin(), refs.end(), [](const Ref& a, const Ref& b) { return a.edge < b.edge; });
  out.polygons = refs.size();

  std::vector<CellKey> keys;
  for (const auto& chunk : chunks) keys.insert(keys.end(), chunk.corners.begin(), chunk.corners.end());
  tbb::parallel_sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  keys.shrink_to_fit();
  // Vertices stay apart by cell even where their positions coincide: every sample is a
  // degenerate power vertex (all polar balls through it have power 0 there) that symbolic
  // perturbation splits into several cells, and merging those by position pinches the crust
  // (measured: a hundred non-manifold edges on a noisy 5k sphere, none without merging).
  auto id_of = [&](const CellKey& key) {
    return static_cast<Index>(std::lower_bound(keys.begin(), keys.end(), key) - keys.begin());
  };
  std::size_t triangles = 0;
  for (const Ref& ref : refs) triangles += ref.chunk->starts[ref.index + 1] - ref.chunk->starts[ref.index] - 2;
  out.mesh.triangles.reserve(triangles);
  out.face_poles.reserve(triangles);
  std::vector<Index> polygon;
  for (const Ref& ref : refs) {
    polygon.clear();
    for (std::size_t k = ref.chunk->starts[ref.index]; k < ref.chunk->starts[ref.index + 1]; ++k)
      polygon.push_back(id_of(ref.chunk->corners[k]));
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      out.mesh.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
      out.face_poles.push_back(ref.edge);
    }
  }
  refs = {};
  chunks.clear();
  out.mesh.vertices.resize(keys.size());
  tbb::parallel_for(std::size_t{0}, keys.size(),
                    [&](std::size_t i) { out.mesh.vertices[i] = corner_point(keys[i], poles, diagram); });
  keys = {};

  if (out.unbounded_faces > 0)
    out.warnings.push_back(std::to_string(out.unbounded_faces) +
                           " In-Out power faces are unbounded (an In pole on the hull of the poles) and were skipped");
  // The circulation's sense is a fixed convention of the TDS: flip everything if it made the
  // crust face inwards.
  if (signed_volume(out.mesh) < 0)
    for (auto& t : out.mesh.triangles) std::swap(t[1], t[2]);
  const EdgeCheck check = check_edges(out.mesh);
  if (!check.clean()) {
    out.warnings.push_back("the crust has " + std::to_string(check.boundary) + " boundary, " +
                           std::to_string(check.non_manifold) + " non-manifold and " +
                           std::to_string(check.misoriented) + " misoriented edges");
    orient_soup(out.mesh, out.warnings);
  }
  if (signed_volume(out.mesh) < 0)
    out.warnings.push_back("the crust encloses a negative volume: it is oriented inwards");
  return out;
}

}  // namespace envcrust::powercrust
