// cut_along_seam / split_long_seam_edges / weld: a non-orientable manifold opened into an
// orientable one along the edges where greedy orientation fails, and closed again.
#include "seam.h"

#include "envcrust/errors.h"
#include "envcrust/mesh_graph.h"
#include "envcrust/union_find.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

namespace envcrust::remesh {
namespace {

std::uint64_t pair_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// The points that split one long seam edge, from its smaller key to its larger one.
struct SeamSplit {
  Index from_key = 0;
  std::vector<Index> keys;
  std::vector<Point3> points;
};

}  // namespace

CutMesh cut_along_seam(const TriangleMesh& mesh, const std::vector<std::uint32_t>& first_faces) {
  const std::size_t n = mesh.vertices.size();
  const auto graph = topology::build_mesh_graph(mesh.triangles, n);
  const auto sign =
      topology::orient_components(graph, std::vector<std::uint32_t>(graph.faces.size(), 0), 1, first_faces).face_sign;

  CutMesh cut;
  auto& faces = cut.mesh.triangles;
  faces = mesh.triangles;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    if (sign[f] < 0) {
      std::swap(faces[f][1], faces[f][2]);
      ++cut.reversed_faces;
    }
  }

  // Corners (face, slot) of one vertex stay together when their faces share a non-seam edge
  // at it; each class of corners becomes one vertex of the cut mesh.
  topology::UnionFind corners(3 * faces.size());
  auto corner_of = [&](std::uint32_t face, Index vertex) {
    const auto& t = faces[face];
    return 3 * face + (t[0] == vertex ? 0 : (t[1] == vertex ? 1 : 2));
  };
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    if (graph.face_count_of_edge(e) != 2) continue;
    const std::uint32_t f0 = graph.edge_faces[graph.edge_face_begin[e]];
    const std::uint32_t f1 = graph.edge_faces[graph.edge_face_begin[e] + 1];
    const auto [a, b] = graph.edges[e];
    if (topology::direction_along(faces[f0], a, b) == topology::direction_along(faces[f1], a, b)) {
      cut.seam_edges.push_back({a, b});
      continue;
    }
    for (const Index v : {a, b}) corners.unite(corner_of(f0, v), corner_of(f1, v));
  }

  // The first class met of a vertex keeps its index; the others are new copies.
  cut.mesh.vertices = mesh.vertices;
  cut.weld_key.resize(n);
  std::iota(cut.weld_key.begin(), cut.weld_key.end(), Index{0});
  constexpr Index unset = kNoWeldKey;
  std::vector<Index> vertex_of_class(3 * faces.size(), unset);
  std::vector<bool> taken(n, false);
  for (std::uint32_t f = 0; f < faces.size(); ++f) {
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t root = corners.find(3 * f + k);
      const Index v = faces[f][k];
      if (vertex_of_class[root] == unset) {
        if (!taken[v]) {
          taken[v] = true;
          vertex_of_class[root] = v;
        } else {
          vertex_of_class[root] = static_cast<Index>(cut.mesh.vertices.size());
          cut.mesh.vertices.push_back(mesh.vertices[v]);
          cut.weld_key.push_back(v);
        }
      }
      faces[f][k] = vertex_of_class[root];
    }
  }
  cut.on_seam.assign(cut.mesh.vertices.size(), false);
  for (std::size_t v = n; v < cut.mesh.vertices.size(); ++v) cut.on_seam[v] = cut.on_seam[cut.weld_key[v]] = true;
  return cut;
}

void split_long_seam_edges(CutMesh& cut, double max_length) {
  Index next_key = 0;
  for (const Index k : cut.weld_key) next_key = std::max(next_key, k + 1);
  std::unordered_map<Index, Point3> key_position;
  for (std::size_t v = 0; v < cut.mesh.vertices.size(); ++v)
    if (cut.on_seam[v]) key_position.emplace(cut.weld_key[v], cut.mesh.vertices[v]);

  // Plan the splits once per seam edge, so that both sides get the very same points.
  std::unordered_map<std::uint64_t, SeamSplit> splits;
  std::vector<std::array<Index, 2>> seam_edges;
  auto add_edge = [&](Index x, Index y) { seam_edges.push_back({std::min(x, y), std::max(x, y)}); };
  for (const auto& [a, b] : cut.seam_edges) {
    const Point3& pa = key_position.at(a);
    const Point3& pb = key_position.at(b);
    const double length = std::sqrt(CGAL::squared_distance(pa, pb));
    const auto pieces = static_cast<std::size_t>(std::ceil(length / max_length));
    if (pieces < 2) {
      add_edge(a, b);
      continue;
    }
    SeamSplit& s = splits[pair_key(a, b)];
    s.from_key = a;
    Index previous = a;
    for (std::size_t i = 1; i < pieces; ++i) {
      s.keys.push_back(next_key++);
      s.points.push_back(pa + (pb - pa) * (static_cast<double>(i) / static_cast<double>(pieces)));
      add_edge(previous, s.keys.back());
      previous = s.keys.back();
    }
    add_edge(previous, b);
  }
  if (splits.empty()) return;

  // Each face with a long seam edge becomes a polygon with the split points inserted, then a
  // fan: from its third corner if one edge was split, else from a new interior centroid.
  auto& mesh = cut.mesh;
  const std::size_t face_count = mesh.triangles.size();
  for (std::size_t f = 0; f < face_count; ++f) {
    const auto t = mesh.triangles[f];
    std::vector<Index> polygon;
    int split_edges = 0, split_slot = 0;
    for (int k = 0; k < 3; ++k) {
      const Index u = t[k], v = t[(k + 1) % 3];
      polygon.push_back(u);
      if (!cut.on_seam[u] || !cut.on_seam[v]) continue;
      const auto it = splits.find(pair_key(cut.weld_key[u], cut.weld_key[v]));
      if (it == splits.end()) continue;
      ++split_edges;
      split_slot = k;
      const SeamSplit& s = it->second;
      std::vector<Index> inserted;
      for (std::size_t i = 0; i < s.keys.size(); ++i) {
        inserted.push_back(static_cast<Index>(mesh.vertices.size()));
        mesh.vertices.push_back(s.points[i]);
        cut.weld_key.push_back(s.keys[i]);
        cut.on_seam.push_back(true);
      }
      if (cut.weld_key[u] != s.from_key) std::reverse(inserted.begin(), inserted.end());
      polygon.insert(polygon.end(), inserted.begin(), inserted.end());
    }
    if (split_edges == 0) continue;
    std::size_t apex_at = 0;
    Index apex = 0;
    if (split_edges == 1) {
      apex = t[(split_slot + 2) % 3];
      apex_at = static_cast<std::size_t>(std::find(polygon.begin(), polygon.end(), apex) - polygon.begin());
    } else {
      Vector3 sum(0, 0, 0);
      for (const Index v : t) sum = sum + (mesh.vertices[v] - CGAL::ORIGIN);
      apex = static_cast<Index>(mesh.vertices.size());
      mesh.vertices.push_back(CGAL::ORIGIN + sum / 3.0);
      cut.weld_key.push_back(kNoWeldKey);
      cut.on_seam.push_back(false);
    }
    // Fan around the polygon (in face order, so the orientation is kept), skipping the two
    // polygon edges at the apex when the apex is a corner of it.
    std::vector<std::array<Index, 3>> fan;
    const std::size_t m = polygon.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Index p = polygon[i], q = polygon[(i + 1) % m];
      if (split_edges == 1 && (i == apex_at || (i + 1) % m == apex_at)) continue;
      fan.push_back({apex, p, q});
    }
    mesh.triangles[f] = fan.front();
    mesh.triangles.insert(mesh.triangles.end(), fan.begin() + 1, fan.end());
  }
  cut.seam_edges = std::move(seam_edges);
}

TriangleMesh weld(const TriangleMesh& mesh, const std::vector<Index>& key) {
  TriangleMesh out;
  std::vector<Index> index(mesh.vertices.size());
  std::unordered_map<Index, Index> first_copy;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (key[v] != kNoWeldKey) {
      const auto [it, inserted] = first_copy.emplace(key[v], static_cast<Index>(out.vertices.size()));
      if (!inserted) {
        if (out.vertices[it->second] != mesh.vertices[v])
          throw NumericalFailure("remeshing: the two sides of the seam moved apart (vertex key " +
                                 std::to_string(key[v]) + ")");
        index[v] = it->second;
        continue;
      }
    }
    index[v] = static_cast<Index>(out.vertices.size());
    out.vertices.push_back(mesh.vertices[v]);
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) out.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  return out;
}

}  // namespace envcrust::remesh
