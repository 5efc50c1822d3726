// Figure 10: PL approximations of a non-planar unknot with fewer and fewer vertices. The
// figure-eight knot ((2 + cos 2t) cos 3t, (2 + cos 2t) sin 3t, sin 4t) has a crossing at
// t = pi/6 over t = 5pi/6 with height gap sqrt 3; a narrow bump z += 2.6 exp(-((t - 5pi/6) /
// 0.02)^2) switches it and makes the curve an unknot. A polyline whose vertices miss the
// bump keeps the figure-eight (docs/method.md §10.5).
#include <cmath>
#include <numbers>
#include <random>

#include "envcrust/random.h"
#include "experiment_list.h"
#include "trial.h"

namespace envcrust::experiments::detail {
namespace {

constexpr double kBumpHeight = 2.6;
constexpr double kBumpWidth = 0.02;

Point3 unknot_point(double t) {
  const double bump_at = 5 * std::numbers::pi / 6;
  const double r = 2 + std::cos(2 * t);
  const double bump = kBumpHeight * std::exp(-std::pow((t - bump_at) / kBumpWidth, 2));
  return {r * std::cos(3 * t), r * std::sin(3 * t), std::sin(4 * t) + bump};
}

// n vertices uniform in t, shifted by `phase` (a fraction of one step).
Polyline approximation(int n, double phase) {
  Polyline curve;
  for (int i = 0; i < n; ++i) curve.push_back(unknot_point(2 * std::numbers::pi * (i + phase) / n));
  return curve;
}

}  // namespace

ExperimentResult run_unknot_curve(const ExperimentOptions& options) {
  ExperimentResult out;
  const std::vector<int> counts =
      options.use_quick_sizes ? std::vector<int>{1000, 120, 30} : std::vector<int>{1000, 500, 250, 120, 60, 30};
  const int phases = options.use_quick_sizes ? 6 : 20;
  Table table;
  table.title = "Knot type of PL approximations of the unknot (" + std::to_string(phases) +
                " random phase offsets per vertex count)";
  table.columns = {"vertices", "unknot", "figure-eight", "trefoil", "other", "all unknots"};
  std::mt19937_64 rng(options.seed);
  std::optional<int> first_knotted;
  Figure figure{"fig10_unknot_curve", "Unknot with a narrow bump; PL approximations (phase 0)", 4, {}};
  if (options.use_figures) {
    render::CurveLayer layer;
    layer.loops.push_back(approximation(4000, 0.0));
    figure.panels.push_back({"the unknot (4000 vertices)", {{}, {}, {layer}}, render::View::top()});
  }
  for (std::size_t i = 0; i < counts.size(); ++i) {
    step(options, "unknot-curve", static_cast<double>(i) / counts.size());
    std::int64_t unknot = 0, figure_eight = 0, trefoil = 0, other = 0;
    for (int k = 0; k < phases; ++k) {
      const double phase = k == 0 ? 0.0 : uniform01(rng);
      const auto report = analysis::analyze_curve(approximation(counts[i], phase));
      switch (report.type) {
        case knots::KnotType::Unknot:
          ++unknot;
          break;
        case knots::KnotType::FigureEight:
          ++figure_eight;
          break;
        case knots::KnotType::Trefoil:
          ++trefoil;
          break;
        case knots::KnotType::Other:
        case knots::KnotType::Unknown:
          ++other;
          break;
      }
      if (k == 0 && options.use_figures) {
        render::CurveLayer layer;
        layer.loops.push_back(approximation(counts[i], 0.0));
        figure.panels.push_back({std::to_string(counts[i]) + " vertices: " + knots::to_string(report.type),
                                 {{}, {}, {layer}},
                                 render::View::top()});
      }
    }
    if (unknot != phases && !first_knotted) first_knotted = counts[i];
    table.add_row({std::int64_t{counts[i]}, unknot, figure_eight, trefoil, other, unknot == phases});
  }
  out.tables.push_back(std::move(table));
  out.notes.push_back(first_knotted ? "first vertex count (descending) at which an approximation is not an unknot: " +
                                          std::to_string(*first_knotted)
                                    : "every approximation is an unknot");
  if (options.use_figures) out.figures.push_back(std::move(figure));
  return out;
}

}  // namespace envcrust::experiments::detail
