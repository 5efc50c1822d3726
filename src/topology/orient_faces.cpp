// orient_faces: flip triangles so that each piece of a mesh is consistently wound;
// orient_along_normals: turn whole pieces to face like the samples' normals.
#include "envcrust/mesh_graph.h"
#include "envcrust/nearest_index.h"
#include "envcrust/topology.h"
#include "envcrust/union_find.h"

#include <tbb/parallel_for.h>

#include <utility>

namespace envcrust::topology {
namespace {

// The edge table of the faces with three distinct vertices; kept[f] is face f's index in mesh.
MeshGraph graph_of_proper_faces(const TriangleMesh& mesh, std::vector<std::uint32_t>& kept) {
  std::vector<std::array<Index, 3>> faces;
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
    kept.push_back(f);
    faces.push_back(t);
  }
  return build_mesh_graph(std::move(faces), mesh.vertices.size());
}

}  // namespace

std::size_t orient_faces(TriangleMesh& mesh) {
  std::vector<std::uint32_t> kept;
  const MeshGraph g = graph_of_proper_faces(mesh, kept);
  UnionFind uf(g.faces.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e)
    if (g.face_count_of_edge(e) == 2)
      uf.unite(g.edge_faces[g.edge_face_begin[e]], g.edge_faces[g.edge_face_begin[e] + 1]);
  std::vector<std::uint32_t> component;
  const std::uint32_t count = uf.label_sets(component);
  const Orientation orientation = orient_components(g, component, count);

  // Closed orientable pieces face outward: their signed volume (sum of det(a, b, c) / 6 over
  // the faces, about any origin) must be positive. The origin is the piece's first vertex, so
  // far-away coordinates do not cancel.
  std::vector<double> volume(count, 0.0);
  std::vector<bool> closed(count, true);
  std::vector<Point3> origin(count);
  std::vector<bool> has_origin(count, false);
  for (std::size_t e = 0; e < g.edges.size(); ++e)
    if (g.face_count_of_edge(e) != 2) closed[component[g.edge_faces[g.edge_face_begin[e]]]] = false;
  for (std::uint32_t f = 0; f < g.faces.size(); ++f) {
    const std::uint32_t c = component[f];
    auto t = g.faces[f];
    if (orientation.face_sign[f] < 0) std::swap(t[1], t[2]);
    if (!has_origin[c]) {
      origin[c] = mesh.vertices[t[0]];
      has_origin[c] = true;
    }
    const Vector3 a = mesh.vertices[t[0]] - origin[c], b = mesh.vertices[t[1]] - origin[c],
                  d = mesh.vertices[t[2]] - origin[c];
    volume[c] += CGAL::scalar_product(a, CGAL::cross_product(b, d));
  }

  std::size_t flipped = 0;
  for (std::uint32_t f = 0; f < g.faces.size(); ++f) {
    const std::uint32_t c = component[f];
    int sign = orientation.face_sign[f];
    if (closed[c] && orientation.is_orientable[c] && volume[c] < 0) sign = -sign;
    if (sign < 0) {
      auto& t = mesh.triangles[kept[f]];
      std::swap(t[1], t[2]);
      ++flipped;
    }
  }
  return flipped;
}

std::size_t orient_along_normals(TriangleMesh& mesh, const std::vector<Point3>& points,
                                 const std::vector<Vector3>& normals) {
  if (mesh.triangles.empty() || points.empty() || normals.size() != points.size()) return 0;
  // Pieces: faces joined through edges (repeated-vertex faces belong to none and stay).
  std::vector<std::uint32_t> kept;
  const MeshGraph g = graph_of_proper_faces(mesh, kept);
  std::vector<std::uint32_t> piece;
  const std::uint32_t count = face_components(g, piece);
  // Per face: its area vector against the normal of the sample nearest to its centre.
  std::vector<double> agreement(g.faces.size());
  const NearestIndex nearest(points);
  tbb::parallel_for(std::size_t{0}, g.faces.size(), [&](std::size_t f) {
    const auto& t = g.faces[f];
    const Point3 &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    agreement[f] = CGAL::cross_product(b - a, c - a) * normals[nearest.nearest(CGAL::centroid(a, b, c)).first];
  });
  std::vector<double> score(count, 0.0);
  for (std::size_t f = 0; f < agreement.size(); ++f) score[piece[f]] += agreement[f];
  std::size_t turned = 0;
  for (const double s : score) turned += s < 0;
  for (std::size_t f = 0; f < g.faces.size(); ++f)
    if (score[piece[f]] < 0) std::swap(mesh.triangles[kept[f]][1], mesh.triangles[kept[f]][2]);
  return turned;
}

}  // namespace envcrust::topology
