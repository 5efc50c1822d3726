// Loading samples of M from a built-in surface, a point file or a mesh file.
#include "surface_input.h"

#include "cli_common.h"
#include "inputs.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/boundary.h"
#include "envcrust/mesh.h"
#include "envcrust/normals.h"
#include "envcrust/outliers.h"
#include "envcrust/surfaces.h"
#include "envcrust/topology.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <utility>

namespace envcrust::cli {
namespace {

// A mesh bent by more than this across an edge: the sheet pairs samples on either side of
// M whose offset directions make at least extract::SheetOptions::min_angle_deg (100), and
// across a crease bent by b the two sides' samples make 180 - b. Measured on a square sheet
// folded along a line (two unit squares, 3,200 faces): one disc up to a bend of 75 degrees,
// two pieces torn apart at the fold at 90 (rho automatic, 0.05 and 0.1 alike).
constexpr double kTearingBendDeg = 80.0;
// ... along edges longer in total than this fraction of the diagonal (a crease, not a few
// bad triangles of a scan: the foot mesh has 2.6%, the face mesh 6.3%, both reconstructed
// right; the lion head 70%, an open box 462%).
constexpr double kCreaseMinLengthRelDiag = 0.1;

// Sharp edges long enough in all to tear the sheet (a crease, not a few bad triangles).
bool is_long_crease(const mesh::SharpEdges& sharp, const std::vector<Point3>& points) {
  return sharp.count > 0 && sharp.total_length > kCreaseMinLengthRelDiag * mesh::bbox_diagonal(points);
}

// Normal lines fitted to the samples (PCA over 24 neighbours), each turned to agree with the
// sample's given normal: they turn across a crease where the given ones jump.
std::vector<Vector3> fitted_like(const std::vector<Point3>& points, const std::vector<Vector3>& given) {
  std::vector<Vector3> fitted = normals::estimate_normal_lines(points);
  for (std::size_t i = 0; i < fitted.size(); ++i)
    if (fitted[i] * given[i] < 0) fitted[i] = -fitted[i];
  return fitted;
}

// "the mesh bends by more than 80 degrees across 96 edges (8 long in all, up to 90 degrees
// near (x, y, z)): creases, " and what is done with them.
std::string crease_note(const std::string& what, const mesh::SharpEdges& sharp, const std::string& across,
                        const std::string& done) {
  std::ostringstream w;
  w << std::setprecision(3) << what << " by more than " << kTearingBendDeg << " degrees across " << sharp.count << " "
    << across << " (" << sharp.total_length << " long in all, up to " << sharp.max_bend_deg << " degrees near ("
    << sharp.sharpest->x() << ", " << sharp.sharpest->y() << ", " << sharp.sharpest->z() << ")): creases, " << done;
  return w.str();
}

constexpr const char* kRoundedOff = "which fitted normal lines round off (--creases join: joined across by the sheet)";
constexpr const char* kJoined = "left out of the reach estimate and joined across by the sheet";

// Vertices with their area-weighted normal lines, plus face centres with face normals (the
// faces carry the surface between vertices), and the mesh's border loops with frames.
void load_mesh_samples(TriangleMesh mesh, const std::string& spec, bool join_creases, LoadedSurface& out) {
  if (mesh.triangles.empty()) throw InvalidInput(spec + ": the mesh has no faces");
  naming_input(spec, [&] { mesh::check_coordinates(mesh.vertices, "vertex"); });
  out.source = "mesh";
  out.kind.is_builtin = false;
  // Coincident vertices are one point of the surface (the analyzer welds them too): an export
  // that splits vertices along seams (per-face normals or texture coordinates, separate
  // parts) would otherwise read as pieces with false border loops along every seam.
  const std::size_t vertices_used = mesh::used_vertex_count(mesh);
  mesh = mesh::weld_identical_vertices(mesh);
  if (const std::size_t welded = vertices_used - mesh.vertices.size(); welded > 0)
    out.notes.push_back(std::to_string(welded) + " vertices at the coordinates of another welded to it");
  const std::size_t dropped = mesh::remove_duplicate_faces(mesh);
  if (mesh.triangles.empty())
    throw InvalidInput(spec + ": the mesh has no faces but " + std::to_string(dropped) +
                       " that use a vertex twice");  // a repeated face keeps one copy
  if (dropped > 0) out.notes.push_back(std::to_string(dropped) + " repeated or degenerate faces dropped");
  const auto vertex_normals = normals::mesh_vertex_normal_lines(mesh);
  try {
    out.samples.boundary = boundary::mesh_boundary_curves(mesh, vertex_normals);
  } catch (const InvalidInput& e) {
    throw InvalidInput(spec + ": " + e.what() + " (--as-points reads its vertices as a point file)");
  }
  const auto mesh_topology = topology::analyze_topology(mesh);  // a manifold, checked above
  out.kind.is_orientable = mesh_topology.is_orientable;
  out.kind.genus = topology::total_genus(mesh_topology);
  std::vector<bool> used(mesh.vertices.size(), false);
  for (const auto& t : mesh.triangles)
    for (Index v : t) used[v] = true;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!used[v] || vertex_normals[v].squared_length() == 0) continue;
    out.samples.points.push_back(mesh.vertices[v]);
    out.samples.normals.push_back(vertex_normals[v]);
  }
  for (const auto& t : mesh.triangles) {
    const Point3& a = mesh.vertices[t[0]];
    const Point3& b = mesh.vertices[t[1]];
    const Point3& c = mesh.vertices[t[2]];
    const Vector3 n = CGAL::cross_product(b - a, c - a);
    const double len = std::sqrt(n.squared_length());
    if (!(len > 0)) continue;
    out.samples.points.push_back(CGAL::centroid(a, b, c));
    out.samples.normals.push_back(n / len);
  }
  if (out.samples.points.empty()) throw InvalidInput(spec + ": the mesh has no face of positive area");
  out.notes.push_back("mesh vertices and face centres; " + std::to_string(out.samples.boundary.size()) +
                      " border loops");
  // Long sharp creases: rounded off by fitted normal lines (the measurements are in
  // docs/reconstruct.md, sharp creases; normal lines smoothed along the mesh over 1-3 rings
  // of faces instead, summed as oriented vectors, read 2.6-7.9% / 3.6-7.3% on the open box of
  // 12 x 12 grids, each after the adaptive retry, where the fitted ones read 1.1% / 2.0%), or
  // joined by the sheet.
  auto sharp = mesh::sharp_edges(mesh, kTearingBendDeg);
  if (!is_long_crease(sharp, mesh.vertices)) return;
  out.notes.push_back(crease_note("the mesh bends", sharp, "edges", join_creases ? kJoined : kRoundedOff));
  if (join_creases) {
    out.samples.creases = std::move(sharp.segments);
  } else {
    out.samples.normals = fitted_like(out.samples.points, out.samples.normals);
  }
}

// Several patches joined: a known genus (the adaptive retry's bound), and creases where the
// patches meet at an angle (a box of flat faces), handled as a point file's jumping normals are.
void load_model_creases(const models::PatchModel& model, bool join_creases, LoadedSurface& out) {
  out.notes.push_back(model.description());
  out.kind.genus = model.genus();
  auto sharp = mesh::sharp_edges(model.truth(), kTearingBendDeg);
  if (!is_long_crease(sharp, model.truth().vertices)) return;
  out.notes.push_back(crease_note("the patches meet", sharp, "edges", join_creases ? kJoined : kRoundedOff));
  if (join_creases) {
    out.samples.creases = std::move(sharp.segments);
  } else {
    out.samples.normals = fitted_like(out.samples.points, out.samples.normals);
    out.kind.are_normals_estimated = true;
    out.kind.are_signs_given = true;  // the fitted lines face like the patches' normals
  }
}

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

// Six columns whose last three are whole numbers in 0..255 on every line, some above 1:
// colours (x y z r g b, a common export), which read as normals would all point into one
// octant and set every envelope sample wrong.
bool columns_look_like_colours(const std::string& spec, const std::vector<Vector3>& normals) {
  if (normals.empty() || !io::is_text_point_file(spec)) return false;
  bool above_one = false;
  for (const Vector3& n : normals) {
    for (const double c : {n.x(), n.y(), n.z()}) {
      if (!(c >= 0 && c <= 255 && c == std::floor(c))) return false;
      above_one = above_one || c > 1;
    }
  }
  return above_one;
}

// Six columns of colours read as normals become the points' colours.
void normals_to_colours(PointSet& read, PointAttributes& attributes) {
  attributes.colours.clear();
  for (const Vector3& n : read.normals)
    attributes.colours.push_back({static_cast<std::uint8_t>(n.x()), static_cast<std::uint8_t>(n.y()),
                                  static_cast<std::uint8_t>(n.z())});
  read.normals.clear();
}

// The points of a point file as the stages need them: normals scaled to unit length (files
// store them at any length; the envelope offsets by rho times the normal) and a zero one
// refused, and repeated points merged (scans repeat points where views overlap; a copy would
// read as a zero spacing), each keeping its first occurrence's normal and attributes; refused
// with the file's name when fewer than 5 are left or all lie on a line.
AttributedPoints usable_points(AttributedPoints input, const std::string& spec, std::vector<std::string>& notes) {
  PointSet& read = input.points;
  if (columns_look_like_colours(spec, read.normals)) {
    normals_to_colours(read, input.attributes);
    notes.push_back("columns 4-6 are whole numbers in 0..255 on every line: read as colours, not normals");
  } else if (!read.normals.empty() && std::all_of(read.normals.begin(), read.normals.end(),
                                                  [](const Vector3& n) { return n == Vector3(0, 0, 0); })) {
    // Exporters write (0, 0, 0) where they have no normals: none given, not each one zero.
    read.normals.clear();
    notes.push_back("every normal in the file is zero: read as no normals");
  }
  for (std::size_t i = 0; i < read.normals.size(); ++i) {
    const double length = std::sqrt(read.normals[i].squared_length());
    if (!(length > 0) || !std::isfinite(length))
      throw InvalidInput(spec + ": point " + std::to_string(i + 1) + " has a zero normal");
    read.normals[i] = read.normals[i] / length;
  }
  mesh::MergedPoints merged = naming_input(spec, [&] { return mesh::merge_duplicate_points(read.points); });
  AttributedPoints result;
  PointSet& out = result.points;
  out.points = std::move(merged.points);
  if (read.has_normals()) {
    std::vector<char> seen(out.points.size(), 0);
    for (std::size_t i = 0; i < read.points.size(); ++i)
      if (const Index k = merged.input_to_merged[i]; !seen[k]) seen[k] = 1, out.normals.push_back(read.normals[i]);
  }
  if (!input.attributes.empty()) {
    std::vector<std::size_t> first(out.points.size(), read.points.size());  // the input point of each merged one
    for (std::size_t i = read.points.size(); i-- > 0;) first[merged.input_to_merged[i]] = i;
    result.attributes = input.attributes.pick(first);
  }
  if (merged.duplicates > 0) notes.push_back(std::to_string(merged.duplicates) + " duplicate points merged");
  const std::size_t n = out.points.size();
  if (n < 5)
    throw DegenerateInput(spec + ": need at least 5 distinct points, got " + std::to_string(n) +
                          (merged.duplicates > 0 ? " (" + std::to_string(merged.duplicates) + " duplicates merged)" : ""));
  // Within 1e-5 of their size of a line (6 printed significant digits leave a line within
  // about 1.5e-6 of it): a curve.
  const double diagonal = mesh::bbox_diagonal(out.points);
  if (mesh::spread_dimension(out.points, 1e-5 * diagonal) < 2) {
    std::ostringstream s;
    s << std::setprecision(3) << spec << ": all " << n << " points lie on a line (within 1e-5 of their extent, "
      << diagonal << "): no surface to reconstruct";
    throw DegenerateInput(s.str());
  }
  return result;
}

// Samples of M from a point set read from `spec` (a file, or a built-in surface's samples):
// usable points, normal lines from the set or by PCA, and boundary curves given, detected or
// none.
void load_point_samples(AttributedPoints read, const std::string& spec, const BuiltinSampling& sampling,
                        const Progress& progress, LoadedSurface& out) {
  AttributedPoints usable = usable_points(std::move(read), spec, out.notes);
  PointSet& points = usable.points;
  out.source = "points";
  // One neighbour search serves the stray samples, the normal lines and the boundary's
  // angle gaps (each searched its own: at 1M points the passes took 7.4-8.8 s, now 4.9-5.7 s).
  const outliers::OutlierOptions outlier_options;
  const normals::NormalOptions normal_options;
  const bool fits_normals = !points.has_normals();
  const bool detects = sampling.boundary_files.empty() && sampling.detect_boundary;
  unsigned k = 0;
  if (sampling.remove_outliers) k = std::max(k, outlier_options.neighbors);
  if (fits_normals) k = std::max(k, static_cast<unsigned>(normal_options.neighbors));
  if (detects) k = std::max(k, static_cast<unsigned>(std::max(sampling.boundary.neighbors, 6)));
  NeighbourTable table;
  if (k > 0) {
    progress.report("input: neighbours", 0.05);
    table = NeighbourTable(points.points, k);
  }
  if (sampling.remove_outliers) {
    progress.report("input: outliers", 0.1);
    const auto found = outliers::find_outliers(points.points, table, outlier_options);
    if (found.count() > 0) {
      std::vector<char> keep(found.is_outlier.size());
      for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = found.is_outlier[i] ? 0 : 1;
      table = table.subset(points.points, keep);
      PointSet kept;
      std::vector<std::size_t> kept_indices;
      for (std::size_t i = 0; i < points.points.size(); ++i) {
        if (found.is_outlier[i]) {
          out.outliers.push_back(points.points[i]);
          continue;
        }
        kept.points.push_back(points.points[i]);
        kept_indices.push_back(i);
        if (points.has_normals()) kept.normals.push_back(points.normals[i]);
      }
      points = std::move(kept);
      if (!usable.attributes.empty()) usable.attributes = usable.attributes.pick(kept_indices);
      out.notes.push_back(std::to_string(found.count()) + " outliers removed (" + std::to_string(found.off_plane) +
                          " off their neighbours' plane, " + std::to_string(found.isolated) + " isolated)");
    }
  }
  out.kind.is_builtin = false;
  // Normals given with the points may jump across sharp creases (fitted ones turn smoothly
  // and are not read so). Rounded off (the default), fitted normal lines replace the file's
  // all: the envelope of the surface so rounded off is reconstructed closer to the creased
  // surface than its creased envelope is, and with a larger rho. Measured on an open box
  // sampled with exact normals (docs/reconstruct.md, sharp creases), 10,000 points 1.14% /
  // 2.40% of the diagonal instead of 2.25% / 2.46% with the creases joined by the sheet, and
  // 1.94% / 2.40% with fitted normals only near the creases (the seam between them reads as
  // curvature: rho 0.021 instead of 0.027); 40,000 points 0.83% / 1.17% in 75 s instead of
  // 1.62% / 2.06% in 162 s and 0.89% / 1.17% in 228 s.
  if (points.has_normals()) {
    progress.report("input: creases", 0.2);
    normals::PointCreaseOptions o;
    o.min_bend_deg = kTearingBendDeg;
    auto sharp = normals::point_creases(points.points, points.normals, o);
    out.notes.push_back("normal lines from the file");
    if (is_long_crease(sharp, points.points)) {
      if (sampling.join_creases) {
        out.notes.push_back(crease_note("the normals given jump", sharp, "neighbour pairs", kJoined));
        out.samples.creases = std::move(sharp.segments);
      } else {
        out.notes.push_back(crease_note("the normals given jump", sharp, "neighbour pairs", kRoundedOff));
        progress.report("input: normals", 0.3);
        points.normals = fitted_like(points.points, points.normals);
        out.kind.are_normals_estimated = true;
        out.kind.are_signs_given = true;  // the fitted lines face like the file's normals
      }
    }
  } else {
    progress.report("input: normals", 0.3);
    points.normals = normals::estimate_normal_lines(points.points, table, normal_options);
    out.kind.are_normals_estimated = true;
    out.notes.push_back("normal lines estimated by PCA over " + std::to_string(normal_options.neighbors) +
                        " neighbours");
  }
  if (!usable.attributes.empty()) {
    out.attribute_points = points.points;
    out.attributes = std::move(usable.attributes);
  }
  out.samples.points = std::move(points.points);
  out.samples.normals = std::move(points.normals);
  // Too few points for the neighbour queries: say which file.
  try {
    if (!sampling.boundary_files.empty()) {
      const PointSet given = read_boundary_points(sampling.boundary_files);
      std::string names;
      for (const auto& f : sampling.boundary_files) names += (names.empty() ? "" : ", ") + f;
      boundary::BoundaryDetection curves;
      try {
        curves = boundary::boundary_from_points(out.samples.points, out.samples.normals, given, sampling.boundary);
      } catch (const InvalidInput& e) {
        throw InvalidInput(names + ": " + e.what());
      }
      out.notes.push_back("boundary given: " + std::to_string(curves.curves.size()) + " curves from " +
                          std::to_string(given.size()) + " points of " + names);
      out.samples.boundary = std::move(curves.curves);
      for (auto& w : curves.warnings) out.notes.push_back(std::move(w));
    } else if (sampling.detect_boundary) {
      progress.report("input: boundary", 0.6);
      auto detection = boundary::detect_boundary(out.samples.points, out.samples.normals, table, sampling.boundary);
      out.notes.push_back("boundary detected: " + std::to_string(detection.curves.size()) + " curves (" +
                          std::to_string(detection.dropped_loops) + " short loops dropped)");
      out.samples.boundary = std::move(detection.curves);
      out.kind.is_boundary_detected = true;
      detection.curves.clear();
      out.min_loop_width = sampling.boundary.min_loop_width;
      for (const auto& w : detection.warnings) out.notes.push_back(w);
      out.detection = std::move(detection);
    }
  } catch (const DegenerateInput& e) {
    throw DegenerateInput(spec + ": " + e.what());
  }
}

}  // namespace

CLI::Option* add_boundary_options(CLI::App& sub, BuiltinSampling& sampling) {
  auto* given = sub.add_option("--boundary", sampling.boundary_files,
                               "Point files: boundary points to use instead of detecting them (point files in any "
                               "order or closed .polyline curves, repeatable, several loops; each point marks its "
                               "nearest sample; normals, if every file has them, are outward conormals)");
  sub.add_option("--boundary-min-length", sampling.boundary.min_loop_length,
                 "Point files: drop detected loops shorter than this many spacings (chains of false "
                 "candidates around random voids; holes this short are below the envelope's resolution)")
      ->capture_default_str()
      ->check(number_above(0, true));
  sub.add_option("--boundary-min-width", sampling.boundary.min_loop_width,
                 "Point files: drop detected loops narrower than this many local spacings "
                 "(sampling gaps, not holes); 0 keeps all")
      ->capture_default_str()
      ->check(number_above(0, true));
  sub.add_flag("--no-boundary-outer-fit", [&sampling](std::int64_t) { sampling.boundary.fit_to_outer_samples = false; },
               "Point files: leave detected curves on the centre line of the flagged band instead of "
               "moving them out to its outermost samples");
  sub.add_flag("--boundary-take-in",
               [&sampling](std::int64_t) { sampling.boundary.take_in_samples_beyond = true; },
               "Point files: bulge detected curves out past samples still beyond them (lone samples on the "
               "rim beside a void), instead of leaving those outside");
  sub.add_flag("--as-points", sampling.mesh_as_points,
               "Mesh files: read only the vertices its faces use, as a point file (normals estimated, boundary "
               "detected, point-file options apply): for a mesh that is no surface (an edge with 3 faces)");
  sub.add_flag("--no-boundary-inlet-closing",
               [&sampling](std::int64_t) { sampling.boundary.close_narrow_inlets = false; },
               "Point files: keep the narrow inlets that voids beside the rim cut into detected curves");
  sub.add_flag("--boundary-density-steps",
               [&sampling](std::int64_t) { sampling.boundary.drop_density_steps = true; },
               "Point files: drop the detected rim samples beyond which the surface goes on, sampled more "
               "sparsely (the edges of densely sampled parts)");
  sub.add_flag("--boundary-local-spacing",
               [&sampling](std::int64_t) { sampling.boundary.link_in_local_spacing = true; },
               "Point files: link detected rims in their local sample spacing where that is larger than "
               "the average (a part sampled several times more sparsely than the rest)");
  return given;
}

void add_crease_options(CLI::App& sub, BuiltinSampling& sampling) {
  sub.add_option_function<std::string>(
         "--creases", [&sampling](const std::string& mode) { sampling.join_creases = mode == "join"; },
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

void add_outlier_options(CLI::App& sub, BuiltinSampling& sampling) {
  sub.add_flag("--keep-outliers", [&sampling](std::int64_t) { sampling.remove_outliers = false; },
               "Point files: keep the stray samples that are otherwise removed first (points farther from the "
               "plane of their 16 nearest neighbours than half the distance to the farthest of them and 8 times "
               "the residual there, or 4 times farther from them than those are from theirs)");
}

LoadedSurface load_surface(const std::string& spec, const BuiltinSampling& sampling, const Progress& progress) {
  LoadedSurface out;
  if (!sampling.boundary_files.empty() && is_parametric_spec(spec) && !sampling.builtin_as_points)
    throw UsageError("--boundary applies to point files: " + spec + " brings its exact boundary");
  if (sampling.mesh_as_points && is_parametric_spec(spec))
    throw UsageError("--as-points applies to mesh files: " + spec + " is sampled with its exact normals");
  if (is_parametric_spec(spec)) {
    // A NURBS file is read as a built-in surface is (out.kind keeps is_builtin: no scan cuts).
    const auto model = parametric_model(spec, sampling.join);
    surfaces::SampleOptions o;
    o.count = sampling.count;
    o.noise_rel_diag = sampling.noise_rel_diag;
    o.seed = sampling.seed;
    o.with_normals = !sampling.builtin_as_points;
    PointSet points = model->sample(o);
    if (sampling.builtin_as_points) {
      load_point_samples({std::move(points), {}}, spec, sampling, progress, out);
      out.notes.push_back("sampled from " + model->name() + " without its normals and boundary");
      return out;
    }
    out.samples.points = std::move(points.points);
    out.samples.normals = std::move(points.normals);
    out.samples.boundary = model->boundary_curves(0.005 * model->diagonal());
    out.source = is_builtin_spec(spec) ? "builtin" : "nurbs";
    out.notes.push_back("exact normals and boundary curves of " + model->name());
    if (model->patch_count() > 1) load_model_creases(*model, sampling.join_creases, out);
    return out;
  }
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
  if (mesh && sampling.mesh_as_points) {
    PointSet vertices;
    std::vector<bool> used(mesh->vertices.size(), false);
    for (const auto& t : mesh->triangles)
      for (const Index v : t) used[v] = true;
    for (std::size_t v = 0; v < used.size(); ++v)
      if (used[v]) vertices.points.push_back(mesh->vertices[v]);
    const std::size_t count = vertices.points.size();
    load_point_samples({std::move(vertices), {}}, spec, sampling, progress, out);
    out.notes.insert(out.notes.begin(), "the mesh's " + std::to_string(count) + " vertices read as a point file (--as-points)");
    return out;
  }
  if (mesh) {
    if (!sampling.boundary_files.empty())
      throw UsageError("--boundary applies to point files: the mesh " + spec + " brings its border loops");
    load_mesh_samples(std::move(*mesh), spec, sampling.join_creases, out);
    if (ext == "ply" || ext == "obj") {  // a mesh's vertex colours (and a PLY's other properties)
      AttributedPoints vertices = io::read_attributed_points(spec);
      if (!vertices.attributes.empty()) {
        out.attribute_points = std::move(vertices.points.points);
        out.attributes = std::move(vertices.attributes);
      }
    }
    return out;
  }
  if (sampling.mesh_as_points) throw UsageError("--as-points applies to mesh files: " + spec + " has no faces");
  // A point file's steps before the envelope take seconds on a million points.
  progress.report("input: reading", 0.0);
  load_point_samples(io::read_attributed_points(spec), spec, sampling, progress, out);
  progress.report("input", 1.0);
  return out;
}

}  // namespace envcrust::cli
