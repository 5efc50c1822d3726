// Loading samples of M from a built-in surface, a point file or a mesh file: the files are
// read here, the samples prepared by the library (input::prepare_points, prepare_mesh,
// prepare_model).
#include "surface_input.h"

#include "cli_common.h"
#include "inputs.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/mesh.h"

#include <optional>
#include <utility>

namespace envcrust::cli {
namespace {

// The points of every --boundary file: a point file, or a closed curve (.polyline). Their
// normals (outward conormals) are kept only if every file has them.
PointSet read_boundary_points(const std::vector<std::string>& files) {
  PointSet all;
  bool has_normals = true;
  for (const auto& file : files) {
    PointSet part;
    if (io::extension_of(file) == "polyline") {
      part.points = io::read_polyline(file);
    } else {
      part = io::read_points(file);
    }
    has_normals = has_normals && part.has_normals();
    all.points.insert(all.points.end(), part.points.begin(), part.points.end());
    all.normals.insert(all.normals.end(), part.normals.begin(), part.normals.end());
  }
  if (!has_normals) all.normals.clear();
  return all;
}

// The --boundary files' points, named by the files in messages about them.
std::optional<input::GivenBoundary> given_boundary(const std::vector<std::string>& files) {
  if (files.empty()) return std::nullopt;
  input::GivenBoundary given;
  given.points = read_boundary_points(files);
  for (const auto& f : files) given.name += (given.name.empty() ? "" : ", ") + f;
  return given;
}

// The library's options, naming the input in its messages.
input::InputOptions named_options(const std::string& spec, const InputSettings& sampling) {
  input::InputOptions options = sampling.preparation;
  options.name = spec;
  return options;
}

LoadedSurface loaded_as(input::PreparedInput prepared, std::string source) {
  LoadedSurface out;
  static_cast<input::PreparedInput&>(out) = std::move(prepared);
  out.source = std::move(source);
  return out;
}

// Samples of M from a point set read from `spec` (a file, a mesh's vertices, or a built-in
// surface's samples without normals). `are_normals_text_columns`: see input::PointInput.
LoadedSurface load_point_samples(AttributedPoints read, bool are_normals_text_columns, const std::string& spec,
                                 const InputSettings& sampling, const Progress& progress) {
  input::PointInput points;
  points.points = std::move(read);
  points.are_normals_text_columns = are_normals_text_columns;
  points.given_boundary = given_boundary(sampling.boundary_files);
  LoadedSurface out =
      loaded_as(input::prepare_points(std::move(points), named_options(spec, sampling), progress), "points");
  if (out.kind.is_boundary_detected) out.min_loop_width = sampling.preparation.boundary.min_loop_width;
  return out;
}

// A mesh file's samples, and its vertex colours (and a PLY's other vertex properties) for the
// output's vertices.
LoadedSurface load_mesh_samples(TriangleMesh mesh, const std::string& spec, const InputSettings& sampling) {
  input::MeshInput in{std::move(mesh), {}};
  if (const std::string ext = io::extension_of(spec); ext == "ply" || ext == "obj") {
    AttributedPoints vertices = io::read_attributed_points(spec);
    // Both readers list the file's vertices in its order; should a reader ever not, the
    // attributes are left out rather than put on the wrong vertices.
    if (vertices.points.points == in.mesh.vertices) in.vertex_attributes = std::move(vertices.attributes);
  }
  try {
    return loaded_as(input::prepare_mesh(std::move(in), named_options(spec, sampling)), "mesh");
  } catch (const input::NotASurface& e) {
    throw InvalidInput(std::string(e.what()) + " (--as-points reads its vertices as a point file)");
  }
}

// builtin:NAME or a NURBS file, sampled (with its exact normals and boundary, or without them
// as a point file is read: --boundary on builtin inputs of `envcrust boundary`).
LoadedSurface load_parametric(const std::string& spec, const InputSettings& sampling, const Progress& progress) {
  // A NURBS file is read as a built-in surface is (kind keeps is_builtin: no scan cuts).
  const auto model = parametric_model(spec, sampling.join);
  surfaces::SampleOptions o;
  o.count = sampling.count;
  o.noise_rel_diag = sampling.noise_rel_diag;
  o.seed = sampling.seed;
  if (!sampling.builtin_as_points)
    return loaded_as(input::prepare_model(*model, o, named_options(spec, sampling)),
                     is_builtin_spec(spec) ? "builtin" : "nurbs");
  LoadedSurface out = load_point_samples({model->sample(o), {}}, false, spec, sampling, progress);
  out.notes.push_back("sampled from " + model->name() + " without its normals and boundary");
  return out;
}

// The vertices the faces use, as a point file (--as-points).
LoadedSurface load_mesh_vertices(const TriangleMesh& mesh, const std::string& spec, const InputSettings& sampling,
                                 const Progress& progress) {
  PointSet vertices;
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (const Index v : t) used[v] = true;
  for (std::size_t v = 0; v < used.size(); ++v)
    if (used[v]) vertices.points.push_back(mesh.vertices[v]);
  const std::size_t count = vertices.points.size();
  LoadedSurface out = load_point_samples({std::move(vertices), {}}, false, spec, sampling, progress);
  out.notes.insert(out.notes.begin(),
                   "the mesh's " + std::to_string(count) + " vertices read as a point file (--as-points)");
  return out;
}

}  // namespace

CLI::Option* add_boundary_options(CLI::App& sub, InputSettings& sampling) {
  auto* given = sub.add_option("--boundary", sampling.boundary_files,
                               "Point files: boundary points to use instead of detecting them (point files in any "
                               "order or closed .polyline curves, repeatable, several loops; each point marks its "
                               "nearest sample; normals, if every file has them, are outward conormals)");
  sub.add_option("--boundary-min-length", sampling.preparation.boundary.min_loop_length,
                 "Point files: drop detected loops shorter than this many spacings (chains of false "
                 "candidates around random voids; holes this short are below the envelope's resolution)")
      ->capture_default_str()
      ->check(number_above(0, true));
  sub.add_option("--boundary-min-width", sampling.preparation.boundary.min_loop_width,
                 "Point files: drop detected loops narrower than this many local spacings "
                 "(sampling gaps, not holes); 0 keeps all")
      ->capture_default_str()
      ->check(number_above(0, true));
  sub.add_flag("--no-boundary-outer-fit",
               [&sampling](std::int64_t) { sampling.preparation.boundary.fit_to_outer_samples = false; },
               "Point files: leave detected curves on the centre line of the flagged band instead of "
               "moving them out to its outermost samples");
  sub.add_flag("--boundary-take-in",
               [&sampling](std::int64_t) { sampling.preparation.boundary.take_in_samples_beyond = true; },
               "Point files: bulge detected curves out past samples still beyond them (lone samples on the "
               "rim beside a void), instead of leaving those outside");
  sub.add_flag("--as-points", sampling.mesh_as_points,
               "Mesh files: read only the vertices its faces use, as a point file (normals estimated, boundary "
               "detected, point-file options apply): for a mesh that is no surface (an edge with 3 faces)");
  sub.add_flag("--no-boundary-inlet-closing",
               [&sampling](std::int64_t) { sampling.preparation.boundary.close_narrow_inlets = false; },
               "Point files: keep the narrow inlets that voids beside the rim cut into detected curves");
  sub.add_flag("--boundary-density-steps",
               [&sampling](std::int64_t) { sampling.preparation.boundary.drop_density_steps = true; },
               "Point files: drop the detected rim samples beyond which the surface goes on, sampled more "
               "sparsely (the edges of densely sampled parts)");
  sub.add_flag("--boundary-local-spacing",
               [&sampling](std::int64_t) { sampling.preparation.boundary.link_in_local_spacing = true; },
               "Point files: link detected rims in their local sample spacing where that is larger than "
               "the average (a part sampled several times more sparsely than the rest)");
  return given;
}

void add_crease_options(CLI::App& sub, InputSettings& sampling) {
  sub.add_option_function<std::string>(
         "--creases", [&sampling](const std::string& mode) {
           sampling.preparation.creases = mode == "join" ? input::CreaseMode::Join : input::CreaseMode::Round;
         },
         "Meshes bent, and point files whose normals jump, by more than 80 degrees along creases longer in all "
         "than a tenth of the diagonal: round (fitted normal lines round the creases off; closer to the creased "
         "surface) or join (the normals kept, the sheet joined across the creases) [round]")
      ->check(CLI::IsMember({"round", "join"}));
}

void add_join_option(CLI::App& sub, models::JoinOptions& join) {
  sub.add_option("--join-tolerance", join.tolerance_rel_diag,
                 "NURBS files of several patches: join edges of two patches closer than this fraction of the "
                 "model's diagonal (CAD faces meet within the modeller's tolerance; a note counts the border vertices "
                 "left open within 20 times it)")
      ->capture_default_str()
      ->check(number_in(0, 0.05, false, true));
}

void add_outlier_options(CLI::App& sub, InputSettings& sampling) {
  sub.add_flag("--keep-outliers", [&sampling](std::int64_t) { sampling.preparation.use_outlier_removal = false; },
               "Point files: keep the stray samples that are otherwise removed first (points farther from the "
               "plane of their 16 nearest neighbours than half the distance to the farthest of them and 8 times "
               "the residual there, or 4 times farther from them than those are from theirs)");
}

void add_classes_option(CLI::App& sub, InputSettings& sampling) {
  sub.add_option("--classes", sampling.preparation.classes,
                 "Point files: keep only the points of these classes, e.g. 2,6 (a LAS file's classification: "
                 "2 ground, 6 building, ...; a point file's column named 'classification'); default: all")
      ->delimiter(',')
      ->check(CLI::Range(0, 255));
}

LoadedSurface load_surface(const std::string& spec, const InputSettings& sampling, const Progress& progress) {
  if (!sampling.preparation.classes.empty() && is_parametric_spec(spec))
    throw UsageError("--classes applies to point files: " + spec + " has no classes");
  if (!sampling.boundary_files.empty() && is_parametric_spec(spec) && !sampling.builtin_as_points)
    throw UsageError("--boundary applies to point files: " + spec + " brings its exact boundary");
  if (sampling.mesh_as_points && is_parametric_spec(spec))
    throw UsageError("--as-points applies to mesh files: " + spec + " is sampled with its exact normals");
  if (is_parametric_spec(spec)) return load_parametric(spec, sampling, progress);
  const std::string ext = io::extension_of(spec);
  std::optional<TriangleMesh> mesh;
  if (ext == "off" || ext == "obj" || ext == "stl") {
    mesh = io::read_triangle_mesh(spec);
  } else if (ext == "ply") {
    try {  // a PLY file with faces is a mesh, without faces a point set
      mesh = mesh::triangulate_polygons(io::read_polygon_mesh(spec));
    } catch (const IoError&) {
    }
  }
  if (mesh && sampling.mesh_as_points) return load_mesh_vertices(*mesh, spec, sampling, progress);
  if (mesh && !sampling.preparation.classes.empty())
    throw UsageError("--classes applies to point files: the mesh " + spec + " has no classes");
  if (mesh) {
    if (!sampling.boundary_files.empty())
      throw UsageError("--boundary applies to point files: the mesh " + spec + " brings its border loops");
    return load_mesh_samples(std::move(*mesh), spec, sampling);
  }
  if (sampling.mesh_as_points) throw UsageError("--as-points applies to mesh files: " + spec + " has no faces");
  // A point file's steps before the envelope take seconds on a million points.
  progress.report("input: reading", 0.0);
  LoadedSurface out =
      load_point_samples(io::read_attributed_points(spec), io::is_text_point_file(spec), spec, sampling, progress);
  progress.report("input", 1.0);
  return out;
}

}  // namespace envcrust::cli
