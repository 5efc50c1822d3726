// One measured reconstruction: sampling, reconstruction, analysis, table cells and panels.
#include "trial.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "envcrust/errors.h"
#include "envcrust/topology.h"

namespace envcrust::experiments::detail {
namespace {

// 20k area samples per side measure the Hausdorff distance to ~0.01% of the diagonal on
// these surfaces; the CLI's 200k cost seconds per analysis and an experiment runs dozens.
constexpr std::size_t kDistanceSamples = 20000;

double percent_of(const distance::DistanceReport& d, double value) { return 100.0 * d.relative(value); }

}  // namespace

SurfaceCase make_case(const std::string& name) {
  SurfaceCase c;
  c.surface = surfaces::make_builtin(name);
  c.expected = c.surface->expected_topology();
  c.diagonal = surfaces::bbox_diagonal(*c.surface);
  c.reference.mesh = surfaces::tessellate(*c.surface);
  for (const auto& curve : surfaces::boundary_curves(*c.surface, 2e-3 * c.diagonal))
    c.reference.boundary.push_back(curve.polyline());
  return c;
}

envelope::SurfaceSamples sample_case(const SurfaceCase& c, std::size_t count, std::uint64_t seed) {
  surfaces::SampleOptions o;
  o.count = count;
  o.seed = seed;
  o.with_normals = true;
  PointSet points = surfaces::sample_surface(*c.surface, o);
  envelope::SurfaceSamples samples;
  samples.points = std::move(points.points);
  samples.normals = std::move(points.normals);
  samples.boundary = surfaces::boundary_curves(*c.surface, 0.005 * c.diagonal);
  return samples;
}

analysis::AnalysisReport analyze(const TriangleMesh& mesh, const analysis::Reference& reference, bool use_distance) {
  analysis::AnalyzeOptions options;
  options.distance.samples = kDistanceSamples;
  if (use_distance && !mesh.triangles.empty()) return analysis::analyze_mesh(mesh, reference, options);
  analysis::Reference topology_only;
  if (!mesh.triangles.empty()) topology_only.boundary = reference.boundary;
  return analysis::analyze_mesh(mesh, topology_only, options);
}

Trial run_trial(const envelope::SurfaceSamples& samples, const pipeline::ReconstructOptions& options,
                const analysis::Reference& reference, const surfaces::ExpectedTopology& expected, bool use_distance,
                const Progress& progress) {
  Trial trial;
  const auto start = std::chrono::steady_clock::now();
  try {
    trial.result = pipeline::reconstruct(samples, options, progress);
  } catch (const DegenerateInput& e) {
    // The direct Power Crust refuses a flat sample (the square): an outcome, not an error.
    trial.result.warnings.push_back(e.what());
  }
  trial.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  trial.report = analyze(trial.result.mesh, reference, use_distance);
  trial.is_topology_correct = has_expected_topology(trial.report, expected);
  return trial;
}

bool has_expected_topology(const analysis::AnalysisReport& report, const surfaces::ExpectedTopology& expected) {
  const auto& t = report.topology;
  if (t.faces == 0 || t.components.size() != 1 || !t.is_manifold()) return false;
  if (t.euler_characteristic != expected.euler_characteristic) return false;
  if (static_cast<int>(t.boundary_loops.size()) != expected.boundary_loops) return false;
  if (t.is_orientable != expected.is_orientable) return false;
  std::vector<std::string> knots;
  for (const auto& loop : report.loops) {
    if (!loop.knot) return false;
    knots.push_back(knots::to_string(loop.knot->type));
  }
  auto wanted = expected.boundary_knots;
  std::sort(knots.begin(), knots.end());
  std::sort(wanted.begin(), wanted.end());
  if (knots != wanted) return false;
  if (expected.boundary_loops >= 2) {
    if (report.linking.empty()) return false;
    if (std::abs(report.linking.front().linking_number) != expected.abs_linking_number) return false;
  }
  return true;
}

std::string knot_list(const analysis::AnalysisReport& report) {
  if (report.loops.empty()) return "-";
  std::vector<std::string> names;
  for (const auto& loop : report.loops) names.push_back(loop.knot ? knots::to_string(loop.knot->type) : "?");
  std::sort(names.begin(), names.end());
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

std::vector<std::string> outcome_columns() {
  return {"topology ok", "χ",    "components",   "loops",        "orientable", "manifold",
          "knots",       "|lk|", "mesh→truth %", "truth→mesh %", "boundary %", "seconds"};
}

Table outcome_table(std::string title, std::vector<std::string> head) {
  Table table;
  table.title = std::move(title);
  table.columns = std::move(head);
  for (auto& column : outcome_columns()) table.columns.push_back(std::move(column));
  return table;
}

std::vector<Cell> outcome_cells(const analysis::AnalysisReport& report, bool is_topology_correct, double seconds) {
  const auto& t = report.topology;
  std::vector<Cell> row;
  row.emplace_back(is_topology_correct);
  row.emplace_back(std::int64_t{t.euler_characteristic});
  row.emplace_back(static_cast<std::int64_t>(t.components.size()));
  row.emplace_back(static_cast<std::int64_t>(t.boundary_loops.size()));
  row.emplace_back(t.is_orientable);
  row.emplace_back(t.is_manifold());
  row.emplace_back(knot_list(report));
  if (report.linking.empty())
    row.emplace_back(std::monostate{});
  else
    row.emplace_back(std::int64_t{std::abs(report.linking.front().linking_number)});
  if (report.distance) {
    const auto& d = *report.distance;
    row.emplace_back(percent_of(d, d.mesh_to_reference.max));
    row.emplace_back(percent_of(d, d.reference_to_mesh.max));
  } else {
    row.emplace_back(std::monostate{});
    row.emplace_back(std::monostate{});
  }
  // Worst true boundary loop against its reconstructed loop; unset when a loop has no match.
  std::optional<double> boundary;
  for (const auto& match : report.boundary_matches) {
    if (!match.mesh_loop || !report.distance) {
      boundary.reset();
      break;
    }
    boundary = std::max(boundary.value_or(0.0), percent_of(*report.distance, match.hausdorff));
  }
  if (boundary)
    row.emplace_back(*boundary);
  else
    row.emplace_back(std::monostate{});
  row.emplace_back(seconds);
  return row;
}

std::vector<Cell> trial_row(std::vector<Cell> head, const Trial& trial) {
  auto cells = outcome_cells(trial.report, trial.is_topology_correct, trial.seconds);
  head.insert(head.end(), cells.begin(), cells.end());
  return head;
}

pipeline::ReconstructOptions method_options(pipeline::Method method, std::uint64_t seed) {
  pipeline::ReconstructOptions options;
  options.method = method;
  options.envelope.seed = seed;
  return options;
}

std::string method_name(pipeline::Method method) {
  return method == pipeline::Method::Envelope ? "envelope" : "direct Power Crust";
}

PanelSpec mesh_panel(std::string caption, const TriangleMesh& mesh, const render::View& view, bool show_boundary) {
  PanelSpec panel;
  panel.caption = std::move(caption);
  panel.view = view;
  if (mesh.triangles.empty()) return panel;
  render::MeshLayer layer;
  layer.mesh = mesh;  // front and back are coloured apart: wind each piece one way
  topology::orient_faces(layer.mesh);
  panel.scene.meshes.push_back(std::move(layer));
  if (show_boundary) {
    const auto topology = topology::analyze_topology(mesh);
    render::CurveLayer curves;
    for (const auto& loop : topology.boundary_loops) curves.loops.push_back(loop.polyline(topology.points));
    if (!curves.loops.empty()) panel.scene.curves.push_back(std::move(curves));
  }
  return panel;
}

PanelSpec points_panel(std::string caption, const std::vector<Point3>& points, const render::View& view,
                       render::Color color) {
  PanelSpec panel;
  panel.caption = std::move(caption);
  panel.view = view;
  render::SphereLayer layer;
  layer.centres = points;
  layer.color = color;
  panel.scene.spheres.push_back(std::move(layer));
  return panel;
}

std::string outcome_caption(const analysis::AnalysisReport& report, bool is_knotted) {
  const auto& t = report.topology;
  if (t.faces == 0) return "empty";
  std::string s =
      "χ " + std::to_string(t.euler_characteristic) + ", " + std::to_string(t.boundary_loops.size()) + " loops";
  if (t.components.size() != 1) s += ", " + std::to_string(t.components.size()) + " parts";
  if (is_knotted) {
    std::size_t knotted = 0;
    for (const auto& loop : report.loops) knotted += loop.knot && loop.knot->type != knots::KnotType::Unknot;
    if (knotted > 0) s += ", " + std::to_string(knotted) + " knotted";
  }
  if (!t.is_manifold()) s += ", non-manifold";
  std::size_t untyped = 0;
  for (const auto& loop : report.loops) untyped += !loop.knot;
  if (untyped > 0) s += ", " + std::to_string(untyped) + " loops untyped";
  return s;
}

void step(const ExperimentOptions& options, std::string_view name, double fraction) {
  if (options.progress.is_cancelled()) throw Error("experiment " + std::string(name) + " cancelled");
  options.progress.report(name, fraction);
}

}  // namespace envcrust::experiments::detail
