// analyze_topology: weld, classify faces, build the edge table, then count everything.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/topology.h"

#include "boundary_loops.h"
#include "envcrust/mesh_graph.h"

#include <algorithm>
#include <string>

namespace envcrust::topology {
namespace {

void check_indices(const TriangleMesh& mesh) {
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (Index v : mesh.triangles[f]) {
      if (v >= mesh.vertices.size()) {
        throw InvalidInput("face " + std::to_string(f) + " has vertex index " +
                           std::to_string(v) + ", but the mesh has " +
                           std::to_string(mesh.vertices.size()) + " vertices");
      }
    }
  }
}

}  // namespace

MeshTopology analyze_topology(const TriangleMesh& input, const TopologyOptions& options) {
  check_indices(input);
  MeshTopology out;
  out.input_vertices = input.vertices.size();

  // Weld identical positions but keep every face (weld_identical_vertices drops unused
  // vertices, which is what we want for V).
  const TriangleMesh mesh =
      options.weld_identical_vertices ? mesh::weld_identical_vertices(input) : input;
  {
    std::vector<bool> referenced(input.vertices.size(), false);
    for (const auto& t : input.triangles)
      for (Index v : t) referenced[v] = true;
    std::size_t used_input = 0;
    for (bool r : referenced) used_input += r ? 1 : 0;
    out.unused_vertices = input.vertices.size() - used_input;
    out.welded_vertices = options.weld_identical_vertices ? used_input - mesh.vertices.size() : 0;
  }

  std::vector<std::array<Index, 3>> faces;
  faces.reserve(mesh.triangles.size());
  std::vector<std::array<Index, 3>> seen;
  seen.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++out.degenerate_faces;  // not a triangle: ignored by the topology
      continue;
    }
    if (CGAL::collinear(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]))
      ++out.degenerate_faces;  // zero area, still a simplex
    auto key = t;
    std::sort(key.begin(), key.end());
    seen.push_back(key);
    faces.push_back(t);
  }
  std::sort(seen.begin(), seen.end());
  out.duplicate_faces =
      static_cast<std::size_t>(seen.end() - std::unique(seen.begin(), seen.end()));

  // Vertices of ignored faces only do not count.
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& f : faces)
    for (Index v : f) used[v] = true;
  out.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  out.points = mesh.vertices;

  const MeshGraph g = build_mesh_graph(std::move(faces), mesh.vertices.size());
  out.faces = g.faces.size();
  out.edges = g.edges.size();
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const std::size_t n = g.face_count_of_edge(e);
    if (n == 1) ++out.boundary_edges;
    if (n >= 3) ++out.non_manifold_edges;
    if (n == 2) {
      const std::uint32_t f0 = g.edge_faces[g.edge_face_begin[e]];
      const std::uint32_t f1 = g.edge_faces[g.edge_face_begin[e] + 1];
      const auto [a, b] = g.edges[e];
      if (direction_along(g.faces[f0], a, b) == direction_along(g.faces[f1], a, b))
        ++out.misoriented_edges;
    }
  }
  const auto fans = count_vertex_fans(g);
  for (std::size_t v = 0; v < fans.size(); ++v)
    if (fans[v] > 1) ++out.non_manifold_vertices;
  out.euler_characteristic = static_cast<long>(out.vertices) - static_cast<long>(out.edges) +
                             static_cast<long>(out.faces);

  // Components: faces joined through any shared edge.
  std::vector<std::uint32_t> component;
  const std::uint32_t num_components = face_components(g, component);
  out.components.resize(num_components);
  const Orientation orientation = orient_components(g, component, num_components);

  for (std::uint32_t f = 0; f < g.faces.size(); ++f) ++out.components[component[f]].faces;
  // A vertex shared by two components (a pinch) counts in both.
  {
    std::vector<std::pair<std::uint32_t, Index>> pairs;
    pairs.reserve(3 * g.faces.size());
    for (std::uint32_t f = 0; f < g.faces.size(); ++f)
      for (Index v : g.faces[f]) pairs.emplace_back(component[f], v);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    for (const auto& [c, v] : pairs) ++out.components[c].vertices;
    for (const auto& [c, v] : pairs)
      if (fans[v] > 1) out.components[c].is_manifold = false;
  }
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    auto& c = out.components[component[g.edge_faces[g.edge_face_begin[e]]]];
    ++c.edges;
    if (g.face_count_of_edge(e) >= 3) c.is_manifold = false;
  }

  out.boundary_loops = trace_boundary_loops(g, mesh.vertices, component, orientation);
  for (const auto& loop : out.boundary_loops) ++out.components[loop.component].boundary_loops;

  for (std::uint32_t i = 0; i < num_components; ++i) {
    auto& c = out.components[i];
    c.euler_characteristic = static_cast<long>(c.vertices) - static_cast<long>(c.edges) +
                             static_cast<long>(c.faces);
    c.is_orientable = orientation.is_orientable[i];
    if (!c.is_orientable) out.is_orientable = false;
    if (c.is_manifold) {
      const long deficit = 2 - c.euler_characteristic - c.boundary_loops;
      if (c.is_orientable && deficit % 2 == 0) c.genus = deficit / 2;
      if (!c.is_orientable) c.genus = deficit;
    }
  }
  return out;
}

std::optional<long> total_genus(const MeshTopology& topology) {
  long sum = 0;
  for (const auto& c : topology.components) {
    if (!c.genus) return std::nullopt;
    sum += *c.genus;
  }
  return sum;
}

std::vector<BoundaryLoop> boundary_loops(const TriangleMesh& mesh) {
  check_indices(mesh);
  std::vector<std::array<Index, 3>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) faces.push_back(t);
  const MeshGraph g = build_mesh_graph(std::move(faces), mesh.vertices.size());
  const std::vector<std::uint32_t> one_component(g.faces.size(), 0);
  const Orientation unoriented{{}, {false}};
  std::vector<BoundaryLoop> loops = trace_boundary_loops(g, mesh.vertices, one_component, unoriented);
  for (auto& loop : loops) loop.component = -1;
  return loops;
}

}  // namespace envcrust::topology
