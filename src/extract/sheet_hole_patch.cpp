// Filling a border loop with a smooth disc: CGAL's hole triangulation of the loop, refined to
// the loop's edge density and faired with the loop held fixed.
#include "sheet_mesh.h"

#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

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

// Whether an edge of the patch between two loop vertices exists in the sheet already (the loop
// passes twice near one face, or a vertex twice): the patch would put a third face on it.
bool reuses_sheet_edge(const TaggedMesh& t, const std::vector<Index>& loop, const Patch& patch) {
  std::unordered_set<Index> on_loop;
  for (Index v : loop)
    if (!on_loop.insert(v).second) return true;  // a pinched loop
  std::unordered_set<std::uint64_t> sheet_edges;
  auto key = [](Index a, Index b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); };
  for (const auto& f : t.mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const Index a = f[k], b = f[(k + 1) % 3];
      if (on_loop.count(a) && on_loop.count(b)) sheet_edges.insert(key(a, b));
    }
  }
  for (auto e : patch.edges()) {
    const auto a = static_cast<std::size_t>(patch.vertex(e, 0)), b = static_cast<std::size_t>(patch.vertex(e, 1));
    const std::size_t gap = a > b ? a - b : b - a;
    if (gap == 1 || gap + 1 == loop.size()) continue;  // an edge of the loop itself
    if (sheet_edges.count(key(loop[a], loop[b]))) return true;
  }
  return false;
}

}  // namespace

bool fill_with_patch(TaggedMesh& t, const std::vector<Index>& loop) {
  std::vector<Point3> points;
  points.reserve(loop.size());
  for (Index v : loop) points.push_back(t.mesh.vertices[v]);
  Patch patch;
  if (loop.size() < 3 || !triangulate_loop(points, patch) || reuses_sheet_edge(t, loop, patch)) return false;

  // Interior vertices at about the loop's edge length (CGAL's density control), then the
  // smoothest surface through the loop (bi-Laplacian fairing, the loop fixed).
  std::vector<Patch::Face_index> new_faces;
  std::vector<Patch::Vertex_index> new_vertices;
  PMP::refine(patch, faces(patch), std::back_inserter(new_faces), std::back_inserter(new_vertices),
              CGAL::parameters::density_control_factor(std::sqrt(2.0)));
  if (!new_vertices.empty()) PMP::fair(patch, new_vertices);

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
