// Figures 5, 6: a real scan open at one boundary (the foot, cut above the ankle): points,
// inner polar balls, pole normals, envelope samples, direct against envelope result.
#include <CGAL/centroid.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "envcrust/boundary.h"
#include "envcrust/input.h"
#include "envcrust/power_crust.h"
#include "envcrust/topology.h"
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {
namespace {

// Every k-th element, so that a panel stays legible (and light to render).
template <class T>
std::vector<T> every(const std::vector<T>& items, std::size_t target) {
  const std::size_t k = std::max<std::size_t>(1, items.size() / std::max<std::size_t>(1, target));
  std::vector<T> out;
  for (std::size_t i = 0; i < items.size(); i += k) out.push_back(items[i]);
  return out;
}

// Looking into the opening: from the boundary loop's centroid away from the shape's centroid.
render::View view_into(const std::vector<Point3>& points, const std::vector<Polyline>& loops) {
  if (loops.empty() || loops.front().empty()) return render::View::iso();
  const Point3 centre = CGAL::centroid(points.begin(), points.end());
  const Point3 rim = CGAL::centroid(loops.front().begin(), loops.front().end());
  Vector3 d = rim - centre;
  d = d / std::sqrt(d.squared_length());
  // Slightly off-axis, so the opening reads as a hole in a surface rather than a disk.
  const double el = std::asin(std::clamp(d.z(), -1.0, 1.0)) * 180 / std::numbers::pi;
  const double az = std::atan2(d.y(), d.x()) * 180 / std::numbers::pi;
  return {az + 25.0, std::clamp(el, -80.0, 80.0)};
}

}  // namespace

ExperimentResult run_scan(const ExperimentOptions& options) {
  ExperimentResult out;
  if (!options.scan) {
    out.is_skipped = true;
    out.notes.push_back("skipped: no scan data (the CLI reads DIR/foot_vhacd/points.xyz: give --data-dir DIR or set "
        "ENVCRUST_SHARED_DATA=DIR)");
    return out;
  }
  const ScanData& scan = *options.scan;
  // The samples as `reconstruct` prepares a point file (duplicates merged, stray samples
  // removed, normal lines fitted when the file has none, boundary detected), so the figure
  // shows what the tool does. The reference is in the file's coordinates: no local origin.
  input::InputOptions preparation;
  preparation.name = scan.name;
  preparation.use_local_origin = false;
  input::PointInput in;
  in.points.points = scan.points;
  const std::string normal_source = scan.points.has_normals() ? "from the file" : "PCA";
  step(options, "scan", 0.05);
  input::PreparedInput prepared = input::prepare_points(std::move(in), preparation);
  const envelope::SurfaceSamples& samples = prepared.samples;
  const std::vector<std::string> detection_warnings =
      prepared.detection ? prepared.detection->warnings : std::vector<std::string>{};

  analysis::Reference reference;
  surfaces::ExpectedTopology expected;
  bool has_expected = false;
  if (scan.reference) {
    reference.mesh = scan.reference;
    const auto truth = topology::analyze_topology(*scan.reference);
    for (const auto& loop : truth.boundary_loops) reference.boundary.push_back(loop.polyline(truth.points));
    expected.euler_characteristic = static_cast<int>(truth.euler_characteristic);
    expected.boundary_loops = static_cast<int>(truth.boundary_loops.size());
    expected.is_orientable = truth.is_orientable;
    expected.boundary_knots.assign(truth.boundary_loops.size(), "unknot");
    has_expected = truth.components.size() == 1;
  } else {
    reference.points = samples.points;
  }

  // The direct Power Crust, kept whole: its poles are the polar balls of the figure.
  step(options, "scan", 0.1);
  const auto start = std::chrono::steady_clock::now();
  const auto pc = powercrust::power_crust(samples.points);
  const double pc_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto direct_report = analyze(pc.crust, reference);

  // Pole normals (Amenta-Bern): the direction from a sample to its outer pole p+.
  std::vector<double> angles_deg;
  std::vector<Polyline> pole_normals;
  const auto box = CGAL::bbox_3(samples.points.begin(), samples.points.end());
  const double diagonal = std::sqrt(
      CGAL::squared_distance(Point3(box.xmin(), box.ymin(), box.zmin()), Point3(box.xmax(), box.ymax(), box.zmax())));
  for (std::size_t i = 0; i < samples.points.size(); ++i) {
    const Index s = pc.input_to_sample[i];
    Vector3 d = pc.poles[pc.sample_poles[s].outer].center - pc.samples[s];
    d = d / std::sqrt(d.squared_length());
    const double c = std::min(1.0, std::abs(d * samples.normals[i]));
    angles_deg.push_back(std::acos(c) * 180 / std::numbers::pi);
    pole_normals.push_back({samples.points[i], samples.points[i] + 0.03 * diagonal * d});
  }
  std::vector<double> sorted = angles_deg;
  std::sort(sorted.begin(), sorted.end());

  step(options, "scan", 0.5);
  auto ro = pipeline::options_for_input(prepared.kind, method_options(pipeline::Method::Envelope, options.seed));
  ro.use_power_crust_fallback = false;  // the envelope's own result, beside the direct one
  Trial envelope_trial = run_trial(samples, ro, reference, expected, true);
  if (!has_expected) envelope_trial.is_topology_correct = false;

  Table table =
      outcome_table(scan.name + ": " + std::to_string(samples.points.size()) + " points, normals " + normal_source +
                        ", " + std::to_string(samples.boundary.size()) + " boundary curves detected" +
                        (scan.reference ? "; truth: the data set's mesh" : "; truth: the points"),
                    {"method", "ρ"});
  const bool direct_ok = has_expected && has_expected_topology(direct_report, expected);
  std::vector<Cell> direct_row = {method_name(pipeline::Method::PowerCrust), Cell{}};
  for (auto& cell : outcome_cells(direct_report, direct_ok, pc_seconds)) direct_row.push_back(std::move(cell));
  table.add_row(std::move(direct_row));
  table.add_row(
      trial_row({method_name(pipeline::Method::Envelope), envelope_trial.result.envelope.rho}, envelope_trial));
  out.tables.push_back(std::move(table));
  Table normals_table;
  normals_table.title = "Pole normals against " + normal_source + " normal lines (angle, degrees)";
  normals_table.columns = {"median", "90th percentile", "max"};
  normals_table.add_row({sorted[sorted.size() / 2], sorted[sorted.size() * 9 / 10], sorted.back()});
  out.tables.push_back(std::move(normals_table));
  for (const auto& w : detection_warnings) out.notes.push_back("boundary detection: " + w);
  for (const auto& w : envelope_trial.result.warnings) out.notes.push_back("envelope: " + w);

  if (!options.use_figures) return out;
  const render::View view = render::View::iso();
  Figure stages{"fig5_scan_stages", scan.name + ": points, polar balls, pole normals, envelope samples", 2, {}};
  stages.panels.push_back(points_panel(std::to_string(samples.points.size()) + " points", samples.points, view));
  PanelSpec balls;
  balls.caption = "inner polar balls";
  balls.view = view;
  render::SphereLayer ball_layer;
  std::vector<powercrust::Pole> inner;
  for (const auto& p : pc.poles)
    if (p.label == powercrust::PoleLabel::In) inner.push_back(p);
  for (const auto& p : every(inner, 600)) {
    ball_layer.centres.push_back(p.center);
    ball_layer.radii.push_back(p.radius);
  }
  ball_layer.opacity = 0.35f;
  ball_layer.color = {0.85f, 0.45f, 0.20f};
  balls.scene.spheres.push_back(std::move(ball_layer));
  stages.panels.push_back(std::move(balls));
  PanelSpec normal_panel;
  normal_panel.caption = "pole normals";
  normal_panel.view = view;
  render::CurveLayer needles;
  needles.loops = every(pole_normals, 1500);
  needles.radius = 0.001 * diagonal;
  needles.colors = {{0.20f, 0.45f, 0.80f}};
  normal_panel.scene.curves.push_back(std::move(needles));
  stages.panels.push_back(std::move(normal_panel));
  stages.panels.push_back(
      points_panel("envelope samples (" + std::to_string(envelope_trial.result.envelope.samples.size()) + ")",
                   envelope_trial.result.envelope.points(), view, {0.85f, 0.45f, 0.20f}));
  out.figures.push_back(std::move(stages));
  const render::View into = view_into(samples.points, reference.boundary);
  Figure results{"fig6_scan_results", scan.name + ": direct vs envelope, towards the open boundary", 2, {}};
  results.panels.push_back(mesh_panel("direct: " + outcome_caption(direct_report), pc.crust, into));
  results.panels.push_back(
      mesh_panel("envelope: " + outcome_caption(envelope_trial.report), envelope_trial.result.mesh, into));
  out.figures.push_back(std::move(results));
  return out;
}

}  // namespace envcrust::experiments::detail
