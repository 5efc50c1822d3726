// `envcrust powercrust`: the Power Crust of a point set, with its medial axis and poles.
#include "cli_common.h"
#include "commands.h"
#include "inputs.h"
#include "surface_input.h"

#include "envcrust/errors.h"
#include "envcrust/io.h"
#include "envcrust/pipeline.h"
#include "envcrust/power_crust.h"
#include "envcrust/topology.h"

#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace envcrust::cli {
namespace {

struct PowerCrustCommand {
  std::string input;
  std::string output;
  std::string medial_axis_output;
  std::string poles_output;
  InputSettings sampling;
  powercrust::PowerCrustOptions options;
  bool keep_unknown = false;
  CommonFlags common;
};

std::vector<Point3> load_points(const PowerCrustCommand& cmd) {
  if (is_parametric_spec(cmd.input)) return load_surface(cmd.input, cmd.sampling).samples.points;
  return io::read_points(cmd.input).points;
}

std::string label_name(powercrust::PoleLabel label) {
  switch (label) {
    case powercrust::PoleLabel::In: return "in";
    case powercrust::PoleLabel::Out: return "out";
    default: return "unknown";
  }
}

void run_powercrust(PowerCrustCommand& cmd) {
  io::check_output_path(cmd.output, io::OutputKind::Mesh);
  if (!cmd.medial_axis_output.empty()) io::check_output_path(cmd.medial_axis_output, io::OutputKind::Mesh);
  if (!cmd.poles_output.empty()) io::check_output_path(cmd.poles_output, io::OutputKind::Text);
  const std::vector<std::pair<std::string, std::string>> outputs = {
      {"-o", cmd.output}, {"--medial-axis", cmd.medial_axis_output}, {"--poles", cmd.poles_output}};
  check_distinct_outputs(outputs);
  check_outputs_are_not_inputs({{"input", cmd.input}}, outputs);
  const auto thread_limit = limit_threads(cmd.common.threads);
  cmd.options.resolve_unknown = !cmd.keep_unknown;
  cmd.options.build_power_shape = !cmd.medial_axis_output.empty();
  const auto points = load_points(cmd);
  // The engine names the problem (too few distinct points, coplanar); the message names the file.
  const auto result = naming_input(cmd.input, [&] {
    return powercrust::power_crust(points, cmd.options, terminal_progress(cmd.common.quiet || cmd.common.json));
  });
  if (result.crust.triangles.empty())
    throw InvalidInput(cmd.input + ": the Power Crust has no face (" + std::to_string(result.stats.input_points) +
                       " points, " + std::to_string(result.stats.inner_poles) + " inner and " +
                       std::to_string(result.stats.outer_poles) +
                       " outer poles): the samples are too few or too sparse for a closed surface; nothing written");
  io::write_mesh(cmd.output, result.crust);
  if (!cmd.medial_axis_output.empty()) io::write_mesh(cmd.medial_axis_output, pipeline::power_shape_mesh(result));
  if (!cmd.poles_output.empty()) {
    io::BallSet poles;
    for (const auto& pole : result.poles) {
      poles.centres.push_back(pole.center);
      poles.radii.push_back(pole.radius);
      poles.labels.emplace_back(label_name(pole.label));
    }
    io::write_balls(cmd.poles_output, poles);
  }
  const auto& s = result.stats;
  const auto crust = topology::analyze_topology(result.crust);
  nlohmann::json j = {
      {"input", cmd.input}, {"output", cmd.output}, {"input_points", s.input_points},
      {"duplicate_points", s.duplicate_points}, {"delaunay_cells", s.delaunay_cells}, {"poles", s.poles},
      {"inner_poles", s.inner_poles}, {"outer_poles", s.outer_poles}, {"unknown_poles", s.unknown_poles},
      {"resolved_unknown_poles", s.resolved_unknown_poles}, {"hidden_poles", s.hidden_poles},
      {"filtered_poles", s.filtered_poles}, {"bad_second_poles", s.bad_second_poles},
      {"bad_poles_left_out", s.bad_poles_left_out}, {"deferred_poles", s.deferred_poles},
      {"crust_faces", s.crust_faces},
      {"crust", {{"euler_characteristic", crust.euler_characteristic}, {"is_closed", crust.is_closed()},
                 {"is_manifold", crust.is_manifold()}, {"components", crust.components.size()},
                 {"misoriented_edges", crust.misoriented_edges}}},
      {"seconds", {{"delaunay", s.seconds_delaunay}, {"poles", s.seconds_poles},
                   {"power_diagram", s.seconds_power_diagram}, {"labeling", s.seconds_labeling},
                   {"crust", s.seconds_crust}, {"power_shape", s.seconds_power_shape}}},
      {"warnings", result.warnings}};
  if (cmd.common.json) {
    print_json(j);
    return;
  }
  if (cmd.common.quiet) return;
  std::cout << "power crust of " << cmd.input << ": " << s.input_points << " points (" << s.duplicate_points
            << " duplicates merged), " << s.poles << " poles (" << s.inner_poles << " in, " << s.outer_poles
            << " out, " << s.unknown_poles << " unknown"
            << (s.filtered_poles > 0 ? ", " + std::to_string(s.filtered_poles) + " below --min-pole-radius left out"
                                     : std::string())
            << (s.bad_second_poles > 0 ? ", " + std::to_string(s.bad_second_poles) +
                                             " second poles nearer than the --sampling-estimate bound (" +
                                             std::to_string(s.bad_poles_left_out) + " poles left out)"
                                       : std::string())
            << "), " << s.crust_faces << " crust triangles\n"
            << "  crust: chi " << crust.euler_characteristic << ", " << (crust.is_closed() ? "closed" : "open")
            << ", " << (crust.is_manifold() ? "manifold" : "non-manifold") << "\n"
            << "  seconds: delaunay " << s.seconds_delaunay << ", poles " << s.seconds_poles << ", power diagram "
            << s.seconds_power_diagram << ", labeling " << s.seconds_labeling << ", crust " << s.seconds_crust
            << (cmd.options.build_power_shape ? ", power shape " + std::to_string(s.seconds_power_shape) : std::string())
            << "\n";
  for (const auto& w : result.warnings) std::cout << "  warning: " << w << "\n";
}

}  // namespace

void register_powercrust(CLI::App& app) {
  auto cmd = std::make_shared<PowerCrustCommand>();
  CLI::App* sub = app.add_subcommand("powercrust", "Run the Power Crust on a point set (closed surfaces)");
  sub->add_option("input", cmd->input, "Point file (.xyz/.pts/.txt/.csv/.ply, or a mesh's vertices), or builtin:NAME or a NURBS file (.igs/.iges/.json, one patch or several), sampled")
      ->required();
  sub->add_option("-o,--output", cmd->output, "Crust mesh (.ply/.off/.obj)")->required();
  add_threads_option(*sub, cmd->common.threads);
  sub->add_option("--medial-axis", cmd->medial_axis_output, "Write the inner power shape's triangles as a mesh");
  sub->add_option("--poles", cmd->poles_output, "Write the poles (polar balls): .ply with x y z radius and a label code (0 unknown, 1 in, 2 out), any "
                  "other name as text lines 'x y z radius in|out|unknown' (both read by render --balls)");
  sub->add_option("-n,--count", cmd->sampling.count, "Points drawn from builtin:NAME and NURBS inputs")
      ->capture_default_str()
      ->check(whole_number_in(1, kMaxPointCount));
  sub->add_option("--seed", cmd->sampling.seed, "Seed of builtin sampling")->check(seed_number())->capture_default_str();
  add_join_option(*sub, cmd->sampling.join);
  const std::map<std::string, powercrust::LabelPreset> presets = {{"code", powercrust::LabelPreset::Code},
                                                                  {"readme", powercrust::LabelPreset::Readme}};
  sub->add_option("--preset", cmd->options.preset,
                  "Labeling thresholds: 'code' (0/0, what the original program runs) or 'readme' (0.4/0.3 and --sampling-estimate 0.6, what its README gives)")
      ->transform(CLI::CheckedTransformer(presets, CLI::ignore_case));
  sub->add_option("--neighbor-threshold", cmd->options.neighbor_threshold,
                  "Neighbour-rule threshold on the ball intersection angle (original -t), overrides the preset")
      ->check(number_in(-1, 1, true, true));
  sub->add_option("--second-pass-threshold", cmd->options.second_pass_threshold,
                  "Second-pass threshold (original -w), overrides the preset")
      ->check(number_in(-1, 1, true, true));
  sub->add_option("--box-scale", cmd->options.bounding_box_scale,
                  "Half-width of the bounding cube in largest extents of the input")
      ->capture_default_str()
      ->check(number_in(1, 1000, false, true));
  sub->add_option("--pole-joggle", cmd->options.pole_joggle,
                  "Move each pole by up to this fraction of the smaller of its radius and the input's box diagonal "
                  "(deterministic) before the power diagram, so exact samples (sphere, torus) do not put the poles "
                  "in degenerate position; 0: off")
      ->capture_default_str()
      ->check(number_in(0, 0.01, true, true));
  sub->add_option("--min-pole-radius", cmd->options.min_pole_radius_rel_spacing,
                  "Noisy input: leave out poles whose radius is below this many local sample spacings (median "
                  "nearest-neighbour distance around the sample), which noise makes and the labeling gets wrong "
                  "(handles, bubbles); 3 suits 0.1% noise; 0: off, as the original")
      ->check(number_in(0, 100, true, true))
      ->capture_default_str();
  sub->add_option("--sampling-estimate", cmd->options.sampling_estimate,
                  "The original's -R r (the input an r-sample): a second pole nearer to its sample than the "
                  "local-feature-size bound the Voronoi vertices near the tangent plane give is left out and not "
                  "paired (default: 1 = off, as the original runs; 0.6 with --preset readme)")
      ->check(number_in(0, 1, false, true));
  sub->add_flag("--drop-bad-pole-pairs", cmd->options.drop_both_bad_poles,
                "With --sampling-estimate below 1: a sample with a bad second pole loses its first pole too "
                "(the original's -B)");
  sub->add_flag("--defer-bad-first-poles", cmd->options.defer_bad_first_poles,
                "With --sampling-estimate below 1: the first poles of samples with a bad second pole are labeled "
                "last, by the second pass (the original's -D, advised for open surfaces)");
  sub->add_flag("--keep-unknown", cmd->keep_unknown,
                "Leave poles the labeling could not decide unlabeled, as the original does (may open the crust)");
  add_common_flags(*sub, cmd->common);
  sub->callback([cmd] { run_powercrust(*cmd); });
}

}  // namespace envcrust::cli
