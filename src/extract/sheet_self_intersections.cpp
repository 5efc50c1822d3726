// Cut out the places where the sheet passes through itself
// (SheetOptions::self_intersection_cut_rel_rho).
#include "sheet_mesh.h"

#include "envcrust/mesh.h"
#include "envcrust/mesh_graph.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <utility>

namespace envcrust::extract {

mesh::SelfIntersections smooth_self_intersections(TriangleMesh& mesh, mesh::SelfIntersections found, int rounds) {
  constexpr int kRings = 2;       // the region: the faces' vertices and two rings around them
  constexpr int kIterations = 3;  // umbrella steps per round
  if (found.face_pairs == 0 || rounds <= 0) return found;
  // Only positions move: the neighbours stay the same through the rounds.
  const topology::MeshGraph g = topology::build_mesh_graph(mesh.triangles, mesh.vertices.size());
  std::vector<std::vector<Index>> neighbours(mesh.vertices.size()), border(mesh.vertices.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const auto [a, b] = g.edges[e];
    neighbours[a].push_back(b), neighbours[b].push_back(a);
    if (g.face_count_of_edge(e) == 1) border[a].push_back(b), border[b].push_back(a);
  }
  // The positions after the round that left the fewest pairs (relaxing one fold can push the
  // sheet through a neighbouring one): a relaxation that ends with more is taken back to them.
  std::vector<Point3> best_vertices = mesh.vertices;
  mesh::SelfIntersections best = found;
  for (int round = 0;; ++round) {
    if (found.face_pairs == 0 || round == rounds) {
      if (found.face_pairs <= best.face_pairs) return found;
      mesh.vertices = std::move(best_vertices);
      return best;
    }
    std::vector<char> in_region(mesh.vertices.size(), 0);
    std::vector<Index> region;
    for (const Index f : found.face_list)
      for (const Index v : mesh.triangles[f])
        if (!in_region[v]) in_region[v] = 1, region.push_back(v);
    for (int ring = 0; ring < kRings; ++ring) {
      const std::size_t size = region.size();
      for (std::size_t k = 0; k < size; ++k)
        for (const Index w : neighbours[region[k]])
          if (!in_region[w]) in_region[w] = 1, region.push_back(w);
    }
    // A border vertex moves along the border only (between its two border neighbours), an
    // inner one to the average of its neighbours.
    std::vector<Point3> moved(region.size());
    for (int iteration = 0; iteration < kIterations; ++iteration) {
      for (std::size_t k = 0; k < region.size(); ++k) {
        const Index v = region[k];
        const auto& around = border[v].empty() ? neighbours[v] : border[v];
        if (around.empty() || (!border[v].empty() && border[v].size() != 2)) {
          moved[k] = mesh.vertices[v];
          continue;
        }
        double x = 0, y = 0, z = 0;
        for (const Index w : around) x += mesh.vertices[w].x(), y += mesh.vertices[w].y(), z += mesh.vertices[w].z();
        const auto n = static_cast<double>(around.size());
        moved[k] = Point3(x / n, y / n, z / n);
      }
      for (std::size_t k = 0; k < region.size(); ++k) mesh.vertices[region[k]] = moved[k];
    }
    // Only the faces that moved can meet others now (every pair found had a face among them).
    std::vector<char> moved_face(mesh.triangles.size(), 0);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
      for (const Index v : mesh.triangles[f]) moved_face[f] |= in_region[v];
    found = mesh::self_intersections(mesh, 0, &moved_face);
    if (found.face_pairs < best.face_pairs) {
      best = found;
      best_vertices = mesh.vertices;
    }
  }
}

std::vector<char> faces_not_in(const TriangleMesh& after, const TriangleMesh& before) {
  // A face is its corners' coordinates, in increasing order: hashed, then compared exactly.
  using Corners = std::array<Point3, 3>;
  auto corners = [](const TriangleMesh& m, std::size_t f) {
    Corners c = {m.vertices[m.triangles[f][0]], m.vertices[m.triangles[f][1]], m.vertices[m.triangles[f][2]]};
    std::sort(c.begin(), c.end());
    return c;
  };
  auto hash = [](const Corners& c) {
    std::uint64_t h = 1469598103934665603ull;
    for (const Point3& p : c)
      for (int d = 0; d < 3; ++d) {
        std::uint64_t bits;
        const double x = p[d] == 0 ? 0.0 : p[d];  // -0 and +0 alike
        std::memcpy(&bits, &x, sizeof bits);
        h = (h ^ bits) * 1099511628211ull;
      }
    return h;
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> known(before.triangles.size());
  for (std::size_t f = 0; f < before.triangles.size(); ++f) known[f] = {hash(corners(before, f)), f};
  std::sort(known.begin(), known.end());
  std::vector<char> is_new(after.triangles.size(), 1);
  for (std::size_t f = 0; f < after.triangles.size(); ++f) {
    const Corners c = corners(after, f);
    const std::uint64_t h = hash(c);
    for (auto it = std::lower_bound(known.begin(), known.end(), std::pair(h, std::size_t{0}));
         it != known.end() && it->first == h && is_new[f] != 0; ++it)
      if (corners(before, it->second) == c) is_new[f] = 0;
  }
  return is_new;
}

SelfIntersectionCutStats cut_self_intersections(TaggedMesh& tagged, const mesh::SelfIntersections& found,
                                                double radius) {
  SelfIntersectionCutStats stats;
  stats.pairs = found.face_pairs;
  if (found.face_pairs == 0) return stats;
  const TriangleMesh& mesh = tagged.mesh;
  std::vector<Index> sources;
  for (const Index f : found.face_list)
    for (const Index v : mesh.triangles[f]) sources.push_back(v);
  const topology::MeshGraph g = topology::build_mesh_graph(mesh.triangles, mesh.vertices.size());
  stats.faces_removed = remove_faces_near(tagged, g, sources, radius);
  return stats;
}

}  // namespace envcrust::extract
