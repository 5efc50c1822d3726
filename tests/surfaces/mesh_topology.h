// A tiny local mesh-topology helper for the surfaces tests: V - E + F, boundary edges and loops,
// and whether the triangles are consistently oriented.
#pragma once

#include "envcrust/types.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

namespace envcrust::surfaces::testing {

struct MeshTopology {
  long euler_characteristic = 0;
  std::size_t boundary_edges = 0;
  std::size_t boundary_loops = 0;
  std::size_t non_manifold_edges = 0;  ///< edges with more than two triangles
  std::size_t degenerate_triangles = 0;
  bool consistently_oriented = true;  ///< every interior edge used once in each direction
};

inline MeshTopology mesh_topology(const TriangleMesh& mesh) {
  MeshTopology result;
  // Per undirected edge: (triangle count, sum of directions +1 for (lo,hi), -1 for (hi,lo)).
  std::map<std::pair<Index, Index>, std::pair<int, int>> edges;
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) ++result.degenerate_triangles;
    for (int k = 0; k < 3; ++k) {
      const Index a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      auto& entry = edges[{std::min(a, b), std::max(a, b)}];
      ++entry.first;
      entry.second += a < b ? 1 : -1;
    }
  }
  std::vector<Index> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), Index{0});
  const auto find = [&](Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::vector<bool> on_boundary(mesh.vertices.size(), false);
  for (const auto& [edge, use] : edges) {
    if (use.first == 1) {
      ++result.boundary_edges;
      on_boundary[edge.first] = on_boundary[edge.second] = true;
      parent[find(edge.first)] = find(edge.second);
    } else if (use.first > 2) {
      ++result.non_manifold_edges;
    } else if (use.second != 0) {
      result.consistently_oriented = false;
    }
  }
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    if (on_boundary[v] && find(v) == v) ++result.boundary_loops;
  }
  result.euler_characteristic = static_cast<long>(mesh.vertices.size()) -
                                static_cast<long>(edges.size()) +
                                static_cast<long>(mesh.triangles.size());
  return result;
}

}  // namespace envcrust::surfaces::testing
