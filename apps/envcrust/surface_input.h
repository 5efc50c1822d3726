// Turning a reconstruct/envelope INPUT argument into samples of M (points, normal lines,
// boundary curves): a built-in surface, a point file, or a triangle mesh.
#pragma once

#include "envcrust/attributes.h"
#include "envcrust/boundary.h"
#include "envcrust/envelope.h"
#include "envcrust/models.h"
#include "envcrust/pipeline.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::cli {

/// How builtin:NAME inputs are sampled.
struct BuiltinSampling {
  std::size_t count = 10000;
  double noise_rel_diag = 0.0;
  std::uint64_t seed = 1;
  bool detect_boundary = true;   ///< point files: find boundary curves (off: treat as closed)
  /// builtin:NAME is sampled without its normals and boundary and then read as a point file
  /// is (normal lines by PCA, boundary detected): what `envcrust boundary` measures.
  bool builtin_as_points = false;
  /// Mesh files: only the vertices the faces use, read as a point file is (normals estimated,
  /// boundary detected): for meshes that are no surface (`--as-points`).
  bool mesh_as_points = false;
  /// Point files: boundary points given instead of detected, from point files or closed
  /// `.polyline` curves (all files together).
  std::vector<std::string> boundary_files;
  boundary::BoundaryOptions boundary;  ///< point files: options of the boundary detector
  /// Point files: drop the stray samples outliers::find_outliers flags before anything else.
  bool remove_outliers = true;
  /// Meshes bent, and point files whose normals jump, by more than 80 degrees along creases
  /// longer in all than a tenth of the diagonal: false (`--creases round`) replaces the
  /// normals by fitted normal lines, which round the creases off; true (`--creases join`)
  /// keeps them and hands the creases to the envelope and the sheet (SurfaceSamples::creases).
  bool join_creases = false;
  /// NURBS files of several patches: how the patches are joined (--join-tolerance).
  models::JoinOptions join;
};

/// Samples of M and how they were obtained (for the report). Point files get their normal
/// lines from the file or by PCA, and their boundary curves by the angle-gap detector; meshes
/// give vertex and face-centre samples, area-weighted normal lines and their border loops.
struct LoadedSurface {
  envelope::SurfaceSamples samples;
  std::string source;                 ///< "builtin", "nurbs", "points", "mesh"
  /// What reconstruct's defaults depend on (pipeline::options_for_input): built-in or not,
  /// normals estimated by PCA, and a mesh's own orientability and genus (handles and
  /// cross-caps summed over components; the envelope should not add any).
  pipeline::InputKind kind;
  /// Point files whose boundary was detected: what the detector found besides the curves
  /// (moved into samples.boundary): flagged points, widths, dropped loops, its spacing.
  std::optional<boundary::BoundaryDetection> detection;
  double min_loop_width = 0.0;  ///< the --boundary-min-width the detection used
  std::vector<std::string> notes;     ///< e.g. "normals estimated (PCA, k 16)"
  /// What the input makes the reconstruction likely to get wrong (a mesh's sharp creases).
  std::vector<std::string> warnings;
  /// Point files: the stray samples removed (see BuiltinSampling::remove_outliers).
  std::vector<Point3> outliers;
  /// Colours and scalars of the input's points (point files: the samples kept; PLY meshes:
  /// the vertices), at `attribute_points`, for the output's vertices (nearest point's).
  std::vector<Point3> attribute_points;
  PointAttributes attributes;
};

/// Add the point-file boundary flags shared by reconstruct, envelope and boundary: --boundary,
/// --boundary-min-width, --no-boundary-outer-fit. Returns the --boundary option.
CLI::Option* add_boundary_options(CLI::App& command, BuiltinSampling& sampling);

/// `--creases round|join` (BuiltinSampling::join_creases).
void add_crease_options(CLI::App& command, BuiltinSampling& sampling);

/// `--join-tolerance` (models::JoinOptions::tolerance_rel_diag) into `join`.
void add_join_option(CLI::App& command, models::JoinOptions& join);

/// Add --keep-outliers (point files: keep the samples find_outliers flags).
void add_outlier_options(CLI::App& command, BuiltinSampling& sampling);

LoadedSurface load_surface(const std::string& spec, const BuiltinSampling& sampling, const Progress& progress = {});

}  // namespace envcrust::cli
