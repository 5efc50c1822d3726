// isotropic_remesh: CGAL's isotropic remeshing on a Surface_mesh built from the soup.
#include "isotropic.h"

#include "envcrust/errors.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace envcrust::remesh {
namespace {

using SurfaceMesh = CGAL::Surface_mesh<Point3>;
namespace PMP = CGAL::Polygon_mesh_processing;

SurfaceMesh to_surface_mesh(const TriangleMesh& mesh) {
  std::vector<Point3> points = mesh.vertices;
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) polygons.push_back({t[0], t[1], t[2]});
  // A manifold orientable mesh is oriented without duplicating any vertex; a false return
  // means it was not one after all.
  if (!PMP::orient_polygon_soup(points, polygons) || points.size() != mesh.vertices.size() ||
      !PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw NumericalFailure("remeshing: the faces cannot be oriented into a halfedge mesh");
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  return sm;
}

TriangleMesh to_triangle_mesh(const SurfaceMesh& sm) {
  TriangleMesh out;
  constexpr Index unused = std::numeric_limits<Index>::max();
  std::vector<Index> index(sm.num_vertices() + sm.number_of_removed_vertices(), unused);
  for (const auto f : sm.faces()) {
    std::array<Index, 3> tri{};
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (index[v] == unused) {
        index[v] = static_cast<Index>(out.vertices.size());
        out.vertices.push_back(sm.point(v));
      }
      if (k < 3) tri[k] = index[v];
      ++k;
    }
    if (k != 3) throw NumericalFailure("remeshing: CGAL returned a face with " + std::to_string(k) + " vertices");
    out.triangles.push_back(tri);
  }
  return out;
}

}  // namespace

double median_edge_length(const TriangleMesh& mesh) {
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) edges.emplace_back(std::minmax(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> lengths;
  lengths.reserve(edges.size());
  for (const auto& [a, b] : edges)
    if (a != b) lengths.push_back(std::sqrt(CGAL::squared_distance(mesh.vertices[a], mesh.vertices[b])));
  if (lengths.empty()) return 0.0;
  auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

TriangleMesh isotropic_remesh(const TriangleMesh& mesh, double target_edge_length, int iterations,
                              BoundaryMode boundary) {
  SurfaceMesh sm = to_surface_mesh(mesh);
  const auto nb_iter = static_cast<unsigned int>(iterations);
  if (boundary == BoundaryMode::Keep) {
    // Protected edges must not exceed 4/3 of the target (CGAL's precondition).
    std::vector<SurfaceMesh::Edge_index> border;
    for (const auto e : sm.edges())
      if (sm.is_border(e)) border.push_back(e);
    PMP::split_long_edges(border, 4.0 / 3.0 * target_edge_length, sm);
    PMP::isotropic_remeshing(faces(sm), target_edge_length, sm,
                             CGAL::parameters::number_of_iterations(nb_iter).protect_constraints(true));
  } else {
    // Border edges are constrained by default: split and collapsed along the border only, and
    // their vertices do not move (relax_constraints would cut the border's corners).
    PMP::isotropic_remeshing(faces(sm), target_edge_length, sm,
                             CGAL::parameters::number_of_iterations(nb_iter));
  }
  return to_triangle_mesh(sm);
}

}  // namespace envcrust::remesh
