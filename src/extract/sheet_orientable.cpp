// Cut a non-orientable sheet open around its orientation seams (SheetOptions::cut_to_orientable).
#include "sheet_mesh.h"

#include "envcrust/mesh_graph.h"
#include "envcrust/topology.h"
#include "envcrust/union_find.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace envcrust::extract {
namespace {

// Two-face edges that both faces run in the same direction, after orient_faces: the seams
// across which no consistent orientation exists.
std::vector<std::size_t> seam_edges(const TriangleMesh& mesh, const topology::MeshGraph& g) {
  auto runs_forward = [&](std::uint32_t f, Index a, Index b) {
    const auto& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k)
      if (t[k] == a && t[(k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<std::size_t> seams;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (g.face_count_of_edge(e) != 2) continue;
    const auto [a, b] = g.edges[e];
    const std::uint32_t f0 = g.edge_faces[g.edge_face_begin[e]], f1 = g.edge_faces[g.edge_face_begin[e] + 1];
    if (runs_forward(f0, a, b) == runs_forward(f1, a, b)) seams.push_back(e);
  }
  return seams;
}

// Distance along mesh edges from the nearest seam vertex, up to `radius` (farther: infinity).
std::vector<double> distance_from_seams(const TriangleMesh& mesh, const topology::MeshGraph& g,
                                        const std::vector<std::size_t>& seams, double radius) {
  std::vector<std::vector<std::pair<Index, double>>> adjacent(mesh.vertices.size());
  for (const auto& [a, b] : g.edges) {
    const double length = std::sqrt(CGAL::squared_distance(mesh.vertices[a], mesh.vertices[b]));
    adjacent[a].emplace_back(b, length);
    adjacent[b].emplace_back(a, length);
  }
  std::vector<double> distance(mesh.vertices.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (const std::size_t e : seams)
    for (const Index v : {g.edges[e].first, g.edges[e].second}) {
      distance[v] = 0;
      queue.emplace(0.0, v);
    }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance[v]) continue;
    for (const auto& [w, length] : adjacent[v])
      if (d + length <= radius && d + length < distance[w]) {
        distance[w] = d + length;
        queue.emplace(d + length, w);
      }
  }
  return distance;
}

std::size_t count_seams(const topology::MeshGraph& g, const std::vector<std::size_t>& seams, std::size_t vertices) {
  topology::UnionFind uf(vertices);
  for (const std::size_t e : seams) uf.unite(g.edges[e].first, g.edges[e].second);
  std::vector<Index> roots;
  for (const std::size_t e : seams) roots.push_back(uf.find(g.edges[e].first));
  std::sort(roots.begin(), roots.end());
  return static_cast<std::size_t>(std::unique(roots.begin(), roots.end()) - roots.begin());
}

}  // namespace

OrientableCutStats cut_to_orientable(TaggedMesh& tagged, double radius, int max_rounds) {
  OrientableCutStats stats;
  for (int round = 0; round < max_rounds; ++round) {
    TriangleMesh& mesh = tagged.mesh;
    topology::orient_faces(mesh);  // flips in place: face order, hence the tags, stay
    const topology::MeshGraph g = topology::build_mesh_graph(mesh.triangles, mesh.vertices.size());
    const std::vector<std::size_t> seams = seam_edges(mesh, g);
    if (seams.empty()) return stats;
    if (round == 0) stats.seams = count_seams(g, seams, mesh.vertices.size());
    const std::vector<double> distance = distance_from_seams(mesh, g, seams, radius);
    std::vector<char> remove(mesh.triangles.size(), 0);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (const Index v : mesh.triangles[f]) remove[f] = remove[f] || distance[v] <= radius;
    stats.faces_removed += remove_faces(tagged, remove);
    // Removing a band can pinch vertices where it touched the border.
    make_manifold(tagged);
  }
  topology::orient_faces(tagged.mesh);
  const topology::MeshGraph g = topology::build_mesh_graph(tagged.mesh.triangles, tagged.mesh.vertices.size());
  stats.still_non_orientable = !seam_edges(tagged.mesh, g).empty();
  return stats;
}

}  // namespace envcrust::extract
