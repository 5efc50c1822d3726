// Samples of M from a point set: stray samples, normal lines, creases, boundary curves.
#include "creases.h"
#include "input_names.h"
#include "local_origin.h"
#include "point_classes.h"
#include "usable_points.h"

#include "envcrust/input.h"
#include "envcrust/mesh.h"
#include "envcrust/neighbour_table.h"
#include "envcrust/normals.h"
#include "envcrust/outliers.h"

#include <algorithm>
#include <utility>

namespace envcrust::input {
namespace {

// The stray samples find_outliers flags moved from `points` (and their attributes and the
// neighbour table) to out.outliers.
void remove_outliers(PointSet& points, PointAttributes& attributes, NeighbourTable& table,
                     const outliers::OutlierOptions& options, PreparedInput& out) {
  const auto found = outliers::find_outliers(points.points, table, options);
  if (found.count() == 0) return;
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
  if (!attributes.empty()) attributes = attributes.pick(kept_indices);
  out.notes.push_back(std::to_string(found.count()) + " outliers removed (" + std::to_string(found.off_plane) +
                      " off their neighbours' plane, " + std::to_string(found.isolated) + " isolated)");
}

// Normals given with the points may jump across sharp creases (fitted ones turn smoothly
// and are not read so). Rounded off (the default), fitted normal lines replace the given ones
// all: the envelope of the surface so rounded off is reconstructed closer to the creased
// surface than its creased envelope is, and with a larger rho. Measured on an open box
// sampled with exact normals (docs/reconstruct.md, sharp creases), 10,000 points 1.14% /
// 2.40% of the diagonal instead of 2.25% / 2.46% with the creases joined by the sheet, and
// 1.94% / 2.40% with fitted normals only near the creases (the seam between them reads as
// curvature: rho 0.021 instead of 0.027); 40,000 points 0.83% / 1.17% in 75 s instead of
// 1.62% / 2.06% in 162 s and 0.89% / 1.17% in 228 s.
void handle_given_normals(PointSet& points, CreaseMode mode, const Progress& progress, PreparedInput& out) {
  progress.report("input: creases", 0.2);
  normals::PointCreaseOptions o;
  o.min_bend_deg = kTearingBendDeg;
  auto sharp = normals::point_creases(points.points, points.normals, o);
  out.notes.push_back("normal lines from the file");
  if (!is_long_crease(sharp, points.points)) return;
  out.notes.push_back(crease_note("the normals given jump", sharp, "neighbour pairs", mode));
  if (mode == CreaseMode::Join) {
    out.samples.creases = std::move(sharp.segments);
    return;
  }
  progress.report("input: normals", 0.3);
  points.normals = fitted_like(points.points, points.normals);
  out.kind.are_normals_estimated = true;
  out.kind.are_signs_given = true;  // the fitted lines face like the given normals
}

// Boundary curves through the given points' nearest samples.
void use_given_boundary(const GivenBoundary& given, const InputOptions& options, PreparedInput& out) {
  boundary::BoundaryDetection curves;
  try {
    curves = boundary::boundary_from_points(out.samples.points, out.samples.normals, given.points, options.boundary);
  } catch (const InvalidInput& e) {
    throw InvalidInput(named(given.name, e.what()));
  }
  const std::string of = given.name.empty() ? "" : " of " + given.name;
  out.notes.push_back("boundary given: " + std::to_string(curves.curves.size()) + " curves from " +
                      std::to_string(given.points.size()) + " points" + of);
  out.samples.boundary = std::move(curves.curves);
  for (auto& w : curves.warnings) out.notes.push_back(std::move(w));
}

void detect_boundary(const NeighbourTable& table, const InputOptions& options, const Progress& progress,
                     PreparedInput& out) {
  progress.report("input: boundary", 0.6);
  auto detection = boundary::detect_boundary(out.samples.points, out.samples.normals, table, options.boundary);
  out.notes.push_back("boundary detected: " + std::to_string(detection.curves.size()) + " curves (" +
                      std::to_string(detection.dropped_loops) + " short loops dropped)");
  out.samples.boundary = std::move(detection.curves);
  out.kind.is_boundary_detected = true;
  detection.curves.clear();
  for (const auto& w : detection.warnings) out.notes.push_back(w);
  out.detection = std::move(detection);
}

}  // namespace

PreparedInput prepare_points(PointInput input, const InputOptions& options, const Progress& progress) {
  PreparedInput out;
  keep_classes(input.points, options.classes, options.name, out.notes);
  // The digits a far input kept are those of its own coordinates: checked before the move
  // to a local origin, which cannot bring back what the file's doubles rounded away.
  naming(options.name, [&] { mesh::check_coordinates(input.points.points.points); });
  if (options.use_local_origin) {
    out.origin = local_origin(input.points.points.points);
    if (out.origin != CGAL::NULL_VECTOR) {
      out.notes.push_back(origin_note(input.points.points.points, out.origin));
      subtract_origin(input.points.points.points, out.origin);
      if (input.given_boundary) subtract_origin(input.given_boundary->points.points, out.origin);
    }
  }
  AttributedPoints usable =
      usable_points(std::move(input.points), input.are_normals_text_columns, options.name, out.notes);
  PointSet& points = usable.points;
  // One neighbour search serves the stray samples, the normal lines and the boundary's
  // angle gaps (each searched its own: at 1M points the passes took 7.4-8.8 s, now 4.9-5.7 s).
  const outliers::OutlierOptions outlier_options;
  const normals::NormalOptions normal_options;
  const bool fits_normals = !points.has_normals();
  const bool detects = !input.given_boundary && options.use_boundary_detection;
  unsigned k = 0;
  if (options.use_outlier_removal) k = std::max(k, outlier_options.neighbors);
  if (fits_normals) k = std::max(k, static_cast<unsigned>(normal_options.neighbors));
  if (detects) k = std::max(k, static_cast<unsigned>(std::max(options.boundary.neighbors, 6)));
  NeighbourTable table;
  if (k > 0) {
    progress.report("input: neighbours", 0.05);
    table = NeighbourTable(points.points, k);
  }
  if (options.use_outlier_removal) {
    progress.report("input: outliers", 0.1);
    remove_outliers(points, usable.attributes, table, outlier_options, out);
  }
  out.kind.is_builtin = false;
  if (points.has_normals()) {
    handle_given_normals(points, options.creases, progress, out);
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
  // Too few points for the neighbour queries: say which input.
  try {
    if (input.given_boundary) {
      use_given_boundary(*input.given_boundary, options, out);
    } else if (options.use_boundary_detection) {
      detect_boundary(table, options, progress, out);
    }
  } catch (const DegenerateInput& e) {
    throw DegenerateInput(named(options.name, e.what()));
  }
  return out;
}

}  // namespace envcrust::input
