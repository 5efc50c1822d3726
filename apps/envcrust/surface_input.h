// Turning a reconstruct/envelope INPUT argument into samples of M (points, normal lines,
// boundary curves): a built-in surface, a point file, or a triangle mesh, read here and
// prepared by the library's input stage (envcrust/input.h).
#pragma once

#include "envcrust/input.h"
#include "envcrust/models.h"
#include "envcrust/progress.h"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::cli {

/// The input settings of the commands: the library's input::InputOptions (bound to the
/// point-file, outlier and crease flags) and what only the CLI does: sample builtin:NAME and
/// NURBS inputs, read --boundary files, read a mesh's vertices as points.
struct InputSettings {
  std::size_t count = 10000;
  double noise_rel_diag = 0.0;
  std::uint64_t seed = 1;
  /// builtin:NAME is sampled without its normals and boundary and then read as a point file
  /// is (normal lines by PCA, boundary detected): what `envcrust boundary` measures.
  bool builtin_as_points = false;
  /// Mesh files: only the vertices the faces use, read as a point file is (normals estimated,
  /// boundary detected): for meshes that are no surface (`--as-points`).
  bool mesh_as_points = false;
  /// Point files: boundary points given instead of detected, from point files or closed
  /// `.polyline` curves (all files together).
  std::vector<std::string> boundary_files;
  /// NURBS files of several patches: how the patches are joined (--join-tolerance).
  models::JoinOptions join;
  /// Outliers, boundary detection, creases (input::prepare_points, prepare_mesh, prepare_model);
  /// its `name` is set to the input argument when it is loaded.
  input::InputOptions preparation;
};

/// Samples of M and how they were obtained (input::PreparedInput), with what only the report
/// shows: where they came from and the --boundary-min-width of a detection.
struct LoadedSurface : input::PreparedInput {
  std::string source;           ///< "builtin", "nurbs", "points", "mesh"
  double min_loop_width = 0.0;  ///< the --boundary-min-width the detection used
};

/// Add the point-file boundary flags shared by reconstruct, envelope and boundary: --boundary,
/// --boundary-min-width, --no-boundary-outer-fit. Returns the --boundary option.
CLI::Option* add_boundary_options(CLI::App& command, InputSettings& sampling);

/// `--creases round|join` (input::InputOptions::creases).
void add_crease_options(CLI::App& command, InputSettings& sampling);

/// `--join-tolerance` (models::JoinOptions::tolerance_rel_diag) into `join`.
void add_join_option(CLI::App& command, models::JoinOptions& join);

/// `--classes LIST` (input::InputOptions::classes): keep only the points of these classes.
void add_classes_option(CLI::App& command, InputSettings& sampling);

/// Add --keep-outliers (point files: keep the samples find_outliers flags).
void add_outlier_options(CLI::App& command, InputSettings& sampling);

LoadedSurface load_surface(const std::string& spec, const InputSettings& sampling, const Progress& progress = {});

}  // namespace envcrust::cli
