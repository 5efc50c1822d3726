// Input resolution: built-in surfaces versus files, meshes versus point sets.
#include "inputs.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/mesh.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"

#include <filesystem>

namespace envcrust::cli {
namespace {

constexpr std::string_view kBuiltinPrefix = "builtin:";
constexpr std::size_t kMaxReferenceLoops = 64;

}  // namespace

bool is_builtin_spec(const std::string& spec) { return spec.rfind(kBuiltinPrefix, 0) == 0; }

bool is_parametric_spec(const std::string& spec) { return is_builtin_spec(spec) || io::is_nurbs_file(spec); }

std::optional<models::PatchModel> parametric_model(const std::string& spec, const models::JoinOptions& join) {
  if (is_builtin_spec(spec)) {
    std::vector<std::unique_ptr<surfaces::Surface>> one;
    one.push_back(surfaces::make_builtin(spec.substr(kBuiltinPrefix.size())));
    std::string name = one.front()->name();
    return models::PatchModel(std::move(one), std::move(name));
  }
  if (!io::is_nurbs_file(spec)) return std::nullopt;
  auto read = io::read_nurbs_patches(spec);
  const std::string stem = std::filesystem::path(spec).stem().string();
  std::vector<std::unique_ptr<surfaces::Surface>> patches;
  for (std::size_t i = 0; i < read.size(); ++i) {
    const std::string which = read.size() > 1 ? "patch " + std::to_string(i + 1) + " of " + std::to_string(read.size()) + ": " : "";
    try {
      patches.push_back(surfaces::make_nurbs_surface(std::move(read[i]), read.size() > 1 ? stem + "." + std::to_string(i + 1) : stem));
    } catch (const InvalidInput& e) {
      throw InvalidInput(spec + ": " + which + e.what());
    }
  }
  try {
    return models::PatchModel(std::move(patches), stem, join);
  } catch (const InvalidInput& e) {
    throw InvalidInput(spec + ": " + e.what());
  }
}

TriangleMesh load_mesh(const std::string& spec) {
  if (is_parametric_spec(spec)) return parametric_model(spec)->truth();
  return io::read_triangle_mesh(spec);
}

analysis::Reference load_reference(const std::string& spec, const models::JoinOptions& join) {
  analysis::Reference reference;
  if (is_parametric_spec(spec)) {
    const auto model = parametric_model(spec, join);
    reference.mesh = model->truth();
    for (const auto& curve : model->boundary_curves(2e-3 * model->diagonal()))
      reference.boundary.push_back(curve.polyline());
    return reference;
  }
  const std::string ext = io::extension_of(spec);
  if (ext == "off" || ext == "obj" || ext == "stl") {
    reference.mesh = io::read_triangle_mesh(spec);
  } else if (ext == "ply") {
    // A PLY file may be a mesh or a point set: faces decide. read_polygon_mesh refuses a
    // file without faces, and the point reader then gives the real error, if any.
    try {
      reference.mesh = mesh::triangulate_polygons(io::read_polygon_mesh(spec));
    } catch (const IoError&) {
      reference.points = io::read_points(spec).points;
    }
  } else {
    reference.points = io::read_points(spec).points;
  }
  // A reference mesh's border loops are the true boundary the result is matched against
  // (a scan's own mesh: the bunny's 5 holes). Beyond kMaxReferenceLoops, a ragged mesh's
  // crumbs, none is matched.
  if (reference.mesh) {
    const auto loops = topology::boundary_loops(*reference.mesh);
    if (loops.size() <= kMaxReferenceLoops)
      for (const auto& loop : loops) reference.boundary.push_back(loop.polyline(reference.mesh->vertices));
  }
  // Distances are reported against the reference's size: it needs one.
  const auto& points = reference.mesh ? reference.mesh->vertices : reference.points;
  if (!(mesh::bbox_diagonal(points) > 0))
    throw InvalidInput(spec + ": all its points coincide (a bounding box of no size: nothing to measure against or to frame)");
  return reference;
}

}  // namespace envcrust::cli
