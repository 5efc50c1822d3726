// orient_along_normals: turn each edge-connected piece of a mesh to face like the normals of
// the samples it was made from.
#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>

namespace envcrust::mesh {
namespace {

// Edge-connected components of the faces: one label per face, in [0, count).
std::pair<std::vector<std::size_t>, std::size_t> face_components(const TriangleMesh& mesh) {
  std::vector<std::size_t> parent(mesh.triangles.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  std::vector<std::array<std::size_t, 3>> edges;  // smaller vertex, larger vertex, face
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Index a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), f});
    }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (edges[i][0] == edges[i - 1][0] && edges[i][1] == edges[i - 1][1])
      parent[find(edges[i][2])] = find(edges[i - 1][2]);
  std::vector<std::size_t> label(mesh.triangles.size());
  std::vector<std::size_t> id_of_root(mesh.triangles.size(), SIZE_MAX);
  std::size_t count = 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    std::size_t& id = id_of_root[find(f)];
    if (id == SIZE_MAX) id = count++;
    label[f] = id;
  }
  return {std::move(label), count};
}

}  // namespace

std::size_t orient_along_normals(TriangleMesh& mesh, const std::vector<Point3>& points,
                                 const std::vector<Vector3>& normals) {
  if (mesh.triangles.empty() || points.empty() || normals.size() != points.size()) return 0;
  const auto [component, count] = face_components(mesh);
  // Per face: its area vector against the normal of the sample nearest to its centre.
  std::vector<double> agreement(mesh.triangles.size());
  const NearestIndex nearest(points);
  tbb::parallel_for(std::size_t{0}, mesh.triangles.size(), [&](std::size_t f) {
    const auto& t = mesh.triangles[f];
    const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    agreement[f] = CGAL::cross_product(b - a, c - a) * normals[nearest.nearest(CGAL::centroid(a, b, c)).first];
  });
  std::vector<double> score(count, 0.0);
  for (std::size_t f = 0; f < agreement.size(); ++f) score[component[f]] += agreement[f];
  std::size_t flipped = 0;
  for (const double s : score) flipped += s < 0;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    if (score[component[f]] < 0) std::swap(mesh.triangles[f][1], mesh.triangles[f][2]);
  return flipped;
}

}  // namespace envcrust::mesh
