// Construction of the edge table and of the vertex fans (non-manifold vertex detection).
#include "envcrust/mesh_graph.h"

#include "envcrust/union_find.h"


#include <algorithm>
#include <tuple>

namespace envcrust::topology {

int direction_along(const std::array<Index, 3>& face, Index a, Index b) {
  for (int k = 0; k < 3; ++k) {
    if (face[k] == a && face[(k + 1) % 3] == b) return 1;
    if (face[k] == b && face[(k + 1) % 3] == a) return -1;
  }
  return 0;
}

MeshGraph build_mesh_graph(std::vector<std::array<Index, 3>> faces, std::size_t num_vertices) {
  MeshGraph g;
  g.num_vertices = num_vertices;
  g.faces = std::move(faces);
  struct HalfEdge {
    Index a, b;
    std::uint32_t face;
    std::uint8_t slot;
  };
  // Sorted by (a, b, face, slot) without a comparison sort (it was the largest cost of the
  // sheet's cleaning, which rebuilds this table a dozen times): a counting sort by a, which
  // keeps the (face, slot) order of generation, then a stable insertion sort by b within each
  // vertex's few half-edges.
  std::vector<std::uint32_t> start(num_vertices + 1, 0);
  for (const auto& f : g.faces)
    for (std::uint8_t k = 0; k < 3; ++k) ++start[std::min(f[k], f[(k + 1) % 3]) + 1];
  for (std::size_t v = 0; v < num_vertices; ++v) start[v + 1] += start[v];
  std::vector<HalfEdge> half_edges(3 * g.faces.size());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::uint32_t f = 0; f < g.faces.size(); ++f)
      for (std::uint8_t k = 0; k < 3; ++k) {
        Index a = g.faces[f][k];
        Index b = g.faces[f][(k + 1) % 3];
        if (a > b) std::swap(a, b);
        half_edges[fill[a]++] = {a, b, f, k};
      }
  }
  for (std::size_t v = 0; v < num_vertices; ++v) {
    if (start[v + 1] - start[v] > 64) {  // a high-degree vertex (a fan over a long hole)
      std::stable_sort(half_edges.begin() + start[v], half_edges.begin() + start[v + 1],
                       [](const HalfEdge& x, const HalfEdge& y) { return x.b < y.b; });
      continue;
    }
    for (std::uint32_t i = start[v] + 1; i < start[v + 1]; ++i) {
      const HalfEdge h = half_edges[i];
      std::uint32_t j = i;
      for (; j > start[v] && half_edges[j - 1].b > h.b; --j) half_edges[j] = half_edges[j - 1];
      half_edges[j] = h;
    }
  }
  g.edges.reserve(half_edges.size() / 2 + 1);
  g.edge_face_begin.reserve(half_edges.size() / 2 + 2);
  g.face_edges.resize(g.faces.size());
  g.edge_faces.reserve(half_edges.size());
  for (std::size_t i = 0; i < half_edges.size();) {
    std::size_t j = i;
    const auto e = static_cast<std::uint32_t>(g.edges.size());
    g.edges.emplace_back(half_edges[i].a, half_edges[i].b);
    g.edge_face_begin.push_back(static_cast<std::uint32_t>(g.edge_faces.size()));
    while (j < half_edges.size() && half_edges[j].a == half_edges[i].a &&
           half_edges[j].b == half_edges[i].b) {
      g.edge_faces.push_back(half_edges[j].face);
      g.face_edges[half_edges[j].face][half_edges[j].slot] = e;
      ++j;
    }
    i = j;
  }
  g.edge_face_begin.push_back(static_cast<std::uint32_t>(g.edge_faces.size()));
  return g;
}

std::vector<std::uint32_t> corner_fans(const MeshGraph& g) {
  // Corners (face, slot) are united when their faces share an edge at that corner's vertex;
  // the fans of a vertex are then the classes among its corners.
  UnionFind corners(3 * g.faces.size());
  auto corner_of = [&](std::uint32_t face, Index vertex) {
    const auto& f = g.faces[face];
    const std::uint32_t slot = f[0] == vertex ? 0 : (f[1] == vertex ? 1 : 2);
    return 3 * face + slot;
  };
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const std::uint32_t begin = g.edge_face_begin[e];
    const std::uint32_t end = g.edge_face_begin[e + 1];
    for (std::uint32_t i = begin + 1; i < end; ++i) {
      for (Index v : {g.edges[e].first, g.edges[e].second}) {
        corners.unite(corner_of(g.edge_faces[begin], v), corner_of(g.edge_faces[i], v));
      }
    }
  }
  std::vector<std::uint32_t> fan(3 * g.faces.size());
  for (std::uint32_t c = 0; c < fan.size(); ++c) fan[c] = corners.find(c);
  return fan;
}

std::vector<std::uint32_t> count_vertex_fans(const MeshGraph& g) {
  // All corners of a fan share its vertex, and each fan has one root corner: a vertex has as
  // many fans as it has root corners.
  const auto fan = corner_fans(g);
  std::vector<std::uint32_t> fans(g.num_vertices, 0);
  for (std::uint32_t c = 0; c < fan.size(); ++c)
    if (fan[c] == c) ++fans[g.faces[c / 3][c % 3]];
  return fans;
}

std::uint32_t face_components(const MeshGraph& graph, std::vector<std::uint32_t>& label) {
  UnionFind uf(graph.faces.size());
  for (std::size_t e = 0; e < graph.edges.size(); ++e)
    for (std::uint32_t k = graph.edge_face_begin[e] + 1; k < graph.edge_face_begin[e + 1]; ++k)
      uf.unite(graph.edge_faces[graph.edge_face_begin[e]], graph.edge_faces[k]);
  return uf.label_sets(label);
}

}  // namespace envcrust::topology
