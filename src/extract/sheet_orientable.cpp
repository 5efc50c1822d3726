// Cut a non-orientable sheet open around its orientation seams (SheetOptions::cut_to_orientable).
#include "sheet_geodesic.h"
#include "sheet_mesh.h"

#include "envcrust/mesh_graph.h"
#include "envcrust/topology.h"
#include "envcrust/union_find.h"

#include <algorithm>

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
    std::vector<Index> seam_vertices;
    for (const std::size_t e : seams) seam_vertices.push_back(g.edges[e].first), seam_vertices.push_back(g.edges[e].second);
    const MeshAdjacency adjacency = mesh_adjacency(mesh, g);
    GeodesicBall band(mesh.vertices.size());
    band.grow(adjacency, seam_vertices, radius);
    std::vector<char> remove(mesh.triangles.size(), 0);
    for (const Index v : band.reached())
      for (std::size_t k = adjacency.face_begin[v]; k < adjacency.face_begin[v + 1]; ++k) remove[adjacency.faces[k]] = 1;
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
