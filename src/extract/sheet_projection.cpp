// Moving sheet vertices onto the sampled surface and onto the boundary curves, each move
// checked so that no incident face flips or collapses.
#include "sheet_projection.h"

#include "envcrust/nearest_index.h"
#include "envcrust/topology.h"

#include <Eigen/Dense>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>

namespace envcrust::extract {
namespace {

Vector3 face_normal(const TriangleMesh& m, const std::array<Index, 3>& f, Index moved, const Point3& at) {
  auto pos = [&](Index v) { return v == moved ? at : m.vertices[v]; };
  return CGAL::cross_product(pos(f[1]) - pos(f[0]), pos(f[2]) - pos(f[0]));
}

// Apply the move, or half of it, when no incident face flips or shrinks below a fifth. A face
// flips when its normal turns by more than 90 degrees, or, given an `axis` (the surface
// normal along which the vertex moves), when its normal's component along the axis changes
// sign: a face of a rough sheet that stands steep may tilt over to the other side while it
// comes down flat onto the surface, and that is no fold.
bool move_if_safe(TriangleMesh& m, const std::vector<std::vector<std::uint32_t>>& faces_of, Index v,
                  const Point3& target, const std::optional<Vector3>& axis = std::nullopt) {
  const Point3 start = m.vertices[v];
  for (double fraction : {1.0, 0.5}) {
    const Point3 at = fraction == 1.0 ? target : start + fraction * (target - start);
    bool ok = true;
    for (auto f : faces_of[v]) {
      const Vector3 before = face_normal(m, m.triangles[f], v, start);
      const Vector3 after = face_normal(m, m.triangles[f], v, at);
      const bool flips = axis && axis->squared_length() > 0.0 ? (before * *axis) * (after * *axis) < 0.0
                                                             : before * after <= 0.0;
      if (flips || after.squared_length() < 0.04 * before.squared_length()) {
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

// The point of M below x from a weighted least-squares quadric over its `neighbors` nearest
// samples: in a frame with the mean sample normal as height axis and x at the origin, the
// height z(u, v) = c0 + c1 u + c2 v + c3 u^2 + c4 uv + c5 v^2 is fitted to the samples'
// heights and to the slopes their normals give (the normals fix the tilt and curvature,
// which a fit to noisy heights alone leaves uncertain, most at one-sided neighbourhoods near
// the boundary), and x moves to c0. Weights (1 - d^2 / h^2)^2, h = sqrt(2) times the
// distance to the farthest neighbour, nearly uniform over the neighbourhood: each sample's
// noise counts about equally, and more neighbours average it out.
Point3 onto_local_fit(const Point3& x, const envelope::SurfaceSamples& s, const NearestIndex& index,
                      unsigned neighbors) {
  const auto hits = index.nearest(x, neighbors);
  const double h2 = std::max(2.0 * hits.back().second * hits.back().second, 1e-300);
  std::vector<double> w(hits.size());
  const Vector3 nearest_normal = s.normals[hits.front().first];
  Vector3 normal(0, 0, 0);
  for (std::size_t j = 0; j < hits.size(); ++j) {
    const double t = 1.0 - hits[j].second * hits[j].second / h2;
    w[j] = t * t;
    const Vector3& n = s.normals[hits[j].first];
    normal = normal + (n * nearest_normal < 0 ? -w[j] : w[j]) * n;
  }
  if (normal.squared_length() == 0.0) return x;
  normal = normal / std::sqrt(normal.squared_length());
  const Eigen::Vector3d nz(normal.x(), normal.y(), normal.z());
  const Eigen::Vector3d e1 = nz.unitOrthogonal(), e2 = nz.cross(e1);
  // Slopes are scaled by the bandwidth so that both kinds of rows are lengths.
  const double scale = std::sqrt(h2);
  Eigen::Matrix<double, 6, 6> ata = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> atb = Eigen::Matrix<double, 6, 1>::Zero();
  auto add_row = [&](const Eigen::Matrix<double, 6, 1>& row, double value, double weight) {
    ata += weight * row * row.transpose();
    atb += weight * value * row;
  };
  for (std::size_t j = 0; j < hits.size(); ++j) {
    const Vector3 d = s.points[hits[j].first] - x;
    const Eigen::Vector3d dv(d.x(), d.y(), d.z());
    const double u = dv.dot(e1), v = dv.dot(e2), z = dv.dot(nz);
    Eigen::Matrix<double, 6, 1> row;
    row << 1.0, u, v, u * u, u * v, v * v;
    add_row(row, z, w[j]);
    const Vector3& n = s.normals[hits[j].first];
    Eigen::Vector3d nv(n.x(), n.y(), n.z());
    if (nv.dot(nz) < 0) nv = -nv;
    const double nn = nv.dot(nz);
    if (nn < 0.5) continue;  // a normal far off the mean gives no usable slope
    row << 0.0, 1.0, 0.0, 2.0 * u, v, 0.0;
    add_row(scale * row, -scale * nv.dot(e1) / nn, w[j]);
    row << 0.0, 0.0, 1.0, 0.0, u, 2.0 * v;
    add_row(scale * row, -scale * nv.dot(e2) / nn, w[j]);
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(ata);
  if (solver.info() != Eigen::Success) return x;
  const Eigen::Matrix<double, 6, 1> c = solver.solve(atb);
  if (!c.allFinite()) return x;
  return x + c(0) * normal;
}

struct BoundaryPolylines {
  std::vector<Point3> points;
  std::vector<Vector3> normals;  // of the surface, per point
  std::vector<std::size_t> curve_start, curve_of;  // per point: its curve; per curve: first point
  std::vector<std::size_t> curve_size;
  std::vector<double> arc;           // per point: arc length from its curve's first point
  std::vector<double> curve_length;  // per curve
};

/// The nearest point of a boundary curve, with its curve and arc-length position.
struct CurvePoint {
  Point3 point;
  std::size_t curve = 0;
  double arc = 0.0;
};

CurvePoint onto_boundary(const Point3& x, const BoundaryPolylines& b, const NearestIndex& index) {
  const std::size_t i = index.nearest(x).first;
  const std::size_t c = b.curve_of[i];
  const std::size_t start = b.curve_start[c], size = b.curve_size[c];
  const std::size_t local = i - start;
  CurvePoint best{b.points[i], c, b.arc[i]};
  double best_d = CGAL::squared_distance(x, best.point);
  for (std::size_t other : {(local + size - 1) % size, (local + 1) % size}) {
    const Kernel::Segment_3 seg(b.points[i], b.points[start + other]);
    if (seg.is_degenerate()) continue;
    const Vector3 d = seg.to_vector();
    const double t = std::clamp(((x - seg.source()) * d) / d.squared_length(), 0.0, 1.0);
    const Point3 p = seg.source() + t * d;
    const double dist = CGAL::squared_distance(x, p);
    if (dist < best_d) {
      best_d = dist;
      // Going backwards from the first point wraps to the closing segment.
      const double arc_other = other == 0 ? b.curve_length[c] : b.arc[start + other];
      const double arc_here = local == 0 && other + 1 == size ? b.curve_length[c] : b.arc[i];
      best = {p, c, arc_here + t * (arc_other - arc_here)};
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

// The border loops depend on the connectivity only, which no vertex move changes: a stage
// computes them once. Which way a loop is walked must not matter: the stages below apply
// their moves in vertex order.
std::vector<topology::BoundaryLoop> border_loops(const TriangleMesh& m) { return topology::boundary_loops(m); }

std::vector<char> border_vertices(const TriangleMesh& m, const std::vector<topology::BoundaryLoop>& loops) {
  std::vector<char> is_border(m.vertices.size(), 0);
  for (const auto& loop : loops)
    for (Index v : loop.vertices) is_border[v] = 1;
  return is_border;
}

BoundaryPolylines polylines_of(const envelope::SurfaceSamples& surface) {
  BoundaryPolylines boundary;
  for (std::size_t c = 0; c < surface.boundary.size(); ++c) {
    boundary.curve_start.push_back(boundary.points.size());
    boundary.curve_size.push_back(surface.boundary[c].vertices.size());
    double arc = 0.0;
    const auto& vertices = surface.boundary[c].vertices;
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      if (k > 0) arc += std::sqrt(CGAL::squared_distance(vertices[k - 1].position, vertices[k].position));
      boundary.points.push_back(vertices[k].position);
      boundary.normals.push_back(vertices[k].normal);
      boundary.curve_of.push_back(c);
      boundary.arc.push_back(arc);
    }
    if (!vertices.empty())
      arc += std::sqrt(CGAL::squared_distance(vertices.back().position, vertices.front().position));
    boundary.curve_length.push_back(arc);
  }
  return boundary;
}

// How far a point lies beyond the boundary curves: its offset from the nearest curve point
// along the outward conormal there (at a corner the larger of the two edges' offsets), for
// points within `reach` of a curve vertex; farther points are not judged (a curve's
// half-space says nothing about a part of the surface that curls round far from it).
class CurveSide {
 public:
  CurveSide(const envelope::SurfaceSamples& surface, double reach)
      : boundary_(polylines_of(surface)), index_(boundary_.points), reach_(reach) {
    for (const auto& c : surface.boundary)
      for (const auto& v : c.vertices) {
        conormals_.push_back(v.conormal);
        conormals_next_.push_back(v.is_corner ? v.conormal_next : v.conormal);
      }
  }
  CurveSide(const CurveSide&) = delete;  // index_ points into boundary_
  CurveSide& operator=(const CurveSide&) = delete;
  [[nodiscard]] const BoundaryPolylines& polylines() const { return boundary_; }
  [[nodiscard]] const NearestIndex& index() const { return index_; }
  [[nodiscard]] std::optional<double> level(const Point3& x) const {
    if (boundary_.points.empty()) return std::nullopt;
    const auto [i, d] = index_.nearest(x);
    if (d > reach_) return std::nullopt;
    const Vector3 offset = x - onto_boundary(x, boundary_, index_).point;
    return std::max(offset * conormals_[i], offset * conormals_next_[i]);
  }

 private:
  BoundaryPolylines boundary_;
  NearestIndex index_;
  double reach_;
  std::vector<Vector3> conormals_, conormals_next_;
};

}  // namespace

ProjectionStats project_onto_samples(TaggedMesh& t, const envelope::SurfaceSamples& surface,
                                     const NearestIndex& samples, double max_move, unsigned neighbors,
                                     unsigned retry_rounds) {
  ProjectionStats stats;
  auto& m = t.mesh;
  const auto faces_of = faces_of_vertices(m);
  const auto is_border = border_vertices(m, border_loops(m));
  // Each target depends on the vertex's own (unmoved) position only.
  std::vector<Point3> targets(m.vertices.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m.vertices.size(), 256), [&](const auto& range) {
    for (std::size_t v = range.begin(); v != range.end(); ++v)
      if (!faces_of[v].empty() && !is_border[v])
        targets[v] = onto_local_fit(m.vertices[v], surface, samples, neighbors);
  });
  // A move that would flip a face of a rough (noisy) sheet often becomes safe once the
  // neighbours have moved: refused and halved moves are retried for a few rounds.
  std::vector<Index> pending;
  for (Index v = 0; v < m.vertices.size(); ++v)
    if (!faces_of[v].empty() && !is_border[v] &&
        CGAL::squared_distance(targets[v], m.vertices[v]) <= max_move * max_move)
      pending.push_back(v);
  const std::size_t eligible = pending.size();
  std::vector<char> moved(m.vertices.size(), 0);
  for (unsigned round = 0; round <= retry_rounds && !pending.empty(); ++round) {
    std::vector<Index> again;
    bool progress = false;
    for (Index v : pending) {
      const Vector3 axis = targets[v] - m.vertices[v];
      const bool ok = move_if_safe(m, faces_of, v, targets[v], axis);
      if (ok) {
        progress = true;
        if (!moved[v]) ++stats.moved;
        moved[v] = 1;
      }
      if (m.vertices[v] != targets[v]) again.push_back(v);
    }
    if (!progress) break;
    pending.swap(again);
  }
  stats.refused = eligible - stats.moved;
  return stats;
}

std::size_t trim_beyond_boundary(TaggedMesh& t, const envelope::SurfaceSamples& surface, double reach) {
  if (surface.boundary.empty()) return 0;
  const CurveSide side(surface, reach);
  auto& m = t.mesh;
  std::vector<double> level(m.vertices.size(), -1.0);
  for (Index v = 0; v < m.vertices.size(); ++v)
    if (const auto l = side.level(m.vertices[v])) level[v] = *l;
  const std::size_t before = m.triangles.size();
  trim_mesh(t, level);
  return before - std::min(before, m.triangles.size());
}

namespace {

// The trimmed border zig-zags where the cut crosses small triangles, and can step backwards
// along the curve; on a planar rim (the cylinder's) such a step is a true self-crossing of
// the loop once the border lies in the plane. Two Jacobi rounds of moving each border
// vertex halfway to the midpoint of its loop neighbours iron the steps out before the snap.
// Vertices within two border edges of a corner of the curves (the square's) stay put, or
// the corner would be rounded off.
void smooth_border_loops(TriangleMesh& m, const std::vector<std::vector<std::uint32_t>>& faces_of,
                         const std::vector<topology::BoundaryLoop>& loops, const std::vector<Point3>& corners,
                         const CurveSide& side) {
  for (int round = 0; round < 2; ++round) {
    std::vector<std::pair<Index, Point3>> moves;
    for (const auto& loop : loops) {
      const std::size_t n = loop.vertices.size();
      if (n < 4) continue;
      for (std::size_t i = 0; i < n; ++i) {
        const Point3& prev = m.vertices[loop.vertices[(i + n - 1) % n]];
        const Point3& next = m.vertices[loop.vertices[(i + 1) % n]];
        const Point3& at = m.vertices[loop.vertices[i]];
        const double reach2 = CGAL::squared_distance(prev, at) + CGAL::squared_distance(at, next);
        bool near_corner = false;
        for (const Point3& corner : corners)  // a handful (four for the square)
          near_corner = near_corner || 2.0 * CGAL::squared_distance(corner, at) < reach2;
        if (near_corner) continue;
        // Where the curve bends (the trefoil ribbon's rims), a move towards the midpoint of
        // the neighbours can leave the trimmed side: measured, a vertex moved 1.1 rho past the
        // curve, which the snap below then refused to bring back.
        const Point3 target = at + 0.5 * (CGAL::midpoint(prev, next) - at);
        const auto was = side.level(at), will = side.level(target);
        if (will && *will > std::max(0.0, was.value_or(0.0))) continue;
        moves.emplace_back(loop.vertices[i], target);
      }
    }
    std::sort(moves.begin(), moves.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [v, target] : moves) move_if_safe(m, faces_of, v, target);
  }
}

// Snapped border vertices whose order along their boundary curve goes against the order of
// their mesh loop (neighbours swapped on the curve): the loop would cross itself on the
// curve, which is planar for a cylinder's rim. Both ends of each backward step are listed.
std::vector<Index> out_of_order_snaps(const std::vector<topology::BoundaryLoop>& loops,
                                      const std::vector<std::optional<CurvePoint>>& snap,
                                      const BoundaryPolylines& boundary) {
  std::vector<Index> bad;
  for (const auto& loop : loops) {
    // The snapped vertices of the loop in order, and the signed steps between consecutive
    // ones on the same curve (wrapped to half the curve's length).
    std::vector<Index> snapped;
    for (Index v : loop.vertices)
      if (snap[v]) snapped.push_back(v);
    if (snapped.size() < 3) continue;
    std::vector<double> step(snapped.size(), 0.0);
    double total = 0.0;
    for (std::size_t k = 0; k < snapped.size(); ++k) {
      const CurvePoint& a = *snap[snapped[k]];
      const CurvePoint& b = *snap[snapped[(k + 1) % snapped.size()]];
      if (a.curve != b.curve) continue;
      const double length = boundary.curve_length[a.curve];
      double d = std::fmod(b.arc - a.arc, length);
      if (d > 0.5 * length) d -= length;
      if (d < -0.5 * length) d += length;
      step[k] = d;
      total += d;
    }
    for (std::size_t k = 0; k < snapped.size(); ++k) {
      const CurvePoint& a = *snap[snapped[k]];
      const CurvePoint& b = *snap[snapped[(k + 1) % snapped.size()]];
      if (a.curve != b.curve || step[k] * total > 0.0) continue;
      bad.push_back(snapped[k]);
      bad.push_back(snapped[(k + 1) % snapped.size()]);
    }
  }
  return bad;
}

}  // namespace

ProjectionStats snap_border(TaggedMesh& t, const envelope::SurfaceSamples& surface, double max_move,
                            unsigned retry_rounds) {
  ProjectionStats stats;
  if (surface.boundary.empty()) return stats;
  auto& m = t.mesh;
  const auto faces_of = faces_of_vertices(m);
  const auto loops = border_loops(m);
  const auto is_border = border_vertices(m, loops);
  // Within the trim's reach (2 rho; max_move is rho) the smoothing keeps to the trimmed side.
  const CurveSide side(surface, 2.0 * max_move);
  const BoundaryPolylines& boundary = side.polylines();
  const NearestIndex& index = side.index();
  std::vector<Point3> corners;
  for (const auto& c : surface.boundary)
    for (const auto& v : c.vertices)
      if (v.is_corner) corners.push_back(v.position);
  smooth_border_loops(m, faces_of, loops, corners, side);
  const std::vector<Point3> before = m.vertices;
  std::vector<std::optional<CurvePoint>> snap(m.vertices.size());
  // Flips are judged in the surface's tangent plane at the nearest curve point; a refused
  // (or halved) snap is retried after its neighbours have snapped.
  std::vector<std::pair<Index, CurvePoint>> pending;
  for (Index v = 0; v < m.vertices.size(); ++v) {
    if (faces_of[v].empty() || !is_border[v]) continue;
    const CurvePoint target = onto_boundary(m.vertices[v], boundary, index);
    if (CGAL::squared_distance(target.point, m.vertices[v]) > max_move * max_move) continue;
    pending.emplace_back(v, target);
  }
  // The nearest-point map onto a polyline is not one-to-one: every point in the normal cone
  // of a convex corner (a ragged scan rim has many) maps to the corner. Two vertices snapped
  // onto one point would be one vertex to anyone who welds the output (a pinched vertex), so
  // a point already taken is refused and the vertex takes the normal-only move below.
  std::set<std::array<double, 3>> taken;
  auto key = [](const Point3& p) { return std::array<double, 3>{p.x(), p.y(), p.z()}; };
  for (unsigned round = 0; round <= retry_rounds && !pending.empty(); ++round) {
    std::vector<std::pair<Index, CurvePoint>> again;
    bool progress = false;
    for (const auto& [v, target] : pending) {
      if (taken.count(key(target.point)) > 0 && m.vertices[v] != target.point) {
        again.emplace_back(v, target);
        continue;
      }
      const Vector3 axis = boundary.normals[index.nearest(target.point).first];
      progress |= move_if_safe(m, faces_of, v, target.point, axis);
      if (m.vertices[v] == target.point) {
        snap[v] = target;
        taken.insert(key(target.point));
      } else {
        again.emplace_back(v, target);
      }
    }
    if (!progress) break;
    pending.swap(again);
  }
  // A snap that still folds a face moves along the surface normal only, which keeps each
  // face's orientation in the tangent plane: the vertex comes onto the surface, short of
  // the curve.
  for (const auto& [v, target] : pending) {
    Vector3 axis = boundary.normals[index.nearest(target.point).first];
    if (axis.squared_length() == 0.0) continue;
    axis = axis / std::sqrt(axis.squared_length());
    move_if_safe(m, faces_of, v, m.vertices[v] + ((target.point - m.vertices[v]) * axis) * axis, axis);
  }
  for (Index v = 0; v < m.vertices.size(); ++v)
    if (snap[v]) ++stats.moved;
  stats.refused = pending.size();
  // Undo the snaps that reverse the loop's order along the curve, until none is left.
  for (int round = 0; round < 8; ++round) {
    auto bad = out_of_order_snaps(loops, snap, boundary);
    std::sort(bad.begin(), bad.end());
    bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
    std::size_t undone = 0;
    for (Index v : bad) {
      if (!snap[v] || !move_if_safe(m, faces_of, v, before[v])) continue;
      snap[v].reset();
      ++undone;
      --stats.moved;
      ++stats.refused;
    }
    if (undone == 0) break;
  }
  return stats;
}

namespace {

// The point at arc length `arc` (taken modulo the curve's length) along curve c.
Point3 point_at_arc(const BoundaryPolylines& b, std::size_t c, double arc) {
  const double length = b.curve_length[c];
  const std::size_t start = b.curve_start[c], size = b.curve_size[c];
  arc = std::fmod(arc, length);
  if (arc < 0) arc += length;
  for (std::size_t k = 0; k < size; ++k) {
    const double a0 = b.arc[start + k], a1 = k + 1 < size ? b.arc[start + k + 1] : length;
    if (arc > a1 && k + 1 < size) continue;
    const Point3& p = b.points[start + k];
    const Point3& q = b.points[start + (k + 1) % size];
    const double f = a1 > a0 ? std::clamp((arc - a0) / (a1 - a0), 0.0, 1.0) : 0.0;
    return p + f * (q - p);
  }
  return b.points[start];
}

// Whether face f runs from a to b.
bool runs(const std::array<Index, 3>& f, Index a, Index b) {
  for (int k = 0; k < 3; ++k)
    if (f[k] == a && f[(k + 1) % 3] == b) return true;
  return false;
}

// The faces from `first` on (a patch) turned, if need be, so that the edge a-b, which one
// face before `first` and one after share, runs opposite ways in them (one orientation).
void orient_like_neighbour(TriangleMesh& m, std::size_t first, Index a, Index b) {
  bool old_ab = false, new_ab = false;
  for (std::size_t f = 0; f < m.triangles.size(); ++f) {
    const bool has = runs(m.triangles[f], a, b) || runs(m.triangles[f], b, a);
    if (!has) continue;
    (f < first ? old_ab : new_ab) = runs(m.triangles[f], a, b);
  }
  if (old_ab != new_ab) return;
  for (std::size_t f = first; f < m.triangles.size(); ++f) std::swap(m.triangles[f][1], m.triangles[f][2]);
}

// How many vertices on either side of a notch, along the curve, tell which way the border runs.
constexpr std::size_t kNotchSideVertices = 8;

}  // namespace

std::size_t close_border_notches(TaggedMesh& t, const envelope::SurfaceSamples& surface, double on_curve,
                                 double min_depth, double max_width) {
  if (surface.boundary.empty()) return 0;
  const BoundaryPolylines boundary = polylines_of(surface);
  const NearestIndex index(boundary.points);
  std::size_t closed = 0;
  for (const auto& border : border_loops(t.mesh)) {
    const std::vector<Index>& loop = border.vertices;
    const std::size_t n = loop.size();
    if (n < 4) continue;
    std::vector<CurvePoint> onto(n);
    std::vector<double> off(n);
    std::size_t near = 0;
    for (std::size_t k = 0; k < n; ++k) {
      onto[k] = onto_boundary(t.mesh.vertices[loop[k]], boundary, index);
      off[k] = std::sqrt(CGAL::squared_distance(t.mesh.vertices[loop[k]], onto[k].point));
      near += off[k] <= on_curve;
    }
    // A loop along a curve (a hole away from the curves is the hole filling's), not all on it.
    if (2 * near < n || near == n) continue;
    std::size_t first = 0;
    while (off[first] > on_curve) ++first;
    // Each run of vertices off the curve between two on it: a notch if it reaches min_depth
    // in and its ends lie on one curve within max_width of each other along it.
    for (std::size_t step = 0; step < n;) {
      const std::size_t u = (first + step) % n;
      std::size_t len = 1;
      while (len < n && off[(u + len) % n] > on_curve) ++len;
      step += len;
      if (len < 2) continue;
      const std::size_t w = (u + len) % n;
      double depth = 0.0;
      for (std::size_t d = 1; d < len; ++d) depth = std::max(depth, off[(u + d) % n]);
      const std::size_t c = onto[u].curve;
      if (depth < min_depth || onto[w].curve != c) continue;
      const double total = boundary.curve_length[c];
      // Which way the border runs along the curve on either side of the notch: the stretch
      // it misses goes from w back to u against that way (the other way round the curve is
      // the part the border follows).
      auto way = [&](std::size_t from, std::size_t to) {
        if (off[from] > on_curve || off[to] > on_curve || onto[from].curve != c || onto[to].curve != c) return 0.0;
        const double d = std::remainder(onto[to].arc - onto[from].arc, total);
        return d > 0 ? 1.0 : d < 0 ? -1.0 : 0.0;
      };
      // Over up to kNotchSideVertices on either side while they stay on the curve: a border
      // that steps back a vertex or two beside the notch still runs on the same way.
      std::size_t after = 0, before = 0;
      while (after < kNotchSideVertices && off[(w + after + 1) % n] <= on_curve) ++after;
      while (before < kNotchSideVertices && off[(u + n - before - 1) % n] <= on_curve) ++before;
      const double runs_on = way(w, (w + after) % n);
      if (runs_on == 0.0 || after < 2 || before < 2 || way((u + n - before) % n, u) != runs_on) continue;
      double along = std::fmod(runs_on * (onto[w].arc - onto[u].arc), total);  // from w back to u
      if (along < 0) along += total;
      const double sign = -runs_on;
      if (along > max_width) continue;
      // The notch's border, then back from its far end to its near end along the curve, at
      // about the notch's own edge length.
      double edges = 0.0;
      for (std::size_t d = 0; d < len; ++d)
        edges += std::sqrt(CGAL::squared_distance(t.mesh.vertices[loop[(u + d) % n]], t.mesh.vertices[loop[(u + d + 1) % n]]));
      const auto inner = static_cast<std::size_t>(std::max(0.0, std::ceil(along / (edges / static_cast<double>(len))) - 1));
      std::vector<Index> patch_loop;
      for (std::size_t d = 0; d <= len; ++d) patch_loop.push_back(loop[(u + d) % n]);
      const std::size_t old_size = t.mesh.vertices.size();
      for (std::size_t q = 1; q <= inner; ++q) {
        patch_loop.push_back(static_cast<Index>(t.mesh.vertices.size()));
        t.mesh.vertices.push_back(point_at_arc(boundary, c, onto[w].arc + sign * along * static_cast<double>(q) /
                                                                              static_cast<double>(inner + 1)));
      }
      const std::size_t old_faces = t.mesh.triangles.size();
      if (fill_with_patch(t, patch_loop)) {
        orient_like_neighbour(t.mesh, old_faces, patch_loop[0], patch_loop[1]);
        ++closed;
      } else {
        t.mesh.vertices.resize(old_size);
      }
    }
  }
  return closed;
}

}  // namespace envcrust::extract
