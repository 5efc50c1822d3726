// Welding of vertices with identical coordinates (exact), removal of unused vertices and of
// repeated faces.
#include "envcrust/mesh.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <tuple>

namespace envcrust::mesh {

TriangleMesh weld_identical_vertices(const TriangleMesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  // Sorted by coordinates, then index: positions are copied next to their index so the
  // parallel sort compares contiguous records.
  struct Keyed {
    double x, y, z;
    Index index;
    bool operator<(const Keyed& o) const { return std::tie(x, y, z, index) < std::tie(o.x, o.y, o.z, o.index); }
  };
  std::vector<Keyed> keyed(n);
  for (std::size_t v = 0; v < n; ++v)
    keyed[v] = {mesh.vertices[v].x(), mesh.vertices[v].y(), mesh.vertices[v].z(), static_cast<Index>(v)};
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<Index> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = keyed[i].index;
  // Representative of each vertex: the smallest index with the same coordinates.
  std::vector<Index> representative(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j < n && mesh.vertices[order[j]] == mesh.vertices[order[i]]) ++j;
    for (std::size_t k = i; k < j; ++k) representative[order[k]] = order[i];
    i = j;
  }
  std::vector<bool> used(n, false);
  for (const auto& t : mesh.triangles)
    for (Index v : t) used[representative[v]] = true;
  constexpr Index kUnset = ~Index{0};
  std::vector<Index> new_index(n, kUnset);
  TriangleMesh out;
  for (std::size_t v = 0; v < n; ++v) {
    if (used[v] && representative[v] == v) {
      new_index[v] = static_cast<Index>(out.vertices.size());
      out.vertices.push_back(mesh.vertices[v]);
    }
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    out.triangles.push_back({new_index[representative[t[0]]], new_index[representative[t[1]]],
                             new_index[representative[t[2]]]});
  }
  return out;
}

std::size_t used_vertex_count(const TriangleMesh& mesh) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (Index v : t)
      if (v < used.size()) used[v] = 1;
  return static_cast<std::size_t>(std::count(used.begin(), used.end(), char{1}));
}

std::vector<char> repeated_or_degenerate_faces(const TriangleMesh& mesh) {
  std::vector<std::pair<std::array<Index, 3>, std::size_t>> keys;
  keys.reserve(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    auto key = mesh.triangles[f];
    std::sort(key.begin(), key.end());
    keys.emplace_back(key, f);
  }
  tbb::parallel_sort(keys.begin(), keys.end());
  std::vector<char> drop(mesh.triangles.size(), 0);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    const auto& [key, f] = keys[k];
    if (key[0] == key[1] || key[1] == key[2] || (k > 0 && keys[k - 1].first == key)) drop[f] = 1;
  }
  return drop;
}

std::size_t remove_duplicate_faces(TriangleMesh& mesh) {
  const std::vector<char> drop = repeated_or_degenerate_faces(mesh);
  std::size_t kept = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (!drop[f]) mesh.triangles[kept++] = mesh.triangles[f];
  const std::size_t dropped = mesh.triangles.size() - kept;
  mesh.triangles.resize(kept);
  return dropped;
}

}  // namespace envcrust::mesh
