// Filling a border loop with a smooth disc: CGAL's hole triangulation of the loop (or rings
// shrunk from the loop where it finds none), refined to the loop's edge density and faired
// with the loop fixed.
#include "sheet_mesh.h"

#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <tuple>
#include <unordered_set>
#include <vector>

namespace envcrust::extract {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Patch = CGAL::Surface_mesh<Point3>;

// The loop's triangulation over its own vertices (minimal dihedral angle, then area, within
// the 3D Delaunay triangulation of the loop; no cubic search: a long loop would take
// minutes). False when CGAL found none or one a halfedge mesh cannot hold.
bool triangulate_loop(const std::vector<Point3>& points, Patch& patch) {
  std::vector<std::tuple<int, int, int>> triangles;
  PMP::triangulate_hole_polyline(points, std::back_inserter(triangles),
                                 CGAL::parameters::do_not_use_cubic_algorithm(true));
  if (triangles.size() + 2 != points.size()) return false;
  for (const Point3& p : points) patch.add_vertex(p);
  for (const auto& [a, b, c] : triangles) {
    if (patch.add_face(Patch::Vertex_index(a), Patch::Vertex_index(b), Patch::Vertex_index(c)) ==
        Patch::null_face())
      return false;
  }
  return true;
}

// A disc over any loop whose vertices are distinct, where CGAL's triangulation of the loop
// fails (long, twisted cut holes): rings shrunk from the loop towards its centroid, about one
// loop edge apart and with fewer vertices the further in (the same number per length), each
// zipped to the next by triangles in the order of their arc length, the innermost fanned to
// the centroid. A plain fan would leave a vertex of the loop's valence that neither CGAL's
// refinement (it reads the hole as fine enough from the spokes' length at the loop) nor its
// isotropic remeshing handles (tried: its tangential relaxation at that vertex took 18.7 s
// over the lion head's 15 long holes, and the loops' longest edges held its target length
// high, so some holes gained one vertex): the lion head's mouth came out as a star.
bool ring_disc(const std::vector<Point3>& loop, Patch& patch) {
  constexpr double kMaxRings = 64;
  const std::size_t n = loop.size();
  std::vector<double> arc(n + 1, 0.0);  // arc[i]: the loop's length up to vertex i, as a fraction
  Vector3 sum(0, 0, 0);
  for (std::size_t i = 0; i < n; ++i) {
    arc[i + 1] = arc[i] + std::sqrt(CGAL::squared_distance(loop[i], loop[(i + 1) % n]));
    sum = sum + (loop[i] - CGAL::ORIGIN);
  }
  const double length = arc[n];
  if (!(length > 0)) return false;
  for (double& a : arc) a /= length;
  const Point3 centre = CGAL::ORIGIN + sum / static_cast<double>(n);
  double radius = 0.0;
  for (const Point3& p : loop) radius += std::sqrt(CGAL::squared_distance(p, centre));
  radius /= static_cast<double>(n);
  const auto rings = static_cast<std::size_t>(std::clamp(std::round(radius / (length / static_cast<double>(n))), 1.0, kMaxRings));

  // The point at arc fraction u of the loop.
  auto on_loop = [&](double u) {
    const std::size_t i = std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::upper_bound(arc.begin(), arc.end(), u) - arc.begin()) - 1);
    const double span = arc[i + 1] - arc[i];
    const double f = span > 0 ? (u - arc[i]) / span : 0.0;
    return loop[i] + f * (loop[(i + 1) % n] - loop[i]);
  };
  for (const Point3& p : loop) patch.add_vertex(p);
  std::vector<Patch::Vertex_index> outer;
  std::vector<double> outer_arc(arc.begin(), arc.end() - 1);
  for (std::size_t i = 0; i < n; ++i) outer.push_back(Patch::Vertex_index(static_cast<std::uint32_t>(i)));
  auto add = [&](Patch::Vertex_index a, Patch::Vertex_index b, Patch::Vertex_index c) {
    return patch.add_face(a, b, c) != Patch::null_face();
  };
  for (std::size_t j = 1; j < rings; ++j) {
    const double t = static_cast<double>(j) / static_cast<double>(rings);
    const auto m = static_cast<std::size_t>(
        std::max(3.0, std::round(static_cast<double>(n) * (1.0 - t))));
    std::vector<Patch::Vertex_index> inner;
    std::vector<double> inner_arc;
    for (std::size_t q = 0; q < m; ++q) {
      const double u = static_cast<double>(q) / static_cast<double>(m);
      const Point3 p = on_loop(u);
      inner.push_back(patch.add_vertex(p + t * (centre - p)));
      inner_arc.push_back(u);
    }
    // Zip: advance on the ring whose next vertex comes first along the arc.
    std::size_t i = 0, q = 0;
    while (i < outer.size() || q < inner.size()) {
      const double next_outer = i + 1 < outer.size() ? outer_arc[i + 1] : 1.0;
      const double next_inner = q + 1 < inner.size() ? inner_arc[q + 1] : 1.0;
      const bool step_outer = q == inner.size() || (i < outer.size() && next_outer <= next_inner);
      const auto a = outer[i % outer.size()], b = inner[q % inner.size()];
      if (step_outer) {
        if (!add(a, outer[(i + 1) % outer.size()], b)) return false;
        ++i;
      } else {
        if (!add(a, inner[(q + 1) % inner.size()], b)) return false;
        ++q;
      }
    }
    outer = std::move(inner);
    outer_arc = std::move(inner_arc);
  }
  const auto middle = patch.add_vertex(centre);
  for (std::size_t i = 0; i < outer.size(); ++i)
    if (!add(outer[i], outer[(i + 1) % outer.size()], middle)) return false;
  return true;
}

// Whether an edge of the patch between two loop vertices exists in the sheet already (the loop
// passes twice near one face): the patch would put a third face on it. `sheet_edges` holds
// the sheet's edges between loop vertices (edge_key).
bool reuses_sheet_edge(const std::vector<Index>& loop, const Patch& patch,
                       const std::unordered_set<std::uint64_t>& sheet_edges) {
  for (auto e : patch.edges()) {
    const auto a = static_cast<std::size_t>(patch.vertex(e, 0)), b = static_cast<std::size_t>(patch.vertex(e, 1));
    if (a >= loop.size() || b >= loop.size()) continue;  // a vertex of the patch's own
    const std::size_t gap = a > b ? a - b : b - a;
    if (gap == 1 || gap + 1 == loop.size()) continue;  // an edge of the loop itself
    if (sheet_edges.count(edge_key(loop[a], loop[b]))) return true;
  }
  return false;
}

// The patch's own vertices: every one past the loop's (which come first and stay fixed).
std::vector<Patch::Vertex_index> inner_vertices(const Patch& patch, std::size_t loop_size) {
  std::vector<Patch::Vertex_index> inner;
  for (auto v : patch.vertices())
    if (static_cast<std::size_t>(v) >= loop_size) inner.push_back(v);
  return inner;
}

// The smoothest surface through the loop (bi-Laplacian fairing of the inner vertices).
void fair_inside(Patch& patch, std::size_t loop_size) {
  const auto inner = inner_vertices(patch, loop_size);
  if (!inner.empty()) PMP::fair(patch, inner);
}

// The membrane through the loop: every vertex past the loop's at the mean of its neighbours
// (uniform weights, one sparse solve), within the loop's convex hull whatever shape the
// patch starts from. The bi-Laplacian fairing takes its cotangent weights from that shape:
// from the rings shrunk into a zigzag loop it overshot by 20% of the lion head's diagonal,
// from the membrane it does not.
void relax_to_membrane(Patch& patch, std::size_t loop_size) {
  const auto inner = inner_vertices(patch, loop_size);
  if (inner.empty()) return;
  std::vector<int> row(patch.num_vertices(), -1);
  for (std::size_t r = 0; r < inner.size(); ++r) row[inner[r]] = static_cast<int>(r);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(inner.size()), 3);
  for (std::size_t r = 0; r < inner.size(); ++r) {
    double degree = 0.0;
    for (auto w : CGAL::vertices_around_target(patch.halfedge(inner[r]), patch)) {
      degree += 1.0;
      if (row[w] >= 0) {
        entries.emplace_back(static_cast<int>(r), row[w], -1.0);
      } else {
        const Point3& p = patch.point(w);
        rhs(static_cast<Eigen::Index>(r), 0) += p.x();
        rhs(static_cast<Eigen::Index>(r), 1) += p.y();
        rhs(static_cast<Eigen::Index>(r), 2) += p.z();
      }
    }
    entries.emplace_back(static_cast<int>(r), static_cast<int>(r), degree);
  }
  Eigen::SparseMatrix<double> laplacian(static_cast<Eigen::Index>(inner.size()), static_cast<Eigen::Index>(inner.size()));
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(laplacian);
  if (solver.info() != Eigen::Success) return;
  const Eigen::MatrixXd x = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return;
  for (std::size_t r = 0; r < inner.size(); ++r) {
    const auto i = static_cast<Eigen::Index>(r);
    patch.point(inner[r]) = Point3(x(i, 0), x(i, 1), x(i, 2));
  }
}

// Interior vertices at about the loop's edge length (CGAL's density control, which reads
// the lengths of the edges at the loop's vertices), then faired.
void refine_and_fair(Patch& patch, std::size_t loop_size) {
  std::vector<Patch::Face_index> new_faces;
  std::vector<Patch::Vertex_index> new_vertices;
  PMP::refine(patch, faces(patch), std::back_inserter(new_faces), std::back_inserter(new_vertices),
              CGAL::parameters::density_control_factor(std::sqrt(2.0)));
  fair_inside(patch, loop_size);
}

}  // namespace

std::unordered_set<std::uint64_t> edges_among(const TriangleMesh& mesh, const std::vector<std::vector<Index>>& loops) {
  std::vector<char> on_loop(mesh.vertices.size(), 0);
  for (const auto& loop : loops)
    for (Index v : loop)
      if (v < on_loop.size()) on_loop[v] = 1;
  std::unordered_set<std::uint64_t> edges;
  for (const auto& f : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Index a = f[k], b = f[(k + 1) % 3];
      if (on_loop[a] && on_loop[b]) edges.insert(edge_key(a, b));
    }
  }
  return edges;
}

bool fill_with_patch(TaggedMesh& t, const std::vector<Index>& loop) {
  return fill_with_patch(t, loop, edges_among(t.mesh, {loop}));
}

bool fill_with_patch(TaggedMesh& t, const std::vector<Index>& loop, const std::unordered_set<std::uint64_t>& sheet_edges) {
  if (loop.size() < 3) return false;
  std::unordered_set<Index> on_loop;
  for (Index v : loop)
    if (!on_loop.insert(v).second) return false;  // a pinched loop: no disc spans it
  std::vector<Point3> points;
  points.reserve(loop.size());
  for (Index v : loop) points.push_back(t.mesh.vertices[v]);
  // CGAL's triangulation of the loop where it finds one that puts no third face on a sheet
  // edge, refined; refinement may flip an edge onto two loop vertices, so the check is
  // repeated after it. Else the rings, already at the loop's density and with no edge between
  // two loop vertices but the loop's own, are not refined (that flipped edges onto the sheet's
  // on 7 of the lion head's 14 long cut holes): relaxed to the membrane, then faired from it.
  Patch patch;
  bool ok = false;
  if (triangulate_loop(points, patch) && !reuses_sheet_edge(loop, patch, sheet_edges)) {
    refine_and_fair(patch, loop.size());
    ok = !reuses_sheet_edge(loop, patch, sheet_edges);
  }
  if (!ok) {
    patch = Patch();
    if (!ring_disc(points, patch)) return false;
    relax_to_membrane(patch, loop.size());
    fair_inside(patch, loop.size());
  }

  std::vector<Index> index(patch.number_of_vertices());
  for (auto v : patch.vertices()) {
    if (static_cast<std::size_t>(v) < loop.size()) {
      index[v] = loop[v];
    } else {
      index[v] = static_cast<Index>(t.mesh.vertices.size());
      t.mesh.vertices.push_back(patch.point(v));
    }
  }
  for (auto f : patch.faces()) {
    std::array<Index, 3> tri{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(patch.halfedge(f), patch)) tri[k++] = index[v];
    t.mesh.triangles.push_back(tri);
    t.face_dot.push_back(-1.0);
  }
  return true;
}

}  // namespace envcrust::extract
