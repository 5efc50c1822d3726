// Figures 3, 4: the open NURBS cylinder stage by stage, and direct against envelope result.
#include <cmath>
#include <numbers>

#include "envcrust/normals.h"
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {
namespace {

// The envelope's generating pieces at the tessellation's vertices: sheet offsets p +- rho n
// and, at boundary vertices, half-circles b + rho (cos t n + sin t c) (docs/method.md §2.1).
std::vector<Point3> offset_points(const TriangleMesh& grid, const std::vector<BoundaryCurve>& boundary, double rho) {
  std::vector<Point3> points;
  const auto normals = normals::mesh_vertex_normal_lines(grid);
  for (std::size_t v = 0; v < grid.vertices.size(); ++v) {
    points.push_back(grid.vertices[v] + rho * normals[v]);
    points.push_back(grid.vertices[v] - rho * normals[v]);
  }
  constexpr int kRimSteps = 8;
  for (const auto& curve : boundary)
    for (const auto& b : curve.vertices)
      for (int k = 1; k < kRimSteps; ++k) {
        const double theta = std::numbers::pi * k / kRimSteps;
        points.push_back(b.position + rho * (std::cos(theta) * b.normal + std::sin(theta) * b.conormal));
      }
  return points;
}

}  // namespace

ExperimentResult run_cylinder(const ExperimentOptions& options) {
  ExperimentResult out;
  const std::size_t count = options.use_quick_sizes ? 3000 : 5000;
  const SurfaceCase c = make_case("cylinder-nurbs");
  const auto samples = sample_case(c, count, options.seed);
  Table table = outcome_table("Open NURBS cylinder (χ 0, two unknotted loops), N " + std::to_string(count),
                              {"method", "ρ", "envelope samples"});
  std::vector<PanelSpec> results;
  double rho = 0;
  std::vector<Point3> envelope_points;
  for (const auto method : {pipeline::Method::PowerCrust, pipeline::Method::Envelope}) {
    step(options, "cylinder", method == pipeline::Method::PowerCrust ? 0.0 : 0.5);
    const Trial trial = run_trial(samples, method_options(method, options.seed), c.reference, c.expected);
    const bool is_envelope = method == pipeline::Method::Envelope;
    if (is_envelope) {
      rho = trial.result.envelope.rho;
      envelope_points = trial.result.envelope.points();
    }
    table.add_row(trial_row({method_name(method), is_envelope ? Cell{rho} : Cell{},
                             is_envelope ? Cell{static_cast<std::int64_t>(envelope_points.size())} : Cell{}},
                            trial));
    const auto& t = trial.report.topology;
    out.notes.push_back(method_name(method) + ": " + std::to_string(t.boundary_loops.size()) + " boundary loops, χ " +
                        std::to_string(t.euler_characteristic) + (t.is_closed() ? " (closed)" : ""));
    if (options.use_figures)
      results.push_back(mesh_panel((is_envelope ? "envelope: " : "direct: ") + outcome_caption(trial.report),
                                   trial.result.mesh, render::View::iso()));
  }
  out.tables.push_back(std::move(table));
  if (!options.use_figures) return out;

  // Figure 3's coarse tessellation (32 x 8 quads) and the envelope built over it.
  surfaces::TessellationOptions grid_options;
  grid_options.nu = 32;
  grid_options.nv = 8;
  const TriangleMesh grid = surfaces::tessellate(*c.surface, grid_options);
  const auto boundary = surfaces::boundary_curves(*c.surface, 0.05 * c.diagonal);
  Figure stages{"fig3_cylinder_stages", "Open cylinder: from the tessellation to the envelope samples", 2, {}};
  stages.panels.push_back(mesh_panel("tessellation 32 x 8", grid, render::View::iso()));
  PanelSpec balls = mesh_panel("balls of radius ρ = " + format_cell(rho), grid, render::View::iso(), false);
  render::SphereLayer ball_layer;
  ball_layer.centres = grid.vertices;
  ball_layer.radii = {rho};
  ball_layer.opacity = 0.25f;
  balls.scene.spheres.push_back(std::move(ball_layer));
  stages.panels.push_back(std::move(balls));
  stages.panels.push_back(points_panel("offsets ±ρn, rim half-circles", offset_points(grid, boundary, rho),
                                       render::View::iso(), {0.85f, 0.45f, 0.20f}));
  stages.panels.push_back(points_panel("envelope samples (" + std::to_string(envelope_points.size()) + ")",
                                       envelope_points, render::View::iso(), {0.85f, 0.45f, 0.20f}));
  out.figures.push_back(std::move(stages));
  out.figures.push_back(
      {"fig4_cylinder_results", "Open cylinder: direct Power Crust vs envelope", 0, std::move(results)});
  return out;
}

}  // namespace envcrust::experiments::detail
