// `envcrust analyze`: topology, boundary knots, linking and distances of a mesh; or the knot
// type of a lone curve (--curve).
#include "analysis_output.h"
#include "cli_common.h"
#include "commands.h"
#include "inputs.h"
#include "html_output.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"

#include <cstdint>
#include <iostream>
#include <memory>

namespace envcrust::cli {
namespace {

struct AnalyzeCommand {
  std::string mesh;
  std::string reference;
  std::string curve;
  std::string report_file;
  std::string html_file;
  bool no_knots = false;
  analysis::AnalyzeOptions options;
  CommonFlags common;
};

void run_curve(const AnalyzeCommand& cmd) {
  const Polyline curve = io::read_polyline(cmd.curve);
  const auto knot = [&] {  // the knot stage names the problem, the message names the file
    try {
      return analysis::analyze_curve(curve, cmd.options);
    } catch (const NumericalFailure& e) {
      throw NumericalFailure(cmd.curve + ": " + e.what());
    }
  }();
  nlohmann::json j = {{"curve", cmd.curve}, {"vertices", curve.size()}, {"knot", knot_json(knot)}};
  if (!cmd.report_file.empty()) io::write_text(cmd.report_file, json_text(j));
  if (cmd.common.json) {
    print_json(j);
  } else if (!cmd.common.quiet) {
    if (knot.type == knots::KnotType::Unknown)
      std::cout << cmd.curve << ": " << curve.size() << " vertices, " << knot_text(knot) << "\n";
    else
      std::cout << cmd.curve << ": " << curve.size() << " vertices, " << knots::to_string(knot.type)
                << " (Alexander polynomial " << knot.alexander << ", determinant " << knot.determinant
                << ", " << knot.crossings << " crossings after simplification to "
                << knot.simplified_vertices << " vertices"
                << (knot.projections_agree ? "" : "; projections disagreed") << ")\n";
  }
}

// Runs a step on the mesh; with --html, a mesh it refuses still gets a page saying why (and
// showing what could be read of it: `mesh`, else its vertices as points), then the error
// ends the run as without --html.
template <class Step>
auto with_failure_page(const AnalyzeCommand& cmd, const std::string& title, const TriangleMesh* mesh, Step&& step) {
  try {
    return step();
  } catch (const Error& e) {
    if (cmd.html_file.empty()) throw;
    TriangleMesh points_only;
    if (!mesh && !is_parametric_spec(cmd.mesh)) {
      try {
        points_only.vertices = io::read_points(cmd.mesh).points;
      } catch (const Error&) {
        // Not even points: the page shows the message alone.
      }
      mesh = &points_only;
    }
    html::write_html_report(cmd.html_file, html::failure_page(title, mesh, e.what()));
    throw;
  }
}

void run_analyze(AnalyzeCommand& cmd) {
  if (!cmd.report_file.empty()) io::check_output_path(cmd.report_file, io::OutputKind::Text);
  html::check_html_output(cmd.html_file);
  check_distinct_outputs({{"--report", cmd.report_file}, {"--html", cmd.html_file}});
  check_outputs_are_not_inputs({{"mesh", cmd.mesh}, {"--reference", cmd.reference}, {"--curve", cmd.curve}},
                               {{"--report", cmd.report_file}, {"--html", cmd.html_file}});
  const auto thread_limit = limit_threads(cmd.common.threads);
  if (!cmd.curve.empty()) {
    if (!cmd.mesh.empty()) throw UsageError("analyze: give either MESH or --curve, not both");
    if (!cmd.html_file.empty()) throw UsageError("analyze: --html shows a MESH, not a --curve");
    run_curve(cmd);
    return;
  }
  if (cmd.mesh.empty()) throw UsageError("analyze: a MESH (or --curve CURVE) is required");
  cmd.options.use_knots = !cmd.no_knots;
  if (!is_parametric_spec(cmd.mesh) && io::is_text_point_file(cmd.mesh)) {
    throw IoError(cmd.mesh + ": a point file, not a mesh: analyze reads meshes (.ply, .off, .obj, .stl); "
                  "reconstruct it first, or give it as --reference, or as --curve if it is an ordered closed curve");
  }
  const std::string title = "envcrust analyze: " + cmd.mesh;
  const TriangleMesh mesh = with_failure_page(cmd, title, nullptr, [&] { return load_mesh(cmd.mesh); });
  analysis::Reference reference;
  if (!cmd.reference.empty()) reference = load_reference(cmd.reference);
  const auto report =
      with_failure_page(cmd, title, &mesh, [&] { return analysis::analyze_mesh(mesh, reference, cmd.options); });
  nlohmann::json j = analysis_json(report);
  j["mesh"] = cmd.mesh;
  if (!cmd.reference.empty()) j["reference"] = cmd.reference;
  if (!cmd.report_file.empty()) io::write_text(cmd.report_file, json_text(j));
  if (!cmd.html_file.empty())
    html::write_html_report(cmd.html_file, html::analyze_page(title, mesh, report, reference, cmd.reference, j));
  if (cmd.common.json) {
    print_json(j);
  } else if (!cmd.common.quiet) {
    print_analysis(std::cout, cmd.mesh, report);
  }
}

}  // namespace

void register_analyze(CLI::App& app) {
  auto cmd = std::make_shared<AnalyzeCommand>();
  CLI::App* sub = app.add_subcommand(
      "analyze",
      "Report a mesh's topology (manifoldness, Euler characteristic, orientability, genus,\n"
      "boundary loops with knot types, linking numbers) and, with --reference, its distances");
  sub->add_option("mesh", cmd->mesh, "Mesh file (.ply/.off/.obj/.stl), builtin:NAME, or a NURBS file (.igs/.iges/.json, one patch or several; its tessellation)");
  sub->add_option("-r,--reference", cmd->reference,
                  "Reference: mesh file, point file, builtin:NAME or a NURBS file (.igs/.iges/.json, one patch or several) (its fine tessellation, chord error below 1e-4 of the diagonal, and boundary curves)");
  sub->add_option("--curve", cmd->curve,
                  "Analyze the knot type of one closed polyline (.polyline/.xyz) instead of a mesh");
  sub->add_option("--report", cmd->report_file, "Also write the JSON report to this file");
  html::add_html_option(*sub, cmd->html_file,
                        "the mesh (a mesh it cannot analyze gets a page saying why); with --reference, each vertex "
                        "coloured by its distance to the reference");
  sub->add_option("--samples", cmd->options.distance.samples,
                  "Area samples per side for distance measurement")
      ->capture_default_str()
      ->check(whole_number_in(0, kMaxPointCount));
  sub->add_option("--seed", cmd->options.distance.seed, "Seed of the distance sampling")->check(seed_number())->capture_default_str();
  sub->add_option("--knot-seed", cmd->options.knot.seed, "Seed of the knot projections")->check(seed_number())->capture_default_str();
  sub->add_option("--projections", cmd->options.knot.projections,
                  "Projections voted over for knot types")
      ->capture_default_str()
      ->check(whole_number_at_least(1));
  sub->add_flag("--no-knots", cmd->no_knots, "Skip knot types and linking numbers of boundary loops");
  sub->add_flag("--no-self-intersections", [cmd](std::int64_t) { cmd->options.use_self_intersections = false; },
                "Skip the search for faces that pass through each other (a few seconds per million faces)");
  add_common_flags(*sub, cmd->common);
  add_threads_option(*sub, cmd->common.threads);
  sub->callback([cmd] { run_analyze(*cmd); });
}

}  // namespace envcrust::cli
