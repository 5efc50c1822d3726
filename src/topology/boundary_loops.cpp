// Boundary loops: walk the one-face edges vertex to vertex, undirected (a Moebius band has no
// consistent face order), then orient by the induced orientation where one exists.
#include "boundary_loops.h"

#include <cmath>

namespace envcrust::topology {
Polyline BoundaryLoop::polyline(const std::vector<Point3>& points) const {
  Polyline out;
  out.reserve(vertices.size());
  for (Index v : vertices) out.push_back(points[v]);
  return out;
}

std::vector<BoundaryLoop> trace_boundary_loops(const MeshGraph& g, const std::vector<Point3>& points,
                                               const std::vector<std::uint32_t>& face_component,
                                               const Orientation& orientation) {
  std::vector<std::vector<std::uint32_t>> border_edges_at(g.num_vertices);
  std::vector<std::uint32_t> border_edges;
  for (std::uint32_t e = 0; e < g.edges.size(); ++e) {
    if (g.face_count_of_edge(e) != 1) continue;
    border_edges.push_back(e);
    border_edges_at[g.edges[e].first].push_back(e);
    border_edges_at[g.edges[e].second].push_back(e);
  }
  std::vector<bool> used(g.edges.size(), false);
  std::vector<BoundaryLoop> loops;
  for (std::uint32_t start : border_edges) {
    if (used[start]) continue;
    const std::uint32_t face = g.edge_faces[g.edge_face_begin[start]];
    const std::uint32_t comp = face_component[face];
    auto [a, b] = g.edges[start];
    BoundaryLoop loop;
    loop.component = static_cast<int>(comp);
    loop.is_oriented = orientation.is_orientable[comp];
    if (loop.is_oriented && orientation.face_sign[face] * direction_along(g.faces[face], a, b) < 0)
      std::swap(a, b);
    used[start] = true;
    loop.vertices.push_back(a);
    Index current = b;
    while (current != a) {
      loop.vertices.push_back(current);
      std::uint32_t next_edge = UINT32_MAX;
      for (std::uint32_t e : border_edges_at[current]) {
        if (!used[e]) {
          next_edge = e;
          break;
        }
      }
      if (next_edge == UINT32_MAX) break;  // open chain: only at non-manifold configurations
      used[next_edge] = true;
      current = g.edges[next_edge].first == current ? g.edges[next_edge].second
                                                     : g.edges[next_edge].first;
    }
    for (std::size_t i = 0; i < loop.vertices.size(); ++i) {
      const Point3& p = points[loop.vertices[i]];
      const Point3& q = points[loop.vertices[(i + 1) % loop.vertices.size()]];
      loop.length += std::sqrt(CGAL::squared_distance(p, q));
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace envcrust::topology
