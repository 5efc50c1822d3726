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
};

bool is_correct(const SurfaceCase& c, pipeline::Method method, std::size_t count, std::uint64_t seed,
                std::string& caption) {
  const Trial trial =
      run_trial(sample_case(c, count, seed), method_options(method, seed), c.reference, c.expected, false);
  caption = outcome_caption(trial.report, true);
  return trial.is_topology_correct;
}

// Walk down the ladder with one seed until the first failure; then confirm the sparsest passing
// count with the extra seeds, stepping back up while a confirmation fails.
LadderResult climb(const SurfaceCase& c, pipeline::Method method, const std::vector<std::size_t>& ladder,
                   std::uint64_t seed, int seeds) {
  LadderResult r;
  std::size_t passed = 0;  // rungs passed with the first seed
  for (; passed < ladder.size(); ++passed) {
    ++r.runs;
    std::string caption;
    if (!is_correct(c, method, ladder[passed], seed, caption)) {
      r.first_failure = ladder[passed];
      r.failure = caption;
      break;
    }
  }
  for (std::size_t k = passed; k-- > 0;) {
    bool is_confirmed = true;
    for (int s = 1; s < seeds && is_confirmed; ++s) {
      ++r.runs;
      std::string caption;
      if (!is_correct(c, method, ladder[k], seed + s, caption)) {
        is_confirmed = false;
        r.first_failure = ladder[k];
        r.failure = caption + " (seed " + std::to_string(seed + s) + ")";
      }
    }
    if (is_confirmed) {
      r.sparsest_ok = ladder[k];
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
                                              ? std::vector<std::size_t>{2000, 250}
                                              : std::vector<std::size_t>{5000, 2500, 1250, 625, 312, 156};
  const int seeds = options.use_quick_sizes ? 1 : 3;
  Table table;
  table.title = "Sparsest sample count with the right topology (ladder " + std::to_string(ladder.front()) + " → " +
                std::to_string(ladder.back()) + ", halving; confirmed with " + std::to_string(seeds) + " seeds)";
  table.columns = {"surface", "method", "sparsest N correct", "first failing N", "outcome there", "runs"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    step(options, "density", static_cast<double>(i) / names.size());
    const SurfaceCase c = make_case(names[i]);
    for (const auto method : {pipeline::Method::Envelope, pipeline::Method::PowerCrust}) {
      const LadderResult r = climb(c, method, ladder, options.seed, seeds);
      table.add_row({names[i], method_name(method),
                     r.sparsest_ok ? Cell{static_cast<std::int64_t>(*r.sparsest_ok)} : Cell{std::string("none")},
                     r.first_failure ? Cell{static_cast<std::int64_t>(*r.first_failure)} : Cell{},
                     r.first_failure ? Cell{r.failure} : Cell{}, std::int64_t{r.runs}});
    }
  }
  out.tables.push_back(std::move(table));
  out.notes.push_back("\"none\": wrong already at N " + std::to_string(ladder.front()) +
                      "; the direct Power Crust closes every boundary, so it never has an open surface's topology");
  return out;
}

}  // namespace envcrust::experiments::detail
