// orient_faces: flip triangles so that each piece of a mesh is consistently wound;
// orient_along_normals: turn whole pieces to face like the samples' normals.
#include "envcrust/mesh_graph.h"
#include "envcrust/nearest_index.h"
#include "envcrust/topology.h"
#include "envcrust/union_find.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
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

// Per orientable piece, -1 when it must be turned over to face outward, else +1: the signed
// volume it encloses (sum of det(a, b, c) / 6 over its faces, about its first vertex so that
// far-away coordinates do not cancel) must be positive. An open piece is closed first by
// cones over its borders, each connected set of border edges to the centre of its vertices
// (a hemisphere capped to a half-ball, a cylinder to a can, a range scan to the solid behind
// its bowl); one enclosing no volume (below kFlatVolume of its area^1.5: a flat square, a
// symmetric saddle) faces the way its vector area has its largest component positive
// (a square in the xy-plane faces +z, a terrain up).
std::vector<int> outward_turns(const TriangleMesh& mesh, const MeshGraph& g, const std::vector<std::uint32_t>& component,
                               std::uint32_t count, const Orientation& orientation) {
  constexpr double kFlatVolume = 1e-4;
  auto wound = [&](std::uint32_t f) {
    auto t = g.faces[f];
    if (orientation.face_sign[f] < 0) std::swap(t[1], t[2]);
    return t;
  };
  // Border half-edges as their one face runs them (edges of one face, or of more than two,
  // which join no faces in a piece), and the connected sets of their vertices (numbered by
  // `slot` in order of appearance: a big mesh has few border vertices).
  std::vector<std::pair<Index, Index>> border;
  std::vector<std::uint32_t> border_piece;
  std::unordered_map<Index, std::uint32_t> slot;
  auto slot_of = [&](Index v) { return slot.try_emplace(v, static_cast<std::uint32_t>(slot.size())).first->second; };
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (g.face_count_of_edge(e) == 2) continue;
    for (std::uint32_t k = g.edge_face_begin[e]; k < g.edge_face_begin[e + 1]; ++k) {
      const std::uint32_t f = g.edge_faces[k];
      const auto [a, b] = g.edges[e];
      const bool forward = direction_along(wound(f), a, b) > 0;
      border.emplace_back(forward ? a : b, forward ? b : a);
      border_piece.push_back(component[f]);
      slot_of(a);
      slot_of(b);
    }
  }
  UnionFind rims(slot.size());
  for (const auto& [a, b] : border) rims.unite(slot.at(a), slot.at(b));
  std::vector<Vector3> rim_sum(slot.size(), CGAL::NULL_VECTOR);
  std::vector<double> rim_count(slot.size(), 0.0);
  for (const auto& [a, b] : border) {
    const std::uint32_t r = rims.find(slot.at(a));
    rim_sum[r] = rim_sum[r] + (mesh.vertices[a] - CGAL::ORIGIN);
    rim_count[r] += 1.0;
  }
  std::vector<double> volume(count, 0.0), area(count, 0.0);
  std::vector<Vector3> vector_area(count, CGAL::NULL_VECTOR);
  std::vector<Point3> origin(count);
  std::vector<bool> has_origin(count, false);
  auto det = [](const Vector3& a, const Vector3& b, const Vector3& c) {
    return CGAL::scalar_product(a, CGAL::cross_product(b, c));
  };
  for (std::uint32_t f = 0; f < g.faces.size(); ++f) {
    const std::uint32_t c = component[f];
    const auto t = wound(f);
    if (!has_origin[c]) {
      origin[c] = mesh.vertices[t[0]];
      has_origin[c] = true;
    }
    const Vector3 a = mesh.vertices[t[0]] - origin[c], b = mesh.vertices[t[1]] - origin[c],
                  d = mesh.vertices[t[2]] - origin[c];
    volume[c] += det(a, b, d);
    const Vector3 n = CGAL::cross_product(b - a, d - a);
    vector_area[c] = vector_area[c] + n;
    area[c] += std::sqrt(n.squared_length());
  }
  // The cone triangle over a border edge a -> b runs it back: (b, a, centre).
  for (std::size_t i = 0; i < border.size(); ++i) {
    const auto [a, b] = border[i];
    const std::uint32_t c = border_piece[i], r = rims.find(slot.at(a));
    const Point3 centre = CGAL::ORIGIN + rim_sum[r] / rim_count[r];
    volume[c] += det(mesh.vertices[b] - origin[c], mesh.vertices[a] - origin[c], centre - origin[c]);
  }
  std::vector<int> turn(count, 1);
  for (std::uint32_t c = 0; c < count; ++c) {
    if (!orientation.is_orientable[c]) continue;
    // volume and area are 6x and 2x the true ones: compare as 6V against kFlatVolume (2A)^1.5.
    if (std::abs(volume[c]) > kFlatVolume * std::pow(area[c], 1.5)) {
      turn[c] = volume[c] < 0 ? -1 : 1;
    } else {
      const Vector3& s = vector_area[c];
      const double largest = std::abs(s.x()) >= std::max(std::abs(s.y()), std::abs(s.z()))
                                 ? s.x()
                                 : (std::abs(s.y()) >= std::abs(s.z()) ? s.y() : s.z());
      turn[c] = largest < 0 ? -1 : 1;
    }
  }
  return turn;
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

  const std::vector<int> turn = outward_turns(mesh, g, component, count, orientation);
  std::size_t flipped = 0;
  for (std::uint32_t f = 0; f < g.faces.size(); ++f) {
    if (orientation.face_sign[f] * turn[component[f]] < 0) {
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
