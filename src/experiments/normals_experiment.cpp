// Figure 9: exact normals rotated by a random angle (everywhere, or on the boundary curves
// only); quality of the envelope reconstruction against the angle. docs/method.md §2.5 predicts that
// interior errors cost little (rho delta^2 / 2) and tilted rims most (a seam of rho delta).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "envcrust/random.h"
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {
namespace {

enum class Perturbed { Everywhere, BoundaryOnly };

// A random unit vector perpendicular to `n` (uniform on the circle).
Vector3 random_perpendicular(const Vector3& n, std::mt19937_64& rng) {
  const Vector3 helper = std::abs(n.x()) < 0.9 ? Vector3(1, 0, 0) : Vector3(0, 1, 0);
  Vector3 a = CGAL::cross_product(n, helper);
  a = a / std::sqrt(a.squared_length());
  const Vector3 b = CGAL::cross_product(n, a);
  const double phi = 2 * std::numbers::pi * uniform01(rng);
  return std::cos(phi) * a + std::sin(phi) * b;
}

// n rotated by exactly `angle` towards a random perpendicular direction.
Vector3 tilt(const Vector3& n, double angle, std::mt19937_64& rng) {
  return std::cos(angle) * n + std::sin(angle) * random_perpendicular(n, rng);
}

envelope::SurfaceSamples perturb(envelope::SurfaceSamples samples, Perturbed where, double angle_deg,
                                 std::uint64_t seed) {
  const double angle = angle_deg * std::numbers::pi / 180.0;
  std::mt19937_64 rng(seed);
  if (where == Perturbed::Everywhere)
    for (auto& n : samples.normals) n = tilt(n, angle, rng);
  // A boundary frame turns about its tangent by +-angle: the rim half-circle tilts.
  for (auto& curve : samples.boundary)
    for (auto& v : curve.vertices) {
      const double a = uniform01(rng) < 0.5 ? angle : -angle;
      const Vector3 n = v.normal;
      v.normal = std::cos(a) * n + std::sin(a) * v.conormal;
      v.conormal = -std::sin(a) * n + std::cos(a) * v.conormal;
      if (v.is_corner) v.conormal_next = -std::sin(a) * n + std::cos(a) * v.conormal_next;
    }
  return samples;
}

}  // namespace

ExperimentResult run_normals(const ExperimentOptions& options) {
  ExperimentResult out;
  const std::size_t count = options.use_quick_sizes ? 3000 : 10000;
  const std::vector<double> angles =
      options.use_quick_sizes ? std::vector<double>{0, 30} : std::vector<double>{0, 2, 5, 10, 20, 30};
  const SurfaceCase c = make_case("trefoil-ribbon");
  const auto exact = sample_case(c, count, options.seed);
  // rho is fixed at its value for exact normals: the automatic reach estimate would itself
  // shrink with the normal error, and the experiment measures the envelope's sensitivity.
  auto ro = method_options(pipeline::Method::Envelope, options.seed);
  ro.envelope.rho = envelope::sample_envelope(exact, ro.envelope).rho;

  Table table = outcome_table("Trefoil ribbon, N " + std::to_string(count) + ", ρ " + format_cell(*ro.envelope.rho) +
                                  ": random normal errors of a fixed angle",
                              {"perturbed", "angle °"});
  Figure figure{"fig9_normals",
                "Trefoil ribbon with rotated normals (top: everywhere, bottom: boundary only)",
                static_cast<int>(std::min<std::size_t>(angles.size(), 3)),
                {}};
  const std::vector<double> shown = {angles.front(), angles[angles.size() / 2], angles.back()};
  std::size_t done = 0;
  for (const auto where : {Perturbed::Everywhere, Perturbed::BoundaryOnly}) {
    for (const double angle : angles) {
      step(options, "normals", static_cast<double>(done++) / (2 * angles.size()));
      const Trial trial = run_trial(perturb(exact, where, angle, options.seed + 7), ro, c.reference, c.expected);
      const std::string where_name = where == Perturbed::Everywhere ? "everywhere" : "boundary only";
      table.add_row(trial_row({where_name, angle}, trial));
      if (options.use_figures && std::find(shown.begin(), shown.end(), angle) != shown.end() &&
          figure.panels.size() < 2 * std::min<std::size_t>(angles.size(), 3))
        figure.panels.push_back(
            mesh_panel(where_name + " " + format_cell(angle) + "°: " + outcome_caption(trial.report, true),
                       trial.result.mesh, ribbon_view()));
    }
  }
  out.tables.push_back(std::move(table));
  out.notes.push_back(
      "boundary only = the boundary curves' frames (n, c) turned about the tangent; the sample "
      "normals stay exact");
  if (options.use_figures) out.figures.push_back(std::move(figure));
  return out;
}

}  // namespace envcrust::experiments::detail
