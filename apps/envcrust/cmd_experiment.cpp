// `envcrust experiment NAME|all -o DIR`: run the paper's experiments and write, per experiment,
// DIR/NAME/results.json, results.md and the figures as PNG files.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli_common.h"
#include "commands.h"
#include "envcrust/errors.h"
#include "envcrust/heap.h"
#include "envcrust/experiments.h"
#include "envcrust/io.h"

namespace envcrust::cli {
namespace {

struct ExperimentCommand {
  std::string name;
  std::string output;
  std::string data_dir;  // --data-dir or ENVCRUST_SHARED_DATA; none: the scan experiment is skipped
  std::string scan = "foot_vhacd";
  std::string scan_reference = "foot_open.off";
  std::string font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  bool list = false;
  experiments::ExperimentOptions options;
  experiments::FigureRenderOptions render;
  CommonFlags common;
};

nlohmann::json cell_json(const experiments::Cell& cell) {
  struct Visitor {
    nlohmann::json operator()(std::monostate) const { return nullptr; }
    nlohmann::json operator()(bool b) const { return b; }
    nlohmann::json operator()(std::int64_t i) const { return i; }
    nlohmann::json operator()(double d) const { return d; }
    nlohmann::json operator()(const std::string& s) const { return s; }
  };
  return std::visit(Visitor{}, cell);
}

nlohmann::json result_json(const experiments::ExperimentResult& r, double render_seconds) {
  nlohmann::json tables = nlohmann::json::array();
  for (const auto& t : r.tables) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& row : t.rows) {
      nlohmann::json cells = nlohmann::json::array();
      for (const auto& cell : row) cells.push_back(cell_json(cell));
      rows.push_back(std::move(cells));
    }
    tables.push_back({{"title", t.title}, {"columns", t.columns}, {"rows", std::move(rows)}});
  }
  nlohmann::json figures = nlohmann::json::array();
  for (const auto& f : r.figures)
    figures.push_back({{"name", f.name}, {"file", f.name + ".png"}, {"title", f.title}, {"panels", f.panels.size()}});
  return {{"name", r.name},
          {"description", r.description},
          {"skipped", r.is_skipped},
          {"seconds", r.seconds},
          {"render_seconds", render_seconds},
          {"notes", r.notes},
          {"tables", tables},
          {"figures", figures}};
}

// The scan experiment's data: points and, when present, the ground-truth mesh. A missing
// folder is not an error: the experiment is then skipped with a note.
std::optional<experiments::ScanData> load_scan(const ExperimentCommand& cmd) {
  if (cmd.data_dir.empty()) return std::nullopt;
  const std::filesystem::path folder = std::filesystem::path(cmd.data_dir) / cmd.scan;
  const auto points = folder / "points.xyz";
  if (!std::filesystem::exists(points)) return std::nullopt;
  experiments::ScanData scan;
  scan.name = cmd.scan;
  scan.points = io::read_points(points);
  if (!cmd.scan_reference.empty()) scan.reference = io::read_triangle_mesh(folder / cmd.scan_reference);
  return scan;
}

// A missing font leaves the captions out (a warning); one FreeType cannot use is an error,
// found before the experiments run.
std::optional<render::Font> load_font(const std::string& path, std::vector<std::string>& warnings) {
  try {
    return read_checked_font(path, 14);
  } catch (const IoError& e) {
    warnings.push_back(std::string("no captions: ") + e.what());
    return std::nullopt;
  }
}

void run_experiments(ExperimentCommand& cmd) {
  io::reuse_freed_memory();
  const auto thread_limit = limit_threads(cmd.common.threads);
  if (cmd.list) {
    for (const auto& e : experiments::experiment_list())
      std::cout << e.name << (e.paper_figures.empty() ? "" : " (" + e.paper_figures + ")") << ": " << e.description
                << "\n";
    return;
  }
  if (cmd.name.empty()) throw UsageError("experiment: NAME (or 'all') is required; --list shows the names");
  if (cmd.output.empty()) throw UsageError("experiment: -o DIR is required");
  std::vector<std::string> names;
  if (cmd.name == "all") {
    for (const auto& e : experiments::experiment_list()) names.push_back(e.name);
  } else {
    std::string known;
    bool is_known = false;
    for (const auto& e : experiments::experiment_list()) {
      known += e.name + ", ";
      is_known = is_known || e.name == cmd.name;
    }
    if (!is_known) throw UsageError("unknown experiment '" + cmd.name + "' (known: " + known + "all)");
    names.push_back(cmd.name);
  }
  // The folder is made first: a name taken by a file fails now, not after the first experiment.
  {
    std::error_code ec;
    std::filesystem::create_directories(cmd.output, ec);
    if (!std::filesystem::is_directory(cmd.output))
      throw IoError(cmd.output + ": cannot make the output folder (" +
                    (ec ? ec.message() : std::string("a file of that name exists")) + ")");
  }
  const bool quiet = cmd.common.quiet || cmd.common.json;
  cmd.options.progress = terminal_progress(quiet);
  if (std::find(names.begin(), names.end(), "scan") != names.end()) cmd.options.scan = load_scan(cmd);
  std::vector<std::string> warnings;
  std::optional<render::Font> font;
  if (cmd.options.use_figures) font = load_font(cmd.font, warnings);

  const auto start = std::chrono::steady_clock::now();
  nlohmann::json all = nlohmann::json::array();
  std::string index = "# envcrust experiments\n\n";
  for (const auto& name : names) {
    const auto result = experiments::run_experiment(name, cmd.options);
    const std::filesystem::path dir = std::filesystem::path(cmd.output) / name;
    std::filesystem::create_directories(dir);
    const auto render_start = std::chrono::steady_clock::now();
    std::string markdown = experiments::to_markdown(result);
    for (const auto& figure : result.figures) {
      io::write_png(dir / (figure.name + ".png"), experiments::render_figure(figure, cmd.render, font));
      markdown += "![" + figure.title + "](" + figure.name + ".png)\n\n";
    }
    const double render_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - render_start).count();
    const auto json = result_json(result, render_seconds);
    io::write_text(dir / "results.json", json_text(json));
    io::write_text(dir / "results.md", markdown);
    all.push_back(json);
    index += experiments::to_markdown(result);
    if (!quiet) {
      std::cout << "experiment " << name << ": " << (result.is_skipped ? "skipped, " : "")
                << static_cast<int>(result.seconds + 0.5) << " s (figures " << static_cast<int>(render_seconds + 0.5)
                << " s) -> " << dir.string() << "\n";
      for (const auto& note : result.notes) std::cout << "  " << note << "\n";
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (names.size() > 1) io::write_text(std::filesystem::path(cmd.output) / "results.md", index);
  if (cmd.common.json) {
    print_json({{"experiments", all}, {"seconds", seconds}, {"warnings", warnings}});
    return;
  }
  if (cmd.common.quiet) return;
  for (const auto& w : warnings) std::cout << "warning: " << w << "\n";
  std::cout << "total " << static_cast<int>(seconds + 0.5) << " s\n";
}

}  // namespace

void register_experiment(CLI::App& app) {
  auto cmd = std::make_shared<ExperimentCommand>();
  CLI::App* sub = app.add_subcommand(
      "experiment",
      "Reproduce the paper's experiments (Figures 1-11) and ours: tables (results.json, results.md)\n"
      "and figures (PNG) per experiment under DIR/NAME/");
  sub->add_option("name", cmd->name, "Experiment name, or 'all' (--list shows them)");
  sub->add_option("-o,--output", cmd->output, "Output folder");
  sub->add_flag("--list", cmd->list, "List the experiments and exit");
  sub->add_flag("--quick", cmd->options.use_quick_sizes, "Small sizes (seconds per experiment; for tests)");
  sub->add_option("--seed", cmd->options.seed, "Seed of every sampling and perturbation")->check(seed_number())->capture_default_str();
  sub->add_option("--data-dir", cmd->data_dir,
                  "Folder of the scan data (scan experiment; none given: the experiment is skipped)")
      ->envname("ENVCRUST_SHARED_DATA");
  sub->add_option("--scan", cmd->scan, "Data set folder under --data-dir for the scan experiment (points.xyz)")
      ->capture_default_str();
  sub->add_option("--scan-reference", cmd->scan_reference,
                  "Ground-truth mesh of the scan, a file in its folder ('' for none: distances to the points)")
      ->capture_default_str();
  sub->add_flag(
      "--no-figures", [cmd](std::int64_t) { cmd->options.use_figures = false; }, "Tables only: no PNG figures");
  // Checked before the experiments run, not when their figures are drawn.
  sub->add_option("--panel-width", cmd->render.panel_width, "Pixels per panel, horizontally")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  sub->add_option("--panel-height", cmd->render.panel_height, "Pixels per panel, vertically")
      ->check(CLI::Range(16, 8192))
      ->capture_default_str();
  sub->add_option("--font", cmd->font, "TrueType font of the captions")->capture_default_str();
  add_common_flags(*sub, cmd->common);
  add_threads_option(*sub, cmd->common.threads);
  sub->callback([cmd] { run_experiments(*cmd); });
}

}  // namespace envcrust::cli
