// Beyond the paper: for each built-in open surface, the sparsest sampling at which each method
// still gets the topology right (descending ladder of sample counts, confirmed with more seeds).
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {
namespace {

struct LadderResult {
  std::optional<std::size_t> sparsest_ok;  ///< all confirmation seeds correct
  std::optional<std::size_t> first_failure;
  std::string failure;  ///< outcome caption at the first failure
  int runs = 0;
  /// For the figure: the first seed's result at sparsest_ok, else at the first failure (with
  /// its outcome in the caption).
  TriangleMesh shown_mesh;
  std::string shown_caption;
};

// One run: the topology verdict, its caption and the result mesh.
struct Rung {
  bool is_correct = false;
  std::string caption;
  TriangleMesh mesh;
};

Rung run_rung(const SurfaceCase& c, pipeline::Method method, std::size_t count, std::uint64_t seed) {
  Trial trial = run_trial(sample_case(c, count, seed), method_options(method, seed), c.reference, c.expected, false);
  return {trial.is_topology_correct, outcome_caption(trial.report, true), std::move(trial.result.mesh)};
}

// Walk down the ladder with one seed until the first failure; then confirm the sparsest passing
// count with the extra seeds, stepping back up while a confirmation fails.
LadderResult climb(const SurfaceCase& c, pipeline::Method method, const std::vector<std::size_t>& ladder,
                   std::uint64_t seed, int seeds) {
  LadderResult r;
  std::vector<Rung> first_seed;  // rungs run with the first seed, all correct but maybe the last
  for (std::size_t k = 0; k < ladder.size(); ++k) {
    ++r.runs;
    first_seed.push_back(run_rung(c, method, ladder[k], seed));
    if (!first_seed.back().is_correct) {
      r.first_failure = ladder[k];
      r.failure = first_seed.back().caption;
      r.shown_mesh = first_seed.back().mesh;
      r.shown_caption = "N " + std::to_string(ladder[k]) + ": " + first_seed.back().caption;
      break;
    }
  }
  const std::size_t passed = first_seed.size() - (r.first_failure ? 1 : 0);
  for (std::size_t k = passed; k-- > 0;) {
    bool is_confirmed = true;
    for (int s = 1; s < seeds && is_confirmed; ++s) {
      ++r.runs;
      const Rung check = run_rung(c, method, ladder[k], seed + s);
      if (!check.is_correct) {
        is_confirmed = false;
        r.first_failure = ladder[k];
        r.failure = check.caption + " (seed " + std::to_string(seed + s) + ")";
      }
    }
    if (is_confirmed) {
      r.sparsest_ok = ladder[k];
      r.shown_mesh = std::move(first_seed[k].mesh);
      r.shown_caption = "N " + std::to_string(ladder[k]) + " (sparsest)";
      break;
    }
  }
  return r;
}

}  // namespace

ExperimentResult run_density(const ExperimentOptions& options) {
  ExperimentResult out;
  std::vector<std::string> names;
  if (options.use_quick_sizes) {
    names = {"cylinder", "moebius"};
  } else {
    for (const auto& name : surfaces::builtin_names())
      if (surfaces::make_builtin(name)->expected_topology().boundary_loops > 0) names.push_back(name);
  }
  const std::vector<std::size_t> ladder = options.use_quick_sizes
                                              ? std::vector<std::size_t>{2000, 250, 80, 30}
                                              : std::vector<std::size_t>{5000, 2500, 1250, 625, 312, 156};
  const int seeds = options.use_quick_sizes ? 1 : 3;
  Table table;
  std::string rungs;
  for (const std::size_t n : ladder) rungs += (rungs.empty() ? "" : ", ") + std::to_string(n);
  table.title = "Sparsest sample count with the right topology (ladder " + rungs + "; confirmed with " +
                std::to_string(seeds) + (seeds == 1 ? " seed)" : " seeds)");
  table.columns = {"surface", "method", "sparsest N correct", "first failing N", "outcome there", "runs"};
  Figure figure{"density", "Sparsest correct sampling per surface: envelope (left) and direct Power Crust (right)", 4, {}};
  for (std::size_t i = 0; i < names.size(); ++i) {
    step(options, "density", static_cast<double>(i) / names.size());
    const SurfaceCase c = make_case(names[i]);
    for (const auto method : {pipeline::Method::Envelope, pipeline::Method::PowerCrust}) {
      const LadderResult r = climb(c, method, ladder, options.seed, seeds);
      table.add_row({names[i], method_name(method),
                     r.sparsest_ok ? Cell{static_cast<std::int64_t>(*r.sparsest_ok)} : Cell{std::string("none")},
                     r.first_failure ? Cell{static_cast<std::int64_t>(*r.first_failure)} : Cell{},
                     r.first_failure ? Cell{r.failure} : Cell{}, std::int64_t{r.runs}});
      if (options.use_figures) {
        const bool is_ribbon = names[i].find("ribbon") != std::string::npos;
        figure.panels.push_back(mesh_panel(names[i] + (method == pipeline::Method::Envelope ? " envelope " : " direct ") +
                                               r.shown_caption,
                                           r.shown_mesh, is_ribbon ? ribbon_view() : render::View::iso()));
      }
    }
  }
  out.tables.push_back(std::move(table));
  if (options.use_figures) out.figures.push_back(std::move(figure));
  out.notes.push_back("\"none\": wrong already at N " + std::to_string(ladder.front()) +
                      "; the direct Power Crust closes every boundary, so it never has an open surface's topology");
  return out;
}

}  // namespace envcrust::experiments::detail
