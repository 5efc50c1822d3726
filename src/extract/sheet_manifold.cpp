// The sheet's last cleaning step: make the mesh a 2-manifold as the analyzer sees it (vertices
// welded by position), or drop the faces where it cannot (docs/method.md §8.4).
#include "sheet_mesh.h"

#include "envcrust/mesh.h"
#include "envcrust/mesh_graph.h"

#include <algorithm>
#include <limits>

namespace envcrust::extract {
namespace {

// Weld vertices with identical coordinates, keeping the tags; faces with a repeated vertex
// after welding, or the vertex set of an earlier face, are dropped. Returns {vertices merged, faces dropped}.
std::pair<std::size_t, std::size_t> weld_and_drop_degenerate(TaggedMesh& t) {
  const std::size_t used_before = [&] {
    std::vector<char> used(t.mesh.vertices.size(), 0);
    for (const auto& f : t.mesh.triangles)
      for (Index v : f) used[v] = 1;
    return static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));
  }();
  TriangleMesh welded = mesh::weld_identical_vertices(t.mesh);
  const std::size_t merged = used_before - welded.vertices.size();
  const std::vector<char> drop = mesh::repeated_or_degenerate_faces(welded);
  std::size_t kept = 0;
  for (std::size_t f = 0; f < welded.triangles.size(); ++f) {
    if (drop[f]) continue;
    welded.triangles[kept] = welded.triangles[f];
    t.face_dot[kept] = t.face_dot[f];
    ++kept;
  }
  const std::size_t dropped = welded.triangles.size() - kept;
  welded.triangles.resize(kept);
  t.face_dot.resize(kept);
  t.mesh = std::move(welded);
  return {merged, dropped};
}

// Non-manifold edges (three or more faces) and pinched vertices (several fans).
struct Defects {
  std::size_t edges = 0;
  std::size_t vertices = 0;
  [[nodiscard]] bool empty() const { return edges == 0 && vertices == 0; }
};

// The defects of the mesh, and in `faces` the faces at them: every face of a non-manifold
// edge, and at a pinched vertex every face outside its largest fan.
Defects find_defects(const TriangleMesh& m, std::vector<char>& faces) {
  Defects out;
  faces.assign(m.triangles.size(), 0);
  if (m.triangles.empty()) return out;
  const auto g = topology::build_mesh_graph(m.triangles, m.vertices.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (g.face_count_of_edge(e) < 3) continue;
    ++out.edges;
    for (std::uint32_t i = g.edge_face_begin[e]; i < g.edge_face_begin[e + 1]; ++i) faces[g.edge_faces[i]] = 1;
  }
  // At a pinched vertex (several fans) every face outside its largest fan goes. Fans are
  // identified by their root corner (corner_fans), which lies at their vertex.
  const auto fan = topology::corner_fans(g);
  std::vector<std::uint32_t> fan_faces(fan.size(), 0);
  for (const std::uint32_t root : fan) ++fan_faces[root];
  constexpr auto kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> largest(g.num_vertices, kNone);
  std::vector<std::uint32_t> fan_count(g.num_vertices, 0);
  for (std::uint32_t c = 0; c < fan.size(); ++c) {
    if (fan[c] != c) continue;
    const Index v = g.faces[c / 3][c % 3];
    ++fan_count[v];
    if (largest[v] == kNone || fan_faces[c] > fan_faces[largest[v]]) largest[v] = c;
  }
  for (const auto count : fan_count) out.vertices += count > 1 ? 1 : 0;
  for (std::uint32_t c = 0; c < fan.size(); ++c) {
    const Index v = g.faces[c / 3][c % 3];
    if (fan_count[v] > 1 && fan[c] != largest[v]) faces[c / 3] = 1;
  }
  return out;
}

}  // namespace

ManifoldRepairStats make_manifold(TaggedMesh& t, int max_rounds) {
  ManifoldRepairStats stats;
  auto weld = [&] {
    const auto [merged, degenerate] = weld_and_drop_degenerate(t);
    stats.vertices_welded += merged;
    stats.degenerate_faces_removed += degenerate;
  };
  weld();
  // Each check also marks the faces at the defects it finds, for the removal below.
  std::vector<char> remove;
  Defects defects = find_defects(t.mesh, remove);
  if (defects.empty()) return stats;  // vertex order kept
  stats.non_manifold_edges_found = defects.edges;
  stats.non_manifold_vertices_found = defects.vertices;
  for (int round = 0; round < max_rounds && !defects.empty(); ++round) {
    ++stats.rounds;
    stats.non_manifold_faces_removed += resolve_non_manifold_edges(t);
    stats.vertices_split += split_pinched_vertices(t);
    weld();
    defects = find_defects(t.mesh, remove);
  }
  // What the rounds could not repair goes: the faces at the remaining defects, until none is
  // left (each pass removes at least one face, so this ends).
  while (!defects.empty()) {
    stats.faces_dropped += remove_faces(t, remove);
    weld();
    defects = find_defects(t.mesh, remove);
  }
  compact_vertices(t);
  return stats;
}

}  // namespace envcrust::extract
