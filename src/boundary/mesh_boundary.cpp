// Boundary loops of an indexed triangle mesh with t, n, c frames and corner flags; refuses
// meshes with an edge of three or more faces.
#include "boundary_detail.h"

#include "envcrust/errors.h"

#include <algorithm>
#include <numbers>
#include <unordered_map>

namespace envcrust::boundary {
namespace {

using detail::cross;
using detail::dot;
using detail::unit;
using detail::unit_perpendicular;

/// A boundary edge as its face runs it (a -> b), with the face's third vertex.
struct BoundaryEdge {
  Index a, b, third;
};

std::uint64_t edge_key(Index a, Index b) {
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

std::vector<BoundaryEdge> boundary_edges(const TriangleMesh& mesh) {
  struct EdgeUse {
    std::size_t faces = 0;
    BoundaryEdge edge{};
  };
  std::unordered_map<std::uint64_t, std::size_t> slot;
  std::vector<EdgeUse> uses;  // in order of first appearance
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;  // no edges of its own
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3], w = t[(k + 2) % 3];
      const auto [it, inserted] = slot.try_emplace(edge_key(a, b), uses.size());
      if (inserted) uses.push_back({0, {a, b, w}});
      ++uses[it->second].faces;
    }
  }
  std::vector<BoundaryEdge> out;
  for (const EdgeUse& use : uses) {
    if (use.faces > 2) {
      throw InvalidInput("edge (" + std::to_string(std::min(use.edge.a, use.edge.b)) + ", " +
                         std::to_string(std::max(use.edge.a, use.edge.b)) + ") has " +
                         std::to_string(use.faces) + " faces: the mesh is not a surface");
    }
    if (use.faces == 1) out.push_back(use.edge);
  }
  return out;
}

/// Loops of boundary edges, each as the sequence of edges walked head to tail.
std::vector<std::vector<BoundaryEdge>> trace_loops(const std::vector<BoundaryEdge>& edges) {
  std::unordered_map<Index, std::vector<std::size_t>> at;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    at[edges[e].a].push_back(e);
    at[edges[e].b].push_back(e);
  }
  std::vector<char> used(edges.size(), 0);
  std::vector<std::vector<BoundaryEdge>> loops;
  for (std::size_t first = 0; first < edges.size(); ++first) {
    if (used[first]) continue;
    std::vector<BoundaryEdge> loop;
    used[first] = 1;
    loop.push_back(edges[first]);
    const Index start = edges[first].a;
    Index current = edges[first].b;
    while (current != start) {
      std::size_t next = edges.size();
      for (const std::size_t e : at[current]) {
        if (!used[e]) {
          next = e;
          break;
        }
      }
      if (next == edges.size()) break;  // open chain (cannot happen on a closed edge set)
      used[next] = 1;
      BoundaryEdge e = edges[next];
      if (e.a != current) std::swap(e.a, e.b);  // walk it from `current` (faces may disagree)
      loop.push_back(e);
      current = e.b;
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

/// Unit direction from the edge's line towards its face's third vertex, in the face's plane.
Vector3 inward(const TriangleMesh& mesh, const BoundaryEdge& e) {
  const Point3& a = mesh.vertices[e.a];
  return unit_perpendicular(mesh.vertices[e.third] - a, unit(mesh.vertices[e.b] - a));
}

/// Conormal perpendicular to the direction d and the normal line, away from `in`.
Vector3 conormal_for(const Vector3& d, const Vector3& normal, const Vector3& in) {
  const Vector3 n = unit_perpendicular(normal, d);
  const Vector3 c = unit(cross(d, n));
  return dot(c, in) > 0 ? -c : c;
}

BoundaryCurve frame_loop(const TriangleMesh& mesh, const std::vector<Vector3>& normal_lines,
                         const std::vector<BoundaryEdge>& loop) {
  const std::size_t m = loop.size();
  constexpr double corner_turn_deg = 30.0;  // docs/method.md §3.2: a corner turns by > 30 degrees
  const double corner_cos = std::cos(corner_turn_deg * std::numbers::pi / 180.0);
  BoundaryCurve curve;
  curve.vertices.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const BoundaryEdge& in_edge = loop[(i + m - 1) % m];
    const BoundaryEdge& out_edge = loop[i];
    const Point3& p = mesh.vertices[out_edge.a];
    const Vector3 d_in = unit(p - mesh.vertices[in_edge.a]);
    const Vector3 d_out = unit(mesh.vertices[out_edge.b] - p);
    const Vector3 in_in = inward(mesh, in_edge), in_out = inward(mesh, out_edge);
    BoundaryVertex& v = curve.vertices[i];
    v.position = p;
    v.is_corner = dot(d_in, d_out) < corner_cos;
    v.tangent = v.is_corner ? d_in : unit(d_in + d_out);
    Vector3 line = normal_lines[out_edge.a];
    if (unit_perpendicular(line, v.tangent) == Vector3(0, 0, 0)) {
      line = cross(d_out, in_out);  // degenerate vertex normal: the boundary face's normal
    }
    v.normal = unit_perpendicular(line, v.tangent);
    if (i > 0 && dot(v.normal, curve.vertices[i - 1].normal) < 0) v.normal = -v.normal;
    if (v.is_corner) {
      v.conormal = conormal_for(d_in, v.normal, in_in);
      v.conormal_next = conormal_for(d_out, v.normal, in_out);
    } else {
      v.conormal = conormal_for(v.tangent, v.normal, in_in + in_out);
    }
  }
  return curve;
}

}  // namespace

std::vector<BoundaryCurve> mesh_boundary_curves(const TriangleMesh& mesh,
                                                const std::vector<Vector3>& vertex_normal_lines) {
  const std::size_t n = mesh.vertices.size();
  if (vertex_normal_lines.size() != n) {
    throw InvalidInput("mesh boundary: " + std::to_string(vertex_normal_lines.size()) +
                       " vertex normal lines for " + std::to_string(n) + " vertices");
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (const Index v : mesh.triangles[f]) {
      if (v >= n) {
        throw InvalidInput("face " + std::to_string(f) + " has vertex index " +
                           std::to_string(v) + ", but the mesh has " + std::to_string(n) +
                           " vertices");
      }
    }
  }
  std::vector<BoundaryCurve> curves;
  for (const auto& loop : trace_loops(boundary_edges(mesh))) {
    curves.push_back(frame_loop(mesh, vertex_normal_lines, loop));
  }
  return curves;
}

}  // namespace envcrust::boundary
