// The paper's experiments (Figures 1-11) and our own, reproducible: each returns measured
// tables and figure scenes; the CLI writes results.json, results.md and the PNG panels.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "envcrust/progress.h"
#include "envcrust/render.h"
#include "envcrust/types.h"

namespace envcrust::experiments {

/// One table cell: empty, yes/no, integer, number or text.
using Cell = std::variant<std::monostate, bool, std::int64_t, double, std::string>;

/// A table of measurements: column names and rows of cells (one cell per column).
struct Table {
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<Cell>> rows;
  /// @throws InvalidInput when the row has a different number of cells than `columns`.
  void add_row(std::vector<Cell> row);
  /// Index of a named column. @throws InvalidInput naming the column when absent.
  [[nodiscard]] std::size_t column(std::string_view name) const;
};

/// A cell as text: "yes"/"no", integers as is, numbers with 3 significant digits, "-" empty.
std::string format_cell(const Cell& cell);

/// One panel of a figure: what to draw, from where, and its caption.
struct PanelSpec {
  std::string caption;
  render::Scene scene;
  render::View view{};
};

/// A figure: panels laid out in a grid, written as `<name>.png`.
struct Figure {
  std::string name;   ///< file stem, e.g. "fig1_trefoil"
  std::string title;  ///< drawn above the grid
  int columns = 0;    ///< 0: one row
  std::vector<PanelSpec> panels;
};

/// A real scan for the `scan` experiment (read by the caller: the library does no I/O).
struct ScanData {
  std::string name;                       ///< e.g. "foot_vhacd"
  PointSet points;                        ///< positions; normals optional (estimated if absent)
  std::optional<TriangleMesh> reference;  ///< ground-truth mesh, if the data set has one
};

/// Options shared by every experiment.
struct ExperimentOptions {
  /// Small sizes (tests): each experiment then runs in seconds and keeps its qualitative
  /// outcome; the default sizes reproduce the figures (`experiment all` < 10 min, 2 cores).
  bool use_quick_sizes = false;
  std::uint64_t seed = 1;        ///< seed of every sampling and perturbation
  bool use_figures = true;       ///< build the figure scenes (off: tables only)
  std::optional<ScanData> scan;  ///< nullopt: the scan experiment is skipped with a note
  Progress progress;             ///< reported as (experiment name, fraction)
};

/// What an experiment measured.
struct ExperimentResult {
  std::string name;
  std::string description;
  std::vector<Table> tables;
  std::vector<Figure> figures;
  std::vector<std::string> notes;  ///< findings and warnings, one sentence each
  bool is_skipped = false;         ///< missing input (the notes say why)
  double seconds = 0.0;            ///< wall time of the run
};

/// A registered experiment.
struct Experiment {
  std::string name;           ///< "trefoil", "cylinder", ...
  std::string paper_figures;  ///< "Figures 1, 2"; "" beyond the paper
  std::string description;
  std::function<ExperimentResult(const ExperimentOptions&)> run;
};

/// Every experiment, in the paper's figure order.
const std::vector<Experiment>& experiment_list();

/// Run one experiment by name.
/// @throws InvalidOptions "unknown experiment 'x' (known: trefoil, ...)".
ExperimentResult run_experiment(std::string_view name, const ExperimentOptions& options = {});

/// The result as Markdown: a heading, each table, the notes (no figures).
std::string to_markdown(const ExperimentResult& result);

/// Size of each rendered panel.
struct FigureRenderOptions {
  int panel_width = 320;   ///< pixels, [16, 8192]
  int panel_height = 240;  ///< pixels, [16, 8192]
  int supersampling = 2;   ///< render::RenderOptions::supersampling
};

/// Render a figure's panels and lay them out with captions (captions need `font`).
/// @throws InvalidInput / InvalidOptions from render_scene and compose_grid.
render::Image render_figure(const Figure& figure, const FigureRenderOptions& options,
                            const std::optional<render::Font>& font);

}  // namespace envcrust::experiments
