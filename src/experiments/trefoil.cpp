// Figures 1, 2: the trefoil ribbon at decreasing sample counts, envelope against direct.
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {

ExperimentResult run_trefoil(const ExperimentOptions& options) {
  ExperimentResult out;
  const std::vector<std::size_t> counts = options.use_quick_sizes
                                              ? std::vector<std::size_t>{2500, 1000}
                                              : std::vector<std::size_t>{40000, 20000, 10000, 5000, 2500, 1250};
  const SurfaceCase c = make_case("trefoil-ribbon");
  Table table =
      outcome_table("Trefoil ribbon (χ 0, two trefoil loops, |lk| 3); ρ fixed at the automatic value of the largest N",
                    {"N", "method", "ρ"});
  Figure envelope_figure{"fig1_trefoil_envelope", "Trefoil ribbon: envelope method", 3, {}};
  Figure direct_figure{"fig2_trefoil_direct", "Trefoil ribbon: direct Power Crust", 3, {}};
  std::optional<double> rho;
  int envelope_correct = 0, direct_open = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    step(options, "trefoil", static_cast<double>(i) / counts.size());
    const auto samples = sample_case(c, counts[i], options.seed);
    for (const auto method : {pipeline::Method::Envelope, pipeline::Method::PowerCrust}) {
      auto ro = method_options(method, options.seed);
      if (method == pipeline::Method::Envelope) ro.envelope.rho = rho;
      const Trial trial = run_trial(samples, ro, c.reference, c.expected);
      const bool is_envelope = method == pipeline::Method::Envelope;
      if (is_envelope && !rho) rho = trial.result.envelope.rho;
      Cell rho_cell;
      if (is_envelope) rho_cell = trial.result.envelope.rho;
      table.add_row(trial_row({static_cast<std::int64_t>(counts[i]), method_name(method), rho_cell}, trial));
      if (is_envelope && trial.is_topology_correct) ++envelope_correct;
      if (!is_envelope && !trial.report.topology.boundary_loops.empty()) ++direct_open;
      if (options.use_figures) {
        auto& figure = is_envelope ? envelope_figure : direct_figure;
        figure.panels.push_back(
            mesh_panel("N " + std::to_string(counts[i]) + ": " + outcome_caption(trial.report, true), trial.result.mesh,
                       ribbon_view()));
      }
    }
  }
  out.tables.push_back(std::move(table));
  out.notes.push_back("envelope: correct topology (two trefoil loops, |lk| 3) at " + std::to_string(envelope_correct) +
                      " of " + std::to_string(counts.size()) + " sample counts");
  out.notes.push_back("direct Power Crust: a boundary loop at " + std::to_string(direct_open) + " of " +
                      std::to_string(counts.size()) + " sample counts (it closes the ribbon into a solid)");
  if (options.use_figures) {
    out.figures.push_back(std::move(envelope_figure));
    out.figures.push_back(std::move(direct_figure));
  }
  return out;
}

}  // namespace envcrust::experiments::detail
