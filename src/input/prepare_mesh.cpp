// Samples of M from a triangle mesh: vertices and face centres with their normal lines, the
// border loops, the mesh's own topology, its long sharp creases.
#include "creases.h"
#include "input_names.h"
#include "local_origin.h"

#include "envcrust/input.h"
#include "envcrust/mesh.h"
#include "envcrust/normals.h"
#include "envcrust/topology.h"

#include <cmath>
#include <utility>

namespace envcrust::input {
namespace {

// Coincident vertices are one point of the surface (the analyzer welds them too): an export
// that splits vertices along seams (per-face normals or texture coordinates, separate parts)
// would otherwise read as pieces with false border loops along every seam. Repeated faces
// keep one copy.
TriangleMesh cleaned(TriangleMesh mesh, const std::string& name, std::vector<std::string>& notes) {
  if (mesh.triangles.empty()) throw InvalidInput(named(name, "the mesh has no faces"));
  naming(name, [&] { mesh::check_coordinates(mesh.vertices, "vertex"); });
  const std::size_t vertices_used = mesh::used_vertex_count(mesh);
  mesh = mesh::weld_identical_vertices(mesh);
  if (const std::size_t welded = vertices_used - mesh.vertices.size(); welded > 0)
    notes.push_back(std::to_string(welded) + " vertices at the coordinates of another welded to it");
  const std::size_t dropped = mesh::remove_duplicate_faces(mesh);
  if (mesh.triangles.empty())
    throw InvalidInput(
        named(name, "the mesh has no faces but " + std::to_string(dropped) + " that use a vertex twice"));
  if (dropped > 0) notes.push_back(std::to_string(dropped) + " repeated or degenerate faces dropped");
  return mesh;
}

// The used vertices with their area-weighted normal lines, then the face centres with face
// normals (the faces carry the surface between vertices).
void add_vertex_and_face_samples(const TriangleMesh& mesh, const std::vector<Vector3>& vertex_normals,
                                 envelope::SurfaceSamples& samples) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (Index v : t) used[v] = true;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!used[v] || vertex_normals[v].squared_length() == 0) continue;
    samples.points.push_back(mesh.vertices[v]);
    samples.normals.push_back(vertex_normals[v]);
  }
  for (const auto& t : mesh.triangles) {
    const Point3& a = mesh.vertices[t[0]];
    const Point3& b = mesh.vertices[t[1]];
    const Point3& c = mesh.vertices[t[2]];
    const Vector3 n = CGAL::cross_product(b - a, c - a);
    const double len = std::sqrt(n.squared_length());
    if (!(len > 0)) continue;
    samples.points.push_back(CGAL::centroid(a, b, c));
    samples.normals.push_back(n / len);
  }
}

void check_attribute_count(std::size_t count, std::size_t vertices, const std::string& what,
                           const std::string& name) {
  if (count != vertices)
    throw InvalidInput(named(name, "the vertex " + what + " number " + std::to_string(count) + " for " +
                                       std::to_string(vertices) + " vertices"));
}

// The attributes of the vertices the faces use, at those vertices (the output's vertices take
// the nearest one's): an unused vertex is no point of the surface.
void keep_vertex_attributes(const TriangleMesh& mesh, const PointAttributes& attributes, const std::string& name,
                            PreparedInput& out) {
  if (attributes.empty()) return;
  if (attributes.has_colours()) check_attribute_count(attributes.colours.size(), mesh.vertices.size(), "colours", name);
  for (std::size_t c = 0; c < attributes.scalars.size(); ++c)
    check_attribute_count(attributes.scalars[c].size(), mesh.vertices.size(),
                          "values of '" + (c < attributes.names.size() ? attributes.names[c] : std::string()) + "'",
                          name);
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (Index v : t)
      if (v < used.size()) used[v] = true;
  std::vector<std::size_t> picks;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) {
      picks.push_back(v);
      out.attribute_points.push_back(mesh.vertices[v]);
    }
  out.attributes = attributes.pick(picks);
}

}  // namespace

PreparedInput prepare_mesh(TriangleMesh input, const InputOptions& options) {
  return prepare_mesh(MeshInput{std::move(input), {}}, options);
}

PreparedInput prepare_mesh(MeshInput input, const InputOptions& options) {
  PreparedInput out;
  out.kind.is_builtin = false;
  keep_vertex_attributes(input.mesh, input.vertex_attributes, options.name, out);
  TriangleMesh mesh = cleaned(std::move(input.mesh), options.name, out.notes);
  if (options.use_local_origin) {
    out.origin = local_origin(mesh.vertices);
    if (out.origin != CGAL::NULL_VECTOR) {
      out.notes.push_back(origin_note(mesh.vertices, out.origin));
      subtract_origin(mesh.vertices, out.origin);
      subtract_origin(out.attribute_points, out.origin);
    }
  }
  const auto vertex_normals = normals::mesh_vertex_normal_lines(mesh);
  try {
    out.samples.boundary = boundary::mesh_boundary_curves(mesh, vertex_normals);
  } catch (const InvalidInput& e) {
    throw NotASurface(named(options.name, e.what()));
  }
  const auto mesh_topology = topology::analyze_topology(mesh);  // a manifold, checked above
  out.kind.is_orientable = mesh_topology.is_orientable;
  out.kind.genus = topology::total_genus(mesh_topology);
  add_vertex_and_face_samples(mesh, vertex_normals, out.samples);
  if (out.samples.points.empty()) throw InvalidInput(named(options.name, "the mesh has no face of positive area"));
  out.notes.push_back("mesh vertices and face centres; " + std::to_string(out.samples.boundary.size()) +
                      " border loops");
  // Long sharp creases: rounded off by fitted normal lines (the measurements are in
  // docs/reconstruct.md, sharp creases; normal lines smoothed along the mesh over 1-3 rings
  // of faces instead, summed as oriented vectors, read 2.6-7.9% / 3.6-7.3% on the open box of
  // 12 x 12 grids, each after the adaptive retry, where the fitted ones read 1.1% / 2.0%), or
  // joined by the sheet.
  auto sharp = mesh::sharp_edges(mesh, kTearingBendDeg);
  if (!is_long_crease(sharp, mesh.vertices)) return out;
  out.notes.push_back(crease_note("the mesh bends", sharp, "edges", options.creases));
  if (options.creases == CreaseMode::Join) {
    out.samples.creases = std::move(sharp.segments);
  } else {
    out.samples.normals = fitted_like(out.samples.points, out.samples.normals);
  }
  return out;
}

}  // namespace envcrust::input
