// Figure 8: the non-C2 cap y = |x|^(3/2): where the envelope's artifacts appear. The envelope
// stops being C^{1,1} where a principal radius (2/3) sqrt(r) falls below rho, i.e. within
// r < 2.25 rho^2 of the apex (docs/method.md §3.1); the error is measured per distance to the apex,
// and the close-ups are coloured by it.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "envcrust/distance.h"
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {
namespace {

std::string bin_label(double lo, double hi) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g ≤ d < %g", lo, hi);
  return buffer;
}

// The mesh's triangles with a vertex within `radius` of the origin (the apex), for close-ups.
TriangleMesh near_apex(const TriangleMesh& mesh, double radius) {
  TriangleMesh out;
  out.vertices = mesh.vertices;
  const Point3 apex(0, 0, 0);
  for (const auto& t : mesh.triangles)
    for (Index v : t)
      if (CGAL::squared_distance(mesh.vertices[v], apex) < radius * radius) {
        out.triangles.push_back(t);
        break;
      }
  return out;
}

}  // namespace

ExperimentResult run_cusp(const ExperimentOptions& options) {
  ExperimentResult out;
  const std::size_t count = options.use_quick_sizes ? 3000 : 10000;
  const std::vector<double> rhos =
      options.use_quick_sizes ? std::vector<double>{0.07, 0.1} : std::vector<double>{0.02, 0.05, 0.1};
  const std::vector<double> edges = {0, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 2.0};
  const SurfaceCase cusp = make_case("cusp");
  const auto samples = sample_case(cusp, count, options.seed);

  Table summary = outcome_table(
      "Cusp cap y = |x|^(3/2) (a disk, C¹ at the apex) and the paper's horn (C^∞), N " + std::to_string(count),
      {"surface", "ρ", "predicted artifact radius 2.25ρ²", "farthest d with error > ρ/32",
       "max vertex error % (d < 0.1)", "max vertex error % (d ≥ 0.1)"});
  Table profile;
  profile.title =
      "Cusp: largest vertex distance to the exact surface (% of the diagonal) against the distance d "
      "to the apex";
  profile.columns = {"ρ"};
  for (std::size_t b = 0; b + 1 < edges.size(); ++b) profile.columns.push_back(bin_label(edges[b], edges[b + 1]));
  Figure figure{"fig8_cusp", "", 0, {}};
  std::vector<std::vector<double>> panel_errors;  // per cusp panel, per vertex

  for (std::size_t i = 0; i < rhos.size(); ++i) {
    step(options, "cusp", static_cast<double>(i) / (rhos.size() + 1));
    auto ro = method_options(pipeline::Method::Envelope, options.seed);
    ro.envelope.rho = rhos[i];
    const Trial trial = run_trial(samples, ro, cusp.reference, cusp.expected);
    const auto& mesh = trial.result.mesh;
    const auto errors = distance::distances_to_mesh(mesh.vertices, *cusp.reference.mesh);
    std::vector<double> bin_max(edges.size() - 1, -1.0);
    double near_max = 0, far_max = 0, artifact_radius = 0;
    // An artifact is a vertex farther from M than twice the sheet error bound rho/64 (F4).
    const double threshold = rhos[i] / 32;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      const double d = std::sqrt(CGAL::squared_distance(mesh.vertices[v], Point3(0, 0, 0)));
      const double e = 100.0 * errors[v] / cusp.diagonal;
      for (std::size_t b = 0; b + 1 < edges.size(); ++b)
        if (d >= edges[b] && d < edges[b + 1]) bin_max[b] = std::max(bin_max[b], e);
      (d < 0.1 ? near_max : far_max) = std::max(d < 0.1 ? near_max : far_max, e);
      if (errors[v] > threshold) artifact_radius = std::max(artifact_radius, d);
    }
    const bool is_empty = mesh.triangles.empty();
    summary.add_row(
        trial_row({std::string("cusp"), rhos[i], 2.25 * rhos[i] * rhos[i], is_empty ? Cell{} : Cell{artifact_radius},
                   is_empty ? Cell{} : Cell{near_max}, is_empty ? Cell{} : Cell{far_max}},
                  trial));
    std::vector<Cell> row = {rhos[i]};
    for (double m : bin_max) row.push_back(m < 0 ? Cell{} : Cell{m});
    profile.add_row(std::move(row));
    if (options.use_figures && !is_empty) {
      figure.panels.push_back(mesh_panel("ρ " + format_cell(rhos[i]) + ": " + outcome_caption(trial.report),
                                         near_apex(mesh, 0.3), render::View{-60.0, -35.0}, false));
      panel_errors.push_back(errors);
    }
  }
  // One colour scale for every close-up: red at the largest vertex error of them all.
  double red_at = 0;
  for (const auto& errors : panel_errors)
    for (const double e : errors) red_at = std::max(red_at, e);
  for (std::size_t p = 0; p < panel_errors.size(); ++p) {
    auto& colors = figure.panels[p].scene.meshes.front().vertex_colors;
    for (const double e : panel_errors[p]) colors.push_back(render::heat_color(red_at > 0 ? e / red_at : 0.0));
  }
  char scale[160];
  std::snprintf(scale, sizeof scale, "coloured by distance to the exact surface (blue 0, red %.2g%% of the diagonal)",
                100.0 * red_at / cusp.diagonal);
  figure.title = "Cusp apex close-ups (d < 0.3) at increasing ρ, " + std::string(scale) + "; horn for comparison";
  out.notes.push_back(
      "d: distance of a vertex of the result from the apex; ρ/32 is twice the sheet error bound "
      "of docs/method.md §2.4, so an error beyond it is an artifact");

  // The horn the paper printed (y = x^(-3/2) revolved) is smooth: no apex, no artifact.
  step(options, "cusp", static_cast<double>(rhos.size()) / (rhos.size() + 1));
  const SurfaceCase horn = make_case("horn");
  const Trial trial =
      run_trial(sample_case(horn, count, options.seed), method_options(pipeline::Method::Envelope, options.seed),
                horn.reference, horn.expected);
  summary.add_row(trial_row({std::string("horn"), trial.result.envelope.rho, Cell{}, Cell{}, Cell{}, Cell{}}, trial));
  if (options.use_figures)
    figure.panels.push_back(
        mesh_panel("horn: " + outcome_caption(trial.report), trial.result.mesh, render::View::iso()));
  out.tables.push_back(std::move(summary));
  out.tables.push_back(std::move(profile));
  if (options.use_figures) out.figures.push_back(std::move(figure));
  return out;
}

}  // namespace envcrust::experiments::detail
