// One measured reconstruction of an experiment: sample a built-in surface, reconstruct it,
// analyze the result against the exact surface, and turn the outcome into table cells.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "envcrust/analysis.h"
#include "envcrust/experiments.h"
#include "envcrust/pipeline.h"
#include "envcrust/surfaces.h"

namespace envcrust::experiments::detail {

/// A built-in surface with its ground truth (fine tessellation and boundary loops).
struct SurfaceCase {
  std::unique_ptr<surfaces::Surface> surface;
  analysis::Reference reference;
  surfaces::ExpectedTopology expected;
  double diagonal = 0.0;
};

/// The surface by name with its reference, as the CLI's builtin: references are built.
SurfaceCase make_case(const std::string& name);

/// `count` exact samples with normal lines and the exact boundary curves (vertex spacing
/// 0.5% of the diagonal, as `reconstruct builtin:NAME` does).
envelope::SurfaceSamples sample_case(const SurfaceCase& c, std::size_t count, std::uint64_t seed);

/// A reconstruction and its analysis.
struct Trial {
  pipeline::ReconstructResult result;
  analysis::AnalysisReport report;
  bool is_topology_correct = false;
  double seconds = 0.0;  ///< reconstruction only
};

/// Reconstruct and analyze. `use_distance` off skips the distance measurement (topology only).
/// An empty reconstruction is analyzed as such (no distances); so is an input the method
/// refuses as degenerate (DegenerateInput: its message goes into the result's warnings).
Trial run_trial(const envelope::SurfaceSamples& samples, const pipeline::ReconstructOptions& options,
                const analysis::Reference& reference, const surfaces::ExpectedTopology& expected,
                bool use_distance = true, const Progress& progress = {});

/// Analyze a mesh against the reference (cheaper distance sampling than the CLI's).
analysis::AnalysisReport analyze(const TriangleMesh& mesh, const analysis::Reference& reference,
                                 bool use_distance = true);

/// Does the report show the expected topology: one component, manifold, chi, loops,
/// orientability, the knot types (as a multiset) and |lk|?
bool has_expected_topology(const analysis::AnalysisReport& report, const surfaces::ExpectedTopology& expected);

/// "trefoil,trefoil" (sorted), "-" without loops, "?" for an unanalyzed loop.
std::string knot_list(const analysis::AnalysisReport& report);

/// Columns of outcome_cells, in order.
std::vector<std::string> outcome_columns();

/// topology ok, chi, components, loops, orientable, manifold, knots, |lk|, mesh->truth %,
/// truth->mesh %, boundary % (worst true loop to its reconstructed loop), seconds.
std::vector<Cell> outcome_cells(const analysis::AnalysisReport& report, bool is_topology_correct, double seconds);

/// `head` followed by outcome_cells of the trial.
std::vector<Cell> trial_row(std::vector<Cell> head, const Trial& trial);

/// Envelope or direct Power Crust options with the experiment's seed.
pipeline::ReconstructOptions method_options(pipeline::Method method, std::uint64_t seed);

/// "envelope" / "direct Power Crust".
std::string method_name(pipeline::Method method);

/// The knot ribbons seen from above at a slant: their strips (along z) show as bands.
inline render::View ribbon_view() { return {-60.0, 40.0}; }

/// A table whose columns are `head` followed by outcome_columns().
Table outcome_table(std::string title, std::vector<std::string> head);

/// A panel showing a mesh (front/back colours) with optional boundary loops of the mesh.
PanelSpec mesh_panel(std::string caption, const TriangleMesh& mesh, const render::View& view,
                     bool show_boundary = true);

/// A panel showing points as small spheres.
PanelSpec points_panel(std::string caption, const std::vector<Point3>& points, const render::View& view,
                       render::Color color = {0.20f, 0.45f, 0.80f});

/// Short caption of a trial: "χ 0, 2 loops" (+ ", 2 knotted" with `is_knotted`; loops the
/// analyzer could not type are counted: ", 1 loops untyped").
std::string outcome_caption(const analysis::AnalysisReport& report, bool is_knotted = false);

/// Report progress and honour cancellation between steps.
/// @throws Error "experiment NAME cancelled".
void step(const ExperimentOptions& options, std::string_view name, double fraction);

}  // namespace envcrust::experiments::detail
