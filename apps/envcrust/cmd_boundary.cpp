// `envcrust boundary`: the boundary curves of a point cloud alone (detected, or through given
// points), with their lengths, widths and knot types, and against a reference's true boundary.
#include "cli_common.h"
#include "commands.h"
#include "curve_output.h"
#include "input_frame.h"
#include "inputs.h"
#include "surface_input.h"

#include "envcrust/distance.h"
#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/knots.h"
#include "envcrust/mesh.h"

#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

namespace envcrust::cli {
namespace {

struct BoundaryCommand {
  std::string input;
  std::string output;
  std::string points_output;
  std::string reference;
  bool no_knots = false;
  InputSettings sampling;
  CommonFlags common;
};

// For each curve of `from`, the index of the nearest curve of `to` (Hausdorff distance) and
// that distance; -1 and infinity when `to` is empty.
std::vector<std::pair<int, double>> nearest_curves(const std::vector<Polyline>& from, const std::vector<Polyline>& to) {
  std::vector<std::pair<int, double>> out;
  for (const auto& a : from) {
    std::pair<int, double> best{-1, std::numeric_limits<double>::infinity()};
    for (std::size_t j = 0; j < to.size(); ++j) {
      const double d = distance::closed_polyline_hausdorff(a, to[j]);
      if (d < best.second) best = {static_cast<int>(j), d};
    }
    out.push_back(best);
  }
  return out;
}

// Each curve's vertices, length, knot type ("unknown", with a note, when the curve passes
// through itself and no projection of it is generic), width and share sampled beyond.
nlohmann::json curves_json(const LoadedSurface& loaded, double diagonal, bool with_knots,
                           std::vector<std::string>& notes) {
  nlohmann::json curves = nlohmann::json::array();
  const auto& detection = loaded.detection;
  for (std::size_t i = 0; i < loaded.samples.boundary.size(); ++i) {
    const Polyline line = loaded.samples.boundary[i].polyline();
    const double length = mesh::closed_length(line);
    nlohmann::json c = {{"vertices", line.size()}, {"length", length}, {"length_rel_diag", length / diagonal}};
    if (with_knots && line.size() >= 3) {
      try {
        c["knot"] = knots::to_string(knots::identify_knot(line).type);
      } catch (const Error& e) {
        c["knot"] = "unknown";
        notes.push_back("curve " + std::to_string(i) + ": no knot type: " + e.what());
      }
    }
    if (detection && i < detection->loop_widths.size()) c["width_local_spacings"] = detection->loop_widths[i];
    if (detection && i < detection->sampled_beyond.size()) c["sampled_beyond"] = detection->sampled_beyond[i];
    curves.push_back(c);
  }
  return curves;
}

// The curves found against the reference's true boundary loops: each true loop's nearest
// curve and their Hausdorff distance, and each curve's nearest true loop.
nlohmann::json reference_json(const analysis::Reference& reference, const LoadedSurface& loaded, double diagonal,
                              nlohmann::json& curves) {
  std::vector<Polyline> found;
  for (const auto& c : loaded.samples.boundary) found.push_back(c.polyline());
  nlohmann::json truth = nlohmann::json::array();
  for (const auto& [curve, d] : nearest_curves(reference.boundary, found)) {
    nlohmann::json t = {{"nearest_curve", curve}};
    if (curve >= 0) t["hausdorff"] = d, t["hausdorff_rel_diag"] = d / diagonal;
    truth.push_back(t);
  }
  const auto back = nearest_curves(found, reference.boundary);
  for (std::size_t i = 0; i < back.size(); ++i) {
    curves[i]["nearest_true_loop"] = back[i].first;
    if (back[i].first >= 0)
      curves[i]["hausdorff_to_true_loop"] = back[i].second, curves[i]["hausdorff_to_true_loop_rel_diag"] = back[i].second / diagonal;
  }
  nlohmann::json j = {{"true_loops", truth}};
  if (!reference.boundary.empty()) {
    // How far the samples leave the true boundary: no curve through them can come closer.
    const auto gap = distance::curves_to_points(reference.boundary, loaded.samples.points, 1e-4 * diagonal);
    j["samples_gap"] = {{"max", gap.max}, {"max_rel_diag", gap.max / diagonal}};
  }
  return j;
}

void print_text(const nlohmann::json& j) {
  std::cout << std::setprecision(4) << j["input"].get<std::string>() << ": " << j["points"] << " points, "
            << j["curves"].size() << " boundary curve" << (j["curves"].size() == 1 ? "" : "s");
  if (j.contains("spacing")) std::cout << " (average spacing " << j["spacing"].get<double>() << ")";
  if (j.contains("dropped_loops"))
    std::cout << ", " << j["dropped_loops"] << " loops dropped, " << j["closed_inlets"] << " inlets closed";
  std::cout << "\n";
  for (std::size_t i = 0; i < j["curves"].size(); ++i) {
    const auto& c = j["curves"][i];
    std::cout << "  curve " << i << ": " << c["vertices"] << " vertices, length " << c["length"].get<double>() << " ("
              << percent(c["length_rel_diag"].get<double>()) << " of the diagonal)";
    if (c.contains("knot")) std::cout << ", " << c["knot"].get<std::string>();
    if (c.contains("width_local_spacings"))
      std::cout << ", width " << std::setprecision(3) << c["width_local_spacings"].get<double>() << " local spacings"
                << std::setprecision(4);
    if (c.contains("nearest_true_loop") && c["nearest_true_loop"].get<int>() >= 0)
      std::cout << ", within " << percent(c["hausdorff_to_true_loop_rel_diag"].get<double>())
                << " of true loop " << c["nearest_true_loop"];
    std::cout << "\n";
  }
  if (j.contains("reference")) {
    const auto& r = j["reference"];
    for (std::size_t i = 0; i < r["true_loops"].size(); ++i) {
      const auto& t = r["true_loops"][i];
      std::cout << "  true loop " << i << ": ";
      if (t["nearest_curve"].get<int>() < 0)
        std::cout << "no curve found\n";
      else
        std::cout << "nearest curve " << t["nearest_curve"] << ", Hausdorff " << percent(t["hausdorff_rel_diag"].get<double>())
                  << " of the diagonal\n";
    }
    if (r.contains("samples_gap"))
      std::cout << "  the samples leave the true boundary up to " << percent(r["samples_gap"]["max_rel_diag"].get<double>())
                << " of the diagonal from the nearest of them\n";
  }
  for (const auto& note : j["notes"]) std::cout << "  note: " << note.get<std::string>() << "\n";
}

void run_boundary(BoundaryCommand& cmd) {
  if (!cmd.output.empty()) check_curve_output(cmd.output);
  if (!cmd.points_output.empty()) io::check_output_path(cmd.points_output, io::OutputKind::Points);
  const std::vector<std::pair<std::string, std::string>> outputs = {{"-o", cmd.output},
                                                                    {"--points-out", cmd.points_output}};
  check_distinct_outputs(outputs);
  std::vector<std::pair<std::string, std::string>> inputs = {{"input", cmd.input}, {"--reference", cmd.reference}};
  for (const auto& f : cmd.sampling.boundary_files) inputs.emplace_back("--boundary", f);
  check_outputs_are_not_inputs(inputs, outputs);
  const auto thread_limit = limit_threads(cmd.common.threads);
  cmd.sampling.builtin_as_points = true;
  std::optional<analysis::Reference> reference;
  if (!cmd.reference.empty()) {
    reference = load_reference(cmd.reference);
  } else if (is_parametric_spec(cmd.input)) {
    reference = load_reference(cmd.input, cmd.sampling.join);
  }
  const Progress progress = terminal_progress(cmd.common.quiet || cmd.common.json);
  const LoadedSurface loaded = load_surface(cmd.input, cmd.sampling, progress);
  if (reference) reference = in_samples_frame(std::move(*reference), loaded.origin);
  // Distances in fractions of the reference's diagonal when there is one, as analyze gives them.
  const double diagonal = reference && reference->mesh   ? mesh::bbox_diagonal(reference->mesh->vertices)
                          : reference && !reference->points.empty() ? mesh::bbox_diagonal(reference->points)
                                                                    : mesh::bbox_diagonal(loaded.samples.points);
  std::vector<std::string> notes = loaded.notes;
  nlohmann::json j = {{"input", cmd.input}, {"source", loaded.source}, {"points", loaded.samples.points.size()},
                      {"diagonal", diagonal}};
  j["curves"] = curves_json(loaded, diagonal, !cmd.no_knots, notes);
  j["notes"] = notes;
  if (loaded.detection) {
    j["spacing"] = loaded.detection->spacing;
    j["dropped_loops"] = loaded.detection->dropped_loops;
    j["closed_inlets"] = loaded.detection->closed_inlets;
    std::size_t flagged = 0;
    for (const bool b : loaded.detection->is_boundary_point) flagged += b;
    j["boundary_points"] = flagged;
  }
  if (reference) {
    j["reference"] = reference_json(*reference, loaded, diagonal, j["curves"]);
    j["reference"]["file"] = cmd.reference.empty() ? cmd.input : cmd.reference;
  }
  if (!cmd.output.empty()) j["files"] = write_curves(cmd.output, in_input_frame(loaded.samples.boundary, loaded.origin));
  if (!cmd.points_output.empty()) {
    PointSet flagged;
    if (loaded.detection) {
      const auto& d = *loaded.detection;
      for (std::size_t i = 0; i < d.is_boundary_point.size(); ++i) {
        if (!d.is_boundary_point[i]) continue;
        flagged.points.push_back(loaded.samples.points[i]);
        flagged.normals.push_back(d.conormals[i]);
      }
    }
    io::write_points(cmd.points_output, in_input_frame(std::move(flagged), loaded.origin));
    j["points_file"] = cmd.points_output;
  }
  if (cmd.common.json) {
    print_json(j);
  } else if (!cmd.common.quiet) {
    print_text(j);
  }
}

}  // namespace

void register_boundary(CLI::App& app) {
  auto cmd = std::make_shared<BoundaryCommand>();
  CLI::App* sub = app.add_subcommand(
      "boundary", "Find the boundary curves of a point cloud (as reconstruct does) and report them, alone");
  sub->add_option("input", cmd->input,
                  "A point file (.xyz/.pts/.txt/.csv/.ply/.las; normals optional), builtin:NAME or a NURBS file (.igs/.iges/.json, one patch or several; sampled "
                  "without its normals and boundary, which are then estimated), or a mesh (its border loops)")
      ->required();
  sub->add_option("-o,--output", cmd->output,
                  "Write the curves: .polyline, one closed curve per file (FILE.i.polyline when several), or "
                  ".xyz/.ply, all vertices as one point file with their outward conormals (reconstruct "
                  "--boundary reads both back)");
  sub->add_option("--points-out", cmd->points_output,
                  "Write the samples the curves were fitted to (.xyz/.ply, normals = their outward conormals)");
  sub->add_option("-r,--reference", cmd->reference,
                  "True boundary to compare with: builtin:NAME, a NURBS file or a mesh (its border loops); "
                  "builtin and NURBS inputs default to their own surface");
  sub->add_flag("--no-knots", cmd->no_knots, "Skip the knot type of each curve (as analyze --no-knots)");
  sub->add_option("-n,--count", cmd->sampling.count, "Points drawn from builtin:NAME and NURBS inputs")
      ->capture_default_str()
      ->check(whole_number_in(1, kMaxPointCount));
  sub->add_option("--noise", cmd->sampling.noise_rel_diag, "Gaussian noise on builtin:NAME and NURBS samples, fraction of the diagonal")
      ->capture_default_str()
      ->check(number_above(0, true));
  sub->add_option("--seed", cmd->sampling.seed, "Seed of builtin sampling")->check(seed_number())->capture_default_str();
  add_boundary_options(*sub, cmd->sampling);
  add_outlier_options(*sub, cmd->sampling);
  add_crease_options(*sub, cmd->sampling);
  add_join_option(*sub, cmd->sampling.join);
  add_common_flags(*sub, cmd->common);
  add_threads_option(*sub, cmd->common.threads);
  sub->callback([cmd] { run_boundary(*cmd); });
}

}  // namespace envcrust::cli
