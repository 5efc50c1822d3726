// Sharp edges of a triangle mesh: where adjacent faces' normals make a large angle.
#include "envcrust/mesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

namespace envcrust::mesh {
namespace {

// The unit direction halfway between the two faces of edge ab, each face's direction being
// from the edge to its third vertex, square to the edge.
Vector3 wedge_bisector(const TriangleMesh& mesh, Index f, Index g, const Point3& a, const Point3& b) {
  const Vector3 edge = (b - a) / std::sqrt(CGAL::squared_distance(a, b));
  auto into = [&](Index face) {
    Vector3 sum(0, 0, 0);
    for (Index v : mesh.triangles[face]) sum = sum + (mesh.vertices[v] - a);
    const Vector3 d = sum - (sum * edge) * edge;  // the third vertex's offset square to the edge
    return d / std::sqrt(d.squared_length());
  };
  const Vector3 sum = into(f) + into(g);
  const double length = std::sqrt(sum.squared_length());
  return length > 0 ? sum / length : Vector3(0, 0, 0);
}

}  // namespace

SharpEdges sharp_edges(const TriangleMesh& input, double min_bend_deg) {
  const TriangleMesh mesh = weld_identical_vertices(input);
  std::vector<Vector3> normal(mesh.triangles.size(), Vector3(0, 0, 0));
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const Vector3 n = CGAL::cross_product(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    const double length = std::sqrt(n.squared_length());
    if (length > 0 && std::isfinite(length)) normal[f] = n / length;
  }
  // Every directed edge (a -> b) of a non-degenerate face, keyed by its sorted ends.
  struct HalfEdge {
    Index lo, hi;
    bool forward;  // a < b
    Index face;
    bool operator<(const HalfEdge& o) const { return std::tie(lo, hi, face) < std::tie(o.lo, o.hi, o.face); }
  };
  std::vector<HalfEdge> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (normal[f] == Vector3(0, 0, 0)) continue;
    const auto& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const Index a = t[k], b = t[(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), a < b, static_cast<Index>(f)});
    }
  }
  std::sort(edges.begin(), edges.end());
  const double cos_threshold = std::cos(min_bend_deg * std::numbers::pi / 180.0);
  SharpEdges out;
  double min_cos = 1.0;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    if (j - i == 2) {
      const HalfEdge &e = edges[i], &d = edges[i + 1];
      // A consistent winding runs a shared edge both ways.
      const double sign = e.forward != d.forward ? 1.0 : -1.0;
      const double cos_bend = std::clamp(sign * (normal[e.face] * normal[d.face]), -1.0, 1.0);
      if (cos_bend < cos_threshold) {
        const Point3 &a = mesh.vertices[e.lo], &b = mesh.vertices[e.hi];
        ++out.count;
        out.segments.push_back({a, b, wedge_bisector(mesh, e.face, d.face, a, b)});
        out.total_length += std::sqrt(CGAL::squared_distance(a, b));
        if (cos_bend < min_cos) out.sharpest = CGAL::midpoint(a, b);
      }
      min_cos = std::min(min_cos, cos_bend);
    }
    i = j;
  }
  out.max_bend_deg = std::acos(min_cos) * 180.0 / std::numbers::pi;
  return out;
}

}  // namespace envcrust::mesh
