// Mesh adjacency with edge lengths and geodesic (edge-path) balls.
#include "sheet_geodesic.h"
#include "sheet_mesh.h"

#include <cmath>
#include <functional>
#include <queue>

namespace envcrust::extract {

MeshAdjacency mesh_adjacency(const TriangleMesh& mesh, const topology::MeshGraph& graph) {
  MeshAdjacency a;
  const std::size_t n = mesh.vertices.size();
  a.neighbour_begin.assign(n + 1, 0);
  for (const auto& [u, v] : graph.edges) ++a.neighbour_begin[u + 1], ++a.neighbour_begin[v + 1];
  for (std::size_t v = 0; v < n; ++v) a.neighbour_begin[v + 1] += a.neighbour_begin[v];
  a.neighbours.resize(a.neighbour_begin[n]);
  std::vector<std::size_t> fill(a.neighbour_begin.begin(), a.neighbour_begin.end() - 1);
  for (const auto& [u, v] : graph.edges) {
    const double length = std::sqrt(CGAL::squared_distance(mesh.vertices[u], mesh.vertices[v]));
    a.neighbours[fill[u]++] = {v, length};
    a.neighbours[fill[v]++] = {u, length};
  }
  a.face_begin.assign(n + 1, 0);
  for (const auto& t : mesh.triangles)
    for (const Index v : t) ++a.face_begin[v + 1];
  for (std::size_t v = 0; v < n; ++v) a.face_begin[v + 1] += a.face_begin[v];
  a.faces.resize(a.face_begin[n]);
  fill.assign(a.face_begin.begin(), a.face_begin.end() - 1);
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f)
    for (const Index v : mesh.triangles[f]) a.faces[fill[v]++] = f;
  return a;
}

void GeodesicBall::grow(const MeshAdjacency& a, std::span<const Index> sources, double radius) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const Index v : reached_) distance_[v] = inf;
  reached_.clear();
  using Item = std::pair<double, Index>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (const Index s : sources) {
    if (distance_[s] == inf) reached_.push_back(s);
    distance_[s] = 0;
    queue.emplace(0.0, s);
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance_[v]) continue;
    for (std::size_t k = a.neighbour_begin[v]; k < a.neighbour_begin[v + 1]; ++k) {
      const auto [w, length] = a.neighbours[k];
      if (d + length > radius || d + length >= distance_[w]) continue;
      if (distance_[w] == inf) reached_.push_back(w);
      distance_[w] = d + length;
      queue.emplace(d + length, w);
    }
  }
}

std::size_t remove_faces_near(TaggedMesh& tagged, const topology::MeshGraph& graph, std::span<const Index> sources,
                              double radius) {
  const TriangleMesh& mesh = tagged.mesh;
  const MeshAdjacency adjacency = mesh_adjacency(mesh, graph);
  GeodesicBall ball(mesh.vertices.size());
  ball.grow(adjacency, sources, radius);
  std::vector<char> remove(mesh.triangles.size(), 0);
  for (const Index v : ball.reached())
    for (std::size_t k = adjacency.face_begin[v]; k < adjacency.face_begin[v + 1]; ++k) remove[adjacency.faces[k]] = 1;
  const std::size_t removed = remove_faces(tagged, remove);
  make_manifold(tagged);
  return removed;
}

}  // namespace envcrust::extract
