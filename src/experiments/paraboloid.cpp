// Figure 7: the paraboloid cap, direct (no boundary) against envelope (one loop).
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {

ExperimentResult run_paraboloid(const ExperimentOptions& options) {
  ExperimentResult out;
  const std::size_t count = options.use_quick_sizes ? 3000 : 10000;
  const SurfaceCase c = make_case("paraboloid");
  const auto samples = sample_case(c, count, options.seed);
  Table table = outcome_table(
      "Paraboloid x = y² + z², x ≤ 4 (a disk: χ 1, one loop of radius 2), N " + std::to_string(count), {"method", "ρ"});
  Figure figure{"fig7_paraboloid", "Paraboloid: direct Power Crust vs envelope", 0, {}};
  for (const auto method : {pipeline::Method::PowerCrust, pipeline::Method::Envelope}) {
    step(options, "paraboloid", method == pipeline::Method::PowerCrust ? 0.0 : 0.5);
    const Trial trial = run_trial(samples, method_options(method, options.seed), c.reference, c.expected);
    const bool is_envelope = method == pipeline::Method::Envelope;
    table.add_row(trial_row({method_name(method), is_envelope ? Cell{trial.result.envelope.rho} : Cell{}}, trial));
    if (options.use_figures)
      figure.panels.push_back(mesh_panel((is_envelope ? "envelope: " : "direct: ") + outcome_caption(trial.report),
                                         trial.result.mesh, render::View{-60.0, 20.0}));
  }
  out.tables.push_back(std::move(table));
  if (options.use_figures) out.figures.push_back(std::move(figure));
  return out;
}

}  // namespace envcrust::experiments::detail
