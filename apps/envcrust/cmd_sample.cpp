// `envcrust sample`: points or an exact tessellation of a built-in surface or NURBS patch, and the list.
#include "cli_common.h"
#include "commands.h"
#include "curve_output.h"
#include "inputs.h"
#include "surface_input.h"

#include "envcrust/io.h"
#include "envcrust/surfaces.h"

#include <iostream>
#include <memory>

namespace envcrust::cli {
namespace {

struct SampleCommand {
  std::string surface;
  std::string output;
  surfaces::SampleOptions sampling;
  bool mesh = false;
  bool list = false;
  std::string boundary_output;
  models::JoinOptions join;
  CommonFlags common;
};

nlohmann::json expected_json(const surfaces::ExpectedTopology& t) {
  return {{"euler_characteristic", t.euler_characteristic},
          {"boundary_loops", t.boundary_loops},
          {"orientable", t.is_orientable},
          {"boundary_knots", t.boundary_knots},
          {"abs_linking_number", t.abs_linking_number}};
}

void list_surfaces(const SampleCommand& cmd) {
  nlohmann::json all = nlohmann::json::array();
  for (const auto& name : surfaces::builtin_names()) {
    const auto s = surfaces::make_builtin(name);
    all.push_back({{"name", name}, {"description", s->description()},
                   {"expected", expected_json(s->expected_topology())}});
  }
  if (cmd.common.json) {
    print_json(all);
    return;
  }
  for (const auto& entry : all) {
    const auto& e = entry["expected"];
    std::string knots;
    for (const auto& k : e["boundary_knots"]) {
      if (!knots.empty()) knots += ',';
      knots += k.get<std::string>();
    }
    std::cout << entry["name"].get<std::string>() << "\n    " << entry["description"].get<std::string>()
              << "\n    chi " << e["euler_characteristic"] << ", " << e["boundary_loops"]
              << " boundary loops, " << (e["orientable"].get<bool>() ? "orientable" : "non-orientable");
    if (!knots.empty()) std::cout << ", boundary knots " << knots;
    if (e["boundary_loops"].get<int>() > 1) std::cout << ", |lk| " << e["abs_linking_number"];
    std::cout << "\n";
  }
}

void run_sample(const SampleCommand& cmd) {
  if (cmd.list) {
    list_surfaces(cmd);
    return;
  }
  if (cmd.surface.empty()) throw UsageError("sample: a SURFACE is required (see --list)");
  if (cmd.output.empty() && cmd.boundary_output.empty())
    throw UsageError("sample: an output file is required (-o OUT)");
  if (!cmd.output.empty()) io::check_output_path(cmd.output, cmd.mesh ? io::OutputKind::Mesh : io::OutputKind::Points);
  if (!cmd.boundary_output.empty()) io::check_output_path(cmd.boundary_output, io::OutputKind::Polyline);
  check_distinct_outputs({{"-o", cmd.output}, {"--boundary-out", cmd.boundary_output}});
  if (is_parametric_spec(cmd.surface) && !is_builtin_spec(cmd.surface))  // a NURBS file
    check_outputs_are_not_inputs({{"surface", cmd.surface}}, {{"-o", cmd.output}, {"--boundary-out", cmd.boundary_output}});
  const auto model = parametric_model(is_parametric_spec(cmd.surface) ? cmd.surface : "builtin:" + cmd.surface, cmd.join);
  nlohmann::json report = {{"surface", cmd.surface}};
  if (!cmd.output.empty()) {
    if (cmd.mesh) {
      const TriangleMesh& mesh = model->truth();
      io::write_mesh(cmd.output, mesh);
      report["mesh"] = {{"file", cmd.output}, {"vertices", mesh.vertices.size()},
                        {"triangles", mesh.triangles.size()}};
    } else {
      const PointSet points = model->sample(cmd.sampling);
      io::write_points(cmd.output, points);
      report["points"] = {{"file", cmd.output}, {"count", points.size()},
                          {"normals", points.has_normals()}, {"seed", cmd.sampling.seed},
                          {"noise_rel_diag", cmd.sampling.noise_rel_diag}};
    }
  }
  if (!cmd.boundary_output.empty()) {
    // All loops in one file, one point per line, loops separated by blank lines is not a
    // format our readers take back: write one file per loop instead (NAME.0.polyline, ...).
    const auto curves = model->boundary_curves(2e-3 * model->diagonal());
    const auto paths = numbered_paths(cmd.boundary_output, curves.size());
    nlohmann::json files = nlohmann::json::array();
    for (std::size_t i = 0; i < curves.size(); ++i) {
      io::write_polyline(paths[i], curves[i].polyline());
      files.push_back(paths[i]);
    }
    report["boundary_files"] = files;
  }
  report["expected"] = expected_json(model->expected_topology());
  if (model->patch_count() > 1) {
    report["patches"] = model->patch_count();
    report["joins"] = {{"joined_edges", model->joins().joined_edges}, {"largest_gap", model->joins().largest_gap},
                       {"tolerance", model->joins().tolerance}, {"near_misses", model->joins().near_misses},
                       {"nearest_miss", model->joins().nearest_miss}};
  }
  if (cmd.common.json) {
    print_json(report);
  } else if (!cmd.common.quiet) {
    if (report.contains("points"))
      std::cout << "wrote " << report["points"]["count"] << " points of " << cmd.surface << " to "
                << cmd.output << "\n";
    if (report.contains("mesh"))
      std::cout << "wrote the tessellation of " << cmd.surface << " (" << report["mesh"]["vertices"]
                << " vertices, " << report["mesh"]["triangles"] << " triangles) to " << cmd.output << "\n";
    if (report.contains("boundary_files"))
      for (const auto& f : report["boundary_files"]) std::cout << "wrote boundary loop " << f.get<std::string>() << "\n";
  }
}

}  // namespace

void register_sample(CLI::App& app) {
  auto cmd = std::make_shared<SampleCommand>();
  CLI::App* sub = app.add_subcommand(
      "sample", "Sample a built-in surface or a NURBS file uniformly by area, or write its exact tessellation");
  sub->add_option("surface", cmd->surface, "Built-in surface name (see --list), or a NURBS file (.igs/.iges IGES entities 128/144, .json NURBS-Python; several patches are joined into one model)");
  sub->add_option("-o,--output", cmd->output, "Output file (.xyz/.ply points; .ply/.off/.obj with --mesh)");
  auto* count = sub->add_option("-n,--count", cmd->sampling.count, "Number of points")
                    ->capture_default_str()
                    ->check(whole_number_in(1, kMaxPointCount));
  auto* noise = sub->add_option("--noise", cmd->sampling.noise_rel_diag,
                                "Gaussian noise sigma as a fraction of the bounding-box diagonal (0.0025 = 0.25%)")
                    ->capture_default_str();
  auto* normals = sub->add_flag("--normals", cmd->sampling.with_normals, "Write the exact unit normals too");
  auto* seed = sub->add_option("--seed", cmd->sampling.seed, "Random seed (same seed, same points)")->check(seed_number())->capture_default_str();
  sub->add_flag("--mesh", cmd->mesh, "Write the exact fine tessellation (ground truth) instead of points")
      ->excludes(count)
      ->excludes(noise)
      ->excludes(normals)
      ->excludes(seed);
  sub->add_option("--boundary-out", cmd->boundary_output,
                  "Write the true boundary loops as polylines (FILE.i.polyline when several)");
  add_join_option(*sub, cmd->join);
  sub->add_flag("--list", cmd->list, "List the built-in surfaces with their expected topology");
  add_common_flags(*sub, cmd->common);
  sub->callback([cmd] { run_sample(*cmd); });
}

}  // namespace envcrust::cli
