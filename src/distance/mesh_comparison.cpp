// Two-sided comparison of a mesh with a reference mesh or point set.
#include "envcrust/distance.h"
#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <algorithm>

namespace envcrust::distance {
namespace {

std::vector<Point3> vertices_and_samples(const TriangleMesh& mesh, const DistanceOptions& o,
                                         std::uint64_t seed_offset) {
  std::vector<Point3> points = mesh::sample_by_area(mesh, o.samples, o.seed + seed_offset);
  // Only vertices that a triangle uses belong to the surface.
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (Index v : t) used[v] = true;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (used[v]) points.push_back(mesh.vertices[v]);
  return points;
}

void require_triangles(const TriangleMesh& mesh, const char* what) {
  if (mesh.triangles.empty()) throw InvalidInput(std::string(what) + " has no triangles");
}

}  // namespace

DistanceReport compare_to_mesh(const TriangleMesh& mesh, const TriangleMesh& reference,
                               const DistanceOptions& options) {
  require_triangles(mesh, "the mesh");
  require_triangles(reference, "the reference mesh");
  DistanceReport out;
  out.mesh_to_reference = points_to_mesh(vertices_and_samples(mesh, options, 0), reference);
  out.reference_to_mesh = points_to_mesh(vertices_and_samples(reference, options, 1), mesh);
  out.hausdorff = std::max(out.mesh_to_reference.max, out.reference_to_mesh.max);
  out.reference_diagonal = mesh::bbox_diagonal(reference.vertices);
  return out;
}

DistanceReport compare_to_points(const TriangleMesh& mesh, const std::vector<Point3>& reference,
                                 const DistanceOptions& options) {
  require_triangles(mesh, "the mesh");
  if (reference.empty()) throw InvalidInput("the reference point set is empty");
  DistanceReport out;
  out.mesh_to_reference = points_to_points(vertices_and_samples(mesh, options, 0), reference);
  out.reference_to_mesh = points_to_mesh(reference, mesh);
  out.hausdorff = std::max(out.mesh_to_reference.max, out.reference_to_mesh.max);
  out.reference_diagonal = mesh::bbox_diagonal(reference);
  return out;
}

}  // namespace envcrust::distance
