// Loading samples of M from a built-in surface, a point file or a mesh file.
#include "surface_input.h"

#include "inputs.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/surfaces.h"

namespace envcrust::cli {

LoadedSurface load_surface(const std::string& spec, const BuiltinSampling& sampling) {
  LoadedSurface out;
  if (is_builtin_spec(spec)) {
    const auto surface = surfaces::make_builtin(spec.substr(std::string("builtin:").size()));
    surfaces::SampleOptions o;
    o.count = sampling.count;
    o.noise_rel_diag = sampling.noise_rel_diag;
    o.seed = sampling.seed;
    o.with_normals = true;
    PointSet points = surfaces::sample_surface(*surface, o);
    out.samples.points = std::move(points.points);
    out.samples.normals = std::move(points.normals);
    out.samples.boundary = surfaces::boundary_curves(*surface, 0.005 * surfaces::bbox_diagonal(*surface));
    out.source = "builtin";
    out.notes.push_back("exact normals and boundary curves of " + surface->name());
    return out;
  }
  const std::string ext = io::extension_of(spec);
  if (ext == "xyz" || ext == "pts" || ext == "txt" || ext == "ply") {
    PointSet points = io::read_points(spec);
    if (!points.has_normals())
      throw InvalidInput(spec + ": the point set has no normals (6 columns or PLY nx ny nz are needed)");
    out.samples.points = std::move(points.points);
    out.samples.normals = std::move(points.normals);
    out.source = "points";
    out.notes.push_back("normals from the file; no boundary curves");
    return out;
  }
  throw InvalidInput(spec + ": unknown input (expected builtin:NAME or a point file)");
}

}  // namespace envcrust::cli
