// Moving sheet vertices onto the sampled surface and onto the boundary curves, each move
// checked so that no incident face flips or collapses.
#include "sheet_projection.h"

#include "envcrust/nearest_index.h"
#include "envcrust/topology.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace envcrust::extract {
namespace {

Vector3 face_normal(const TriangleMesh& m, const std::array<Index, 3>& f, Index moved, const Point3& at) {
  auto pos = [&](Index v) { return v == moved ? at : m.vertices[v]; };
  return CGAL::cross_product(pos(f[1]) - pos(f[0]), pos(f[2]) - pos(f[0]));
}

// Apply the move, or half of it, when no incident face flips or shrinks below a fifth.
bool move_if_safe(TriangleMesh& m, const std::vector<std::vector<std::uint32_t>>& faces_of, Index v,
                  const Point3& target) {
  const Point3 start = m.vertices[v];
  for (double fraction : {1.0, 0.5}) {
    const Point3 at = start + fraction * (target - start);
    bool ok = true;
    for (auto f : faces_of[v]) {
      const Vector3 before = face_normal(m, m.triangles[f], v, start);
      const Vector3 after = face_normal(m, m.triangles[f], v, at);
      if (before * after <= 0.0 || after.squared_length() < 0.04 * before.squared_length()) {
        ok = false;
        break;
      }
    }
    if (ok) {
      m.vertices[v] = at;
      return true;
    }
  }
  return false;
}

// Offset of x from M estimated from the tangent planes of its nearest samples (normal lines
// aligned with the nearest one), inverse-distance weighted.
Point3 onto_tangent_planes(const Point3& x, const envelope::SurfaceSamples& s, const NearestIndex& index) {
  const auto hits = index.nearest(x, 6);
  const Vector3 reference = s.normals[hits.front().first];
  Vector3 shift(0, 0, 0);
  double weight = 0.0;
  for (const auto& [i, d] : hits) {
    Vector3 n = s.normals[i];
    if (n * reference < 0) n = -n;
    const double w = 1.0 / (d * d + 1e-24);
    shift = shift + w * ((x - s.points[i]) * n) * n;
    weight += w;
  }
  return x - shift / weight;
}

struct BoundaryPolylines {
  std::vector<Point3> points;
  std::vector<std::size_t> curve_start, curve_of;  // per point: its curve; per curve: first point
  std::vector<std::size_t> curve_size;
};

Point3 onto_boundary(const Point3& x, const BoundaryPolylines& b, const NearestIndex& index) {
  const std::size_t i = index.nearest(x).first;
  const std::size_t c = b.curve_of[i];
  const std::size_t start = b.curve_start[c], size = b.curve_size[c];
  const std::size_t local = i - start;
  Point3 best = b.points[i];
  double best_d = CGAL::squared_distance(x, best);
  for (std::size_t other : {(local + size - 1) % size, (local + 1) % size}) {
    const Kernel::Segment_3 seg(b.points[i], b.points[start + other]);
    if (seg.is_degenerate()) continue;
    const Vector3 d = seg.to_vector();
    const double t = std::clamp(((x - seg.source()) * d) / d.squared_length(), 0.0, 1.0);
    const Point3 p = seg.source() + t * d;
    const double dist = CGAL::squared_distance(x, p);
    if (dist < best_d) {
      best_d = dist;
      best = p;
    }
  }
  return best;
}

}  // namespace

namespace {

std::vector<std::vector<std::uint32_t>> faces_of_vertices(const TriangleMesh& m) {
  std::vector<std::vector<std::uint32_t>> faces_of(m.vertices.size());
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f)
    for (Index v : m.triangles[f]) faces_of[v].push_back(f);
  return faces_of;
}

std::vector<char> border_vertices(const TriangleMesh& m) {
  const auto topo = topology::analyze_topology(m, {.weld_identical_vertices = false});
  std::vector<char> is_border(m.vertices.size(), 0);
  for (const auto& loop : topo.boundary_loops)
    for (Index v : loop.vertices) is_border[v] = 1;
  return is_border;
}

BoundaryPolylines polylines_of(const envelope::SurfaceSamples& surface) {
  BoundaryPolylines boundary;
  for (std::size_t c = 0; c < surface.boundary.size(); ++c) {
    boundary.curve_start.push_back(boundary.points.size());
    boundary.curve_size.push_back(surface.boundary[c].vertices.size());
    for (const auto& v : surface.boundary[c].vertices) {
      boundary.points.push_back(v.position);
      boundary.curve_of.push_back(c);
    }
  }
  return boundary;
}

}  // namespace

ProjectionStats project_onto_samples(TaggedMesh& t, const envelope::SurfaceSamples& surface,
                                     double max_move) {
  ProjectionStats stats;
  auto& m = t.mesh;
  const auto faces_of = faces_of_vertices(m);
  const auto is_border = border_vertices(m);
  const NearestIndex samples(surface.points);
  for (Index v = 0; v < m.vertices.size(); ++v) {
    if (faces_of[v].empty() || is_border[v]) continue;
    const Point3 target = onto_tangent_planes(m.vertices[v], surface, samples);
    if (CGAL::squared_distance(target, m.vertices[v]) > max_move * max_move) continue;
    if (move_if_safe(m, faces_of, v, target)) {
      ++stats.moved;
    } else {
      ++stats.refused;
    }
  }
  return stats;
}

std::size_t trim_beyond_boundary(TaggedMesh& t, const envelope::SurfaceSamples& surface, double reach) {
  if (surface.boundary.empty()) return 0;
  const BoundaryPolylines boundary = polylines_of(surface);
  const NearestIndex index(boundary.points);
  // At a corner the region beyond either edge is outside M: take the larger level.
  std::vector<Vector3> conormals, conormals_next;
  for (const auto& c : surface.boundary)
    for (const auto& v : c.vertices) {
      conormals.push_back(v.conormal);
      conormals_next.push_back(v.is_corner ? v.conormal_next : v.conormal);
    }
  auto& m = t.mesh;
  std::vector<double> level(m.vertices.size(), -1.0);
  for (Index v = 0; v < m.vertices.size(); ++v) {
    const auto [i, d] = index.nearest(m.vertices[v]);
    if (d > reach) continue;
    const Point3 b = onto_boundary(m.vertices[v], boundary, index);
    const Vector3 offset = m.vertices[v] - b;
    double s = std::max(offset * conormals[i], offset * conormals_next[i]);
    // A vertex exactly on the cut would give a zero-area piece: count it as inside.
    if (std::abs(s) < 1e-12 * reach) s = -1e-12 * reach;
    level[v] = s;
  }
  const std::size_t before = m.triangles.size();
  trim_mesh(t, level);
  return before - std::min(before, m.triangles.size());
}

ProjectionStats snap_border(TaggedMesh& t, const envelope::SurfaceSamples& surface, double max_move) {
  ProjectionStats stats;
  if (surface.boundary.empty()) return stats;
  auto& m = t.mesh;
  const auto faces_of = faces_of_vertices(m);
  const auto is_border = border_vertices(m);
  const BoundaryPolylines boundary = polylines_of(surface);
  const NearestIndex index(boundary.points);
  for (Index v = 0; v < m.vertices.size(); ++v) {
    if (faces_of[v].empty() || !is_border[v]) continue;
    const Point3 target = onto_boundary(m.vertices[v], boundary, index);
    if (CGAL::squared_distance(target, m.vertices[v]) > max_move * max_move) continue;
    if (move_if_safe(m, faces_of, v, target)) {
      ++stats.moved;
    } else {
      ++stats.refused;
    }
  }
  return stats;
}

}  // namespace envcrust::extract
