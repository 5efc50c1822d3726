// `envcrust reconstruct` (the main job) and `envcrust envelope` (the envelope samples alone).
#include "analysis_output.h"
#include "boundary_check_output.h"
#include "cli_common.h"
#include "commands.h"
#include "curve_output.h"
#include "html_output.h"
#include "input_frame.h"
#include "inputs.h"
#include "output_vertex_data.h"
#include "reconstruct_hints.h"
#include "reconstruct_output.h"
#include "rho_support.h"
#include "surface_input.h"

#include "envcrust/distance.h"
#include "envcrust/errors.h"
#include "envcrust/heap.h"
#include "envcrust/io.h"
#include "envcrust/mesh.h"
#include "envcrust/pipeline.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

namespace envcrust::cli {
namespace {

struct ReconstructCommand {
  std::string input;
  std::string output;
  std::string rho = "auto";
  std::string envelope_output;
  std::string boundary_output;
  std::string outliers_output;
  std::string reference;
  std::string report_file;
  std::string html_file;
  bool no_analysis = false;
  bool no_adaptive_retry = false;
  bool no_power_crust_fallback = false;
  bool use_remesh = false;
  bool force = false;  // --force: run a rho the sampling cannot support
  remesh::RemeshOptions remesh;  // used with --remesh
  std::string extract;                // --extract: samples, sheet or powershape; empty: by input
  std::string orientable = "auto";    // --orientable: auto, yes or no
  std::optional<double> cut_handles;  // --cut-handles; unset: by input (choose_input_options)
  InputSettings sampling;
  pipeline::ReconstructOptions options;
  CommonFlags common;
};

std::optional<double> parse_rho(const std::string& text) {
  if (text == "auto") return std::nullopt;
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size() && value > 0 && std::isfinite(value)) return value;
  } catch (const std::exception&) {
  }
  throw UsageError("--rho must be 'auto' or a positive number (got '" + text + "')");
}

void add_input_options(CLI::App& sub, ReconstructCommand& cmd) {
  sub.add_option("input", cmd.input, "builtin:NAME, a NURBS file (.igs/.iges IGES entities 128/144, .json NURBS-Python; several patches are joined into one model), a point file (.xyz/.pts/.txt/.csv/.ply/.las; normals optional), or a mesh (.off/.obj/.stl/.ply)")
      ->required();
  sub.add_option("--rho", cmd.rho,
                 "Envelope radius: 'auto' (half the estimated reach, the reach taken as at most 10% of the "
                 "diagonal and --rho-width-cap times the surface's half-width, then raised to bridge the gaps "
                 "of --rho-gap-quantile of the samples) or a value")
      ->capture_default_str();
  sub.add_option("--rho-width-cap", cmd.options.envelope.max_reach_rel_half_width,
                 "Automatic rho: the reach is taken as at most this many times the surface's half-width (the "
                 "largest distance from a sample to its boundary curves), so a narrow strip gets envelope "
                 "samples across it")
      ->capture_default_str()
      ->check(number_above(0));
  sub.add_option("--rho-gap-quantile", cmd.options.envelope.gap_quantile,
                 "Automatic rho is at least this quantile of the samples' 8th-neighbour distances / 2.5 "
                 "(0: half the reach only)")
      ->capture_default_str()
      ->check(number_in(0, 1, true, true));
  sub.add_option("--spacing", cmd.options.envelope.spacing_rel_rho,
                 "Envelope sample spacing as a fraction of rho")
      ->capture_default_str()
      ->check(number_in(0, 4, false, true));
  sub.add_option("-n,--count", cmd.sampling.count, "Points drawn from builtin:NAME and NURBS inputs")
      ->capture_default_str()
      ->check(whole_number_in(1, kMaxPointCount));
  sub.add_option("--noise", cmd.sampling.noise_rel_diag,
                 "Gaussian noise on builtin:NAME and NURBS samples, fraction of the diagonal")
      ->capture_default_str()
      ->check(number_above(0, true));
  sub.add_option("--seed", cmd.sampling.seed, "Seed of builtin sampling and envelope thinning")->check(seed_number())->capture_default_str();
  auto* no_boundary =
      sub.add_flag("--no-boundary", [&cmd](std::int64_t) { cmd.sampling.preparation.use_boundary_detection = false; },
                   "Point files: do not detect boundary curves (a closed surface)");
  add_boundary_options(sub, cmd.sampling)->excludes(no_boundary);
  sub.add_flag("--rho-adaptive",
               [&cmd](std::int64_t) { cmd.options.envelope.rho_mode = envelope::RhoMode::Adaptive; },
               "Vary rho with the local feature size: rho(p) = alpha lfs(p), clamped to "
               "[--rho-min-rel * rho, rho] (rho = --rho), Lipschitz --rho-lipschitz, and raised where the "
               "samples are sparse to bridge their local gaps");
  sub.add_option("--rho-alpha", cmd.options.envelope.adaptive_rho_rel_lfs,
                 "Adaptive rho: rho(p) = alpha * local reach")
      ->capture_default_str()
      ->check(number_in(0, 1, false, false));
  sub.add_option("--rho-min-rel", cmd.options.envelope.adaptive_min_rel_rho,
                 "Adaptive rho: smallest rho as a fraction of rho")
      ->capture_default_str()
      ->check(number_in(0, 1, false, true));
  sub.add_option("--rho-lipschitz", cmd.options.envelope.adaptive_lipschitz,
                 "Adaptive rho: Lipschitz constant along M")
      ->capture_default_str()
      ->check(number_in(0, 1, true, false));
  sub.add_flag("--rho-shrink-only", [&cmd](std::int64_t) { cmd.options.envelope.adaptive_gap_floor = false; },
               "Adaptive rho: only shrink with the local feature size (by default it also grows where the "
               "samples are sparse, to bridge their local gaps, also beyond --rho)");
  sub.add_option("--boundary-out", cmd.boundary_output,
                 "Also write the boundary curves used (detected or read): .polyline, one closed curve "
                 "per file (FILE.i.polyline when several), or .xyz/.ply, all vertices as one point file "
                 "(normals = outward conormals)");
  add_outlier_options(sub, cmd.sampling);
  add_classes_option(sub, cmd.sampling);
  add_crease_options(sub, cmd.sampling);
  add_join_option(sub, cmd.sampling.join);
  sub.add_option("--outliers-out", cmd.outliers_output,
                 "Also write the stray samples removed from a point file (.xyz/.ply; none: an empty file)");
  sub.add_flag("--force", cmd.force,
               "Run a given --rho even when the sampling cannot support it: below the rho that bridges the gaps "
               "of 99% of the samples (their 8th-neighbour distances / 2.5), or with an envelope predicted "
               "beyond 50 samples per input sample (at least 1 million, at most 5 million). Without it such a "
               "rho is refused before the run, naming one that passes");
  add_threads_option(sub, cmd.common.threads);
}

// A given uniform rho the input's sampling cannot support is refused before the run (in a
// fraction of a second, not after minutes and gigabytes), naming one that passes.
void check_rho(const ReconstructCommand& cmd, const LoadedSurface& loaded) {
  const auto& e = cmd.options.envelope;
  if (cmd.force || !e.rho || cmd.options.method != pipeline::Method::Envelope ||
      e.rho_mode != envelope::RhoMode::Uniform || loaded.samples.points.size() < 2)
    return;
  const RhoSupport support = rho_support(loaded.samples, *e.rho, e.spacing_rel_rho);
  if (!support.is_supported()) throw InvalidInput(rho_refusal(cmd.input, support));
}

void print_outliers_line(const LoadedSurface& loaded) {
  if (loaded.outliers.empty()) return;
  std::cout << "  input: " << loaded.outliers.size()
            << " stray samples removed (--outliers-out writes them, --keep-outliers keeps them)\n";
}

void write_outliers(const ReconstructCommand& cmd, const LoadedSurface& loaded) {
  if (cmd.outliers_output.empty()) return;
  PointSet removed;
  removed.points = loaded.outliers;
  io::write_points(cmd.outliers_output, in_input_frame(std::move(removed), loaded.origin));
}

// The options for the loaded input (pipeline::options_for_input: a scan's sheet cut at handles
// and to an orientable sheet, the 5th-percentile reach of estimated normals, the adaptive
// retry with automatic rho), then what was asked: --orientable yes/no, --cut-handles,
// --no-adaptive-retry. The cuts apply to the medial sheet only.
void choose_input_options(ReconstructCommand& cmd, const LoadedSurface& loaded) {
  cmd.options = pipeline::options_for_input(loaded.kind, cmd.options);
  if (cmd.extract == "samples") cmd.options.mesh_samples = interpolate::InterpolateOptions{};
  if (cmd.extract == "sheet") cmd.options.mesh_samples.reset();
  auto& sheet = cmd.options.sheet;
  if (cmd.orientable == "yes") {
    sheet.cut_to_orientable = true;
    sheet.orientable_max_twist_loop_rel_rho = std::numeric_limits<double>::infinity();
  } else if (cmd.orientable == "no") {
    sheet.cut_to_orientable = false;
  }
  if (cmd.cut_handles) sheet.cut_handles_rel_rho = *cmd.cut_handles;
  if (cmd.no_adaptive_retry)
    cmd.options.use_adaptive_retry = cmd.options.use_local_rho_first = cmd.options.use_power_crust_first = false;
  if (cmd.no_power_crust_fallback) cmd.options.use_power_crust_fallback = cmd.options.use_power_crust_first = false;
  // The envelope asked for is made: no Power Crust in its place before it.
  if (!cmd.envelope_output.empty()) cmd.options.use_power_crust_first = false;
  if (cmd.options.method == pipeline::Method::Envelope && cmd.options.extraction == pipeline::Extraction::Sheet) return;
  if (cmd.orientable == "yes" || cmd.cut_handles.value_or(0) > 0)
    throw UsageError("--orientable and --cut-handles apply to the medial sheet (--method envelope --extract sheet)");
  sheet.cut_to_orientable = false;
  sheet.cut_handles_rel_rho = 0;
}

// Why a run came out empty, for its error: rho too small for the input's gaps, the input too
// sparse for its size, or rho too large for it. Starts with the input's name and `what`.
std::string empty_result_reason(const ReconstructCommand& cmd, const LoadedSurface& loaded,
                                const envelope::EnvelopeSamples& e, const std::string& what) {
  std::ostringstream reason;
  reason << cmd.input << ": " << what;
  if (cmd.options.method == pipeline::Method::Envelope && e.rho < e.min_rho_for_gaps)
    reason << ": rho " << e.rho << " is too small for the input's gaps (up to " << e.input_coverage
           << "); use --rho " << e.min_rho_for_gaps << " or more, or input with gaps below "
           << e.input_coverage * e.rho / e.min_rho_for_gaps;
  else if (cmd.options.method == pipeline::Method::Envelope && e.is_input_too_sparse)
    reason << ": the input is too sparse or noisy for its size (rho " << e.rho
           << " is " << std::setprecision(3) << 100.0 * e.rho / mesh::bbox_diagonal(loaded.samples.points)
           << "% of its diagonal); sample it denser";
  else if (const double diagonal = mesh::bbox_diagonal(loaded.samples.points);
           cmd.options.method == pipeline::Method::Envelope && e.rho > 0.25 * diagonal)
    reason << ": rho " << e.rho << " is more than a quarter of the input's size (diagonal " << diagonal
           << "), so its envelope is one blob around it with no sheets to take apart; use a rho below "
           << 0.1 * diagonal << " (or leave --rho out: auto)";
  else if (cmd.options.method == pipeline::Method::Envelope)
    reason << ": no piece of the medial sheet held together (rho " << e.rho << ", " << e.samples.size()
           << " envelope samples from " << loaded.samples.points.size() << " input points); try denser input";
  return reason.str();
}

// Outputs checked before the run, not after minutes of it: known extensions, existing folders.
void check_outputs(const ReconstructCommand& cmd, io::OutputKind output_kind) {
  io::check_output_path(cmd.output, output_kind);
  if (!cmd.envelope_output.empty()) io::check_output_path(cmd.envelope_output, io::OutputKind::Points);
  if (!cmd.boundary_output.empty()) check_curve_output(cmd.boundary_output);
  if (!cmd.outliers_output.empty()) io::check_output_path(cmd.outliers_output, io::OutputKind::Points);
  if (!cmd.report_file.empty()) io::check_output_path(cmd.report_file, io::OutputKind::Text);
  html::check_html_output(cmd.html_file);
  const std::vector<std::pair<std::string, std::string>> outputs = {{"-o", cmd.output},
                                                                    {"--envelope-out", cmd.envelope_output},
                                                                    {"--boundary-out", cmd.boundary_output},
                                                                    {"--outliers-out", cmd.outliers_output},
                                                                    {"--report", cmd.report_file},
                                                                    {"--html", cmd.html_file}};
  check_distinct_outputs(outputs);
  std::vector<std::pair<std::string, std::string>> inputs = {{"input", cmd.input}, {"--reference", cmd.reference}};
  for (const auto& f : cmd.sampling.boundary_files) inputs.emplace_back("--boundary", f);
  check_outputs_are_not_inputs(inputs, outputs);
}

// After the outputs are written and the report printed: a result that fails its checks ends
// the run with kExitChecksFailed.
void throw_if_failed(const ReconstructCommand& cmd, const std::vector<std::string>& failed) {
  if (failed.empty()) return;
  std::string what;
  for (const auto& f : failed) what += (what.empty() ? "" : "; ") + f;
  throw ChecksFailed(cmd.output + " was written, but the result fails its checks: " + what);
}

void run_reconstruct(ReconstructCommand& cmd) {
  io::reuse_freed_memory();
  const auto thread_limit = limit_threads(cmd.common.threads);
  check_outputs(cmd, io::OutputKind::Mesh);
  cmd.options.envelope.rho = parse_rho(cmd.rho);
  cmd.options.envelope.seed = cmd.sampling.seed;
  if (cmd.use_remesh) cmd.options.remesh = cmd.remesh;
  const Progress progress = terminal_progress(cmd.common.quiet || cmd.common.json);
  const LoadedSurface loaded = load_surface(cmd.input, cmd.sampling, progress);
  choose_input_options(cmd, loaded);
  check_rho(cmd, loaded);
  // A reference that cannot be read fails now, not after the run.
  std::optional<analysis::Reference> given_reference;
  if (!cmd.reference.empty() && !cmd.no_analysis)
    given_reference = in_samples_frame(load_reference(cmd.reference), loaded.origin);
  auto result = naming_input(cmd.input, [&] { return pipeline::reconstruct(loaded.samples, cmd.options, progress); });
  if (result.mesh.triangles.empty())
    throw NumericalFailure(empty_result_reason(cmd, loaded, result.envelope, "the reconstruction is empty"));
  nlohmann::json j = {{"input", cmd.input}, {"output", cmd.output}, {"source", loaded.source},
                      {"input_points", loaded.samples.points.size()},
                      {"input_boundary_curves", loaded.samples.boundary.size()},
                      {"input_outliers_removed", loaded.outliers.size()},
                      {"notes", loaded.notes}};
  j.update(run_stages_json(result, cmd.options));
  j["threads"] = allowed_threads();
  if (loaded.kind.is_orientable) j["input_is_orientable"] = *loaded.kind.is_orientable;
  if (loaded.kind.genus) j["input_genus"] = *loaded.kind.genus;
  if (loaded.origin != CGAL::NULL_VECTOR) j["input_origin"] = {loaded.origin.x(), loaded.origin.y(), loaded.origin.z()};
  if (loaded.detection && !loaded.detection->loop_widths.empty())
    j["input_boundary_widths"] = loaded.detection->loop_widths;
  std::vector<std::string> warnings = loaded.warnings;
  warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
  std::optional<analysis::AnalysisReport> report;
  std::optional<double> boundary_gap;  // of the reference's boundary from the samples, / diagonal
  std::vector<std::size_t> unresolved_curves;  // input curves below the resolution (boundary check)
  std::vector<std::string> failed;             // the result's own checks that fail
  if (!cmd.no_analysis) {
    // The truth when known: the exact surface of a built-in or a NURBS patch, a mesh input's own surface (its
    // vertices alone would count the triangles' size as error); else the input points.
    analysis::Reference reference;
    if (given_reference) {
      reference = std::move(*given_reference);
      j["reference"] = cmd.reference;
    } else if (is_parametric_spec(cmd.input) || loaded.source == "mesh") {
      reference = in_samples_frame(load_reference(cmd.input, cmd.sampling.join), loaded.origin);
      j["reference"] = cmd.input;
    } else {
      reference.points = loaded.samples.points;
      j["reference"] = "input points";
    }
    report = result.topology ? analysis::analyze_mesh(result.mesh, std::move(*result.topology), reference)
                             : analysis::analyze_mesh(result.mesh, reference);
    j["analysis"] = analysis_json(*report);
    // How far the input's samples leave the true boundary: near it, truth->mesh cannot be
    // smaller (the bar reads max(bar, 1.1 x this) there).
    if (report->distance && !reference.boundary.empty()) {
      const double diagonal = report->distance->reference_diagonal;
      const auto gap = distance::curves_to_points(reference.boundary, loaded.samples.points, 1e-4 * diagonal);
      boundary_gap = gap.max / diagonal;
      j["analysis"]["reference_boundary_gap"] = {{"max", gap.max}, {"max_rel_diag", *boundary_gap}};
    }
    // The result's border against the curves the reconstruction was given or detected.
    std::vector<Polyline> curves;
    for (const auto& c : loaded.samples.boundary) curves.push_back(c.polyline());
    const bool is_envelope = result.method == pipeline::Method::Envelope;
    const pipeline::ResultChecks checks =
        pipeline::check_result(*report, loaded.samples, result, loaded.kind.is_boundary_detected);
    const analysis::BoundaryCheck& check = checks.boundary;
    std::ostringstream tolerance_text;
    tolerance_text.precision(4);
    tolerance_text << (is_envelope ? "2 rho = " : "1% of the diagonal = ") << check.tolerance;
    j["boundary_check"] = boundary_check_json(check, curves, report->topology);
    unresolved_curves = check.unresolved_curves;
    failed = checks.failed;
    if (checks.uncovered_patches > 0) warnings.push_back(uncovered_patches_warning(checks.uncovered_patches));
    j["checks"] = {{"passed", failed.empty()}, {"failed", failed}, {"uncovered_patches", checks.uncovered_patches}};
    for (auto& w : boundary_check_warnings(check, curves, report->topology, tolerance_text.str()))
      warnings.push_back(std::move(w));
  }
  j["warnings"] = warnings;
  // The hints are for the method whose result this is (the fallback's Power Crust gets none).
  pipeline::ReconstructOptions result_options = cmd.options;
  result_options.method = result.method;
  const std::vector<std::string> hints =
      report ? scan_hints(loaded, result_options, *report, unresolved_curves, result.envelope) : std::vector<std::string>{};
  j["hints"] = hints;
  const io::MeshVertexData vertex_data = output_vertex_data(result.mesh, loaded);
  j["output_vertex_data"] = vertex_data_json(vertex_data);
  // Every output is written once nothing can fail any more, so a failed run leaves none.
  const std::string report_text = json_text(j);
  io::write_mesh(cmd.output, in_input_frame(result.mesh, loaded.origin), vertex_data);
  if (!cmd.envelope_output.empty()) {
    PointSet env;
    for (const auto& s : result.envelope.samples) {
      env.points.push_back(s.position);
      env.normals.push_back(s.direction);
    }
    io::write_points(cmd.envelope_output, in_input_frame(std::move(env), loaded.origin));
  }
  if (!cmd.boundary_output.empty())
    write_curves(cmd.boundary_output, in_input_frame(loaded.samples.boundary, loaded.origin));
  write_outliers(cmd, loaded);
  if (!cmd.report_file.empty()) io::write_text(cmd.report_file, report_text);
  if (!cmd.html_file.empty())
    html::write_html_report(cmd.html_file,
                            html::reconstruct_page("envcrust reconstruct: " + cmd.input + " -> " + cmd.output, result.mesh,
                                                   report ? &*report : nullptr, loaded.samples.points, failed, hints, j));
  if (cmd.common.json || cmd.common.quiet) {
    if (cmd.common.json) print_json(j);
    throw_if_failed(cmd, failed);
    return;
  }
  std::cout << "reconstructed " << cmd.input << " (" << loaded.samples.points.size() << " points) -> "
            << cmd.output << "\n";
  print_outliers_line(loaded);
  print_run_stages(std::cout, result, cmd.options);
  for (const auto& w : warnings) std::cout << "  warning: " << w << "\n";
  if (report) print_analysis(std::cout, cmd.output, *report);
  if (boundary_gap)
    std::cout << "  the input's samples leave the reference's boundary up to " << std::setprecision(3)
              << 100 * *boundary_gap << "% of the diagonal from the nearest of them (as closely as they "
              << "locate it)\n";
  for (const auto& h : hints) std::cout << "  hint: " << h << "\n";
  throw_if_failed(cmd, failed);
}


void run_envelope(ReconstructCommand& cmd) {
  io::reuse_freed_memory();
  const auto thread_limit = limit_threads(cmd.common.threads);
  check_outputs(cmd, io::OutputKind::Points);
  cmd.options.envelope.rho = parse_rho(cmd.rho);
  cmd.options.envelope.seed = cmd.sampling.seed;
  const Progress progress = terminal_progress(cmd.common.quiet || cmd.common.json);
  const LoadedSurface loaded = load_surface(cmd.input, cmd.sampling, progress);
  cmd.options = pipeline::options_for_input(loaded.kind, cmd.options);  // the envelope's settings
  check_rho(cmd, loaded);
  progress.report("envelope", 0.0);
  const auto env = naming_input(cmd.input, [&] { return envelope::sample_envelope(loaded.samples, cmd.options.envelope); });
  progress.report("envelope", 1.0);
  if (env.samples.empty()) throw NumericalFailure(empty_result_reason(cmd, loaded, env, "the envelope has no samples"));
  if (!cmd.boundary_output.empty())
    write_curves(cmd.boundary_output, in_input_frame(loaded.samples.boundary, loaded.origin));
  write_outliers(cmd, loaded);
  PointSet points;
  for (const auto& s : env.samples) {
    points.points.push_back(s.position);
    points.normals.push_back(s.direction);
  }
  io::write_points(cmd.output, in_input_frame(std::move(points), loaded.origin));
  nlohmann::json j = {{"input", cmd.input}, {"output", cmd.output}, {"envelope", envelope_json(env)},
                      {"warnings", env.warnings}};
  if (cmd.common.json) {
    print_json(j);
  } else if (!cmd.common.quiet) {
    std::cout << "wrote " << env.samples.size() << " envelope samples (rho " << env.rho << ", spacing "
              << env.spacing << ") to " << cmd.output << "\n";
    print_outliers_line(loaded);
    for (const auto& w : env.warnings) std::cout << "  warning: " << w << "\n";
  }
}

}  // namespace

void register_reconstruct(CLI::App& app) {
  auto cmd = std::make_shared<ReconstructCommand>();
  CLI::App* sub = app.add_subcommand(
      "reconstruct",
      "Reconstruct a surface with boundary through its rho-envelope (the main job), then\n"
      "report the result's topology, boundary knots and distances");
  add_input_options(*sub, *cmd);
  sub->add_option("-o,--output", cmd->output,
                  "Output mesh: .ply (float positions, vertex normals, and the input's colours as uchar red green "
                  "blue and other columns as float properties, each vertex taking its nearest input point's), "
                  ".obj (normals, colours), .off or .stl (the mesh alone). Normals come from the faces; on a "
                  "non-orientable result (a Moebius band) their sign flips across a seam")
      ->required();
  const std::map<std::string, pipeline::Method> methods = {{"envelope", pipeline::Method::Envelope},
                                                           {"powercrust", pipeline::Method::PowerCrust}};
  sub->add_option("--method", cmd->options.method, "envelope (default) or powercrust (direct, for comparison)")
      ->transform(CLI::CheckedTransformer(methods, CLI::ignore_case));
  sub->add_option("--extract", cmd->extract,
                  "samples (default for files: the input samples meshed along the medial sheet, kept in the "
                  "sheet's place when their mesh has the sheet's topology: the input's resolution), sheet (default "
                  "for built-in surfaces: the medial sheet itself, a clean 2-manifold finer than the input) or "
                  "powershape (the paper's raw power shape)")
      ->check(CLI::IsMember({"samples", "sheet", "powershape"}, CLI::ignore_case))
      ->each([cmd](const std::string& value) {
        std::string lower = value;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
        cmd->extract = lower;
        cmd->options.extraction =
            lower == "powershape" ? pipeline::Extraction::PowerShape : pipeline::Extraction::Sheet;
      });
  sub->add_option("--envelope-out", cmd->envelope_output, "Also write the envelope samples (with offset directions)");
  sub->add_flag("--orientable{yes}", cmd->orientable,
                "--orientable alone = --orientable=yes: the surface is orientable (a scan of a solid): where the sheet comes "
                "out non-orientable, remove it within "
                "--orientable-cut rho of each orientation seam, and close the hole with a disc (reported). "
                "--orientable=auto (default): yes when the input is an orientable mesh; for a point file only the seams "
                "that an orientation-reversing loop shorter than 4 pi rho crosses (a twist of the surface itself is at "
                "least 2 pi reach long, so a Moebius strip keeps its twist); no for a non-orientable mesh and built-in "
                "surfaces; --orientable=no: never")
      ->check(CLI::IsMember({"auto", "yes", "no"}));
  sub->add_option("--orientable-cut", cmd->options.sheet.orientable_cut_rel_rho,
                  "With --orientable: half-width of the band removed around a seam, in rho")
      ->capture_default_str()
      ->check(number_above(0));
  sub->add_option_function<double>(
         "--cut-handles", [cmd](double k) { cmd->cut_handles = k; },
         "Remove every geodesic ball of this radius (in rho) where the result is not a disc once its own "
         "holes are capped, and close each hole with a disc: handles and cross-caps at thin, sparsely "
         "sampled parts (reported; 0: off; default: 1.5 for point files and meshes, 0 for built-in surfaces)")
      ->check(number_above(0, true));
  sub->add_flag("--keep-cut-holes", [cmd](std::int64_t) { cmd->options.sheet.fill_cut_holes = false; },
                "With --orientable or --cut-handles: leave the holes the cuts make open instead of closing them "
                "(those along a boundary curve are never closed)");
  sub->add_option("--fold-angle", cmd->options.sheet.fold_min_angle_deg,
                  "Sharp folds: also join envelope samples whose offset directions make at least this many "
                  "degrees (below 100) when the segment between them passes through the surface (0: off)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 99.0));
  sub->add_option("--self-intersection-cut", cmd->options.sheet.self_intersection_cut_rel_rho,
                  "Where the result passes through itself, relax the vertices there; where that is not enough, "
                  "remove the faces within this radius (in rho) and close the holes with discs (reported; 0: off)")
      ->capture_default_str()
      ->check(number_above(0, true));
  sub->add_option("--self-intersection-rounds", cmd->options.sheet.self_intersection_cut_rounds,
                  "Cut rounds: after each, the result is checked again and relaxed and cut where it still passes "
                  "through itself")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  sub->add_flag("--crust-check", cmd->options.use_envelope_crust_check,
                "Also run the Power Crust on the envelope and report its topology (chi(E) = 2 chi(M))");
  sub->add_flag("--remesh", cmd->use_remesh,
                "Collapse the short edges, then remesh the result isotropically (keeps topology and boundary; a Moebius band is cut along a seam and welded back)");
  sub->add_option_function<double>(
         "--remesh-edge", [cmd](double length) { cmd->remesh.target_edge_length = length; },
         "With --remesh: target edge length (default: --remesh-edge-rel-median x the median edge)")
      ->check(number_above(0));
  sub->add_option("--remesh-edge-rel-median", cmd->remesh.edge_length_rel_median,
                  "With --remesh: target edge length as a multiple of the median edge")
      ->capture_default_str()
      ->check(number_above(0));
  sub->add_option("--remesh-iterations", cmd->remesh.iterations, "With --remesh: remeshing rounds")
      ->capture_default_str()
      ->check(whole_number_in(1, 100));
  const std::map<std::string, remesh::BoundaryMode> boundary_modes = {{"resample", remesh::BoundaryMode::Resample},
                                                                      {"keep", remesh::BoundaryMode::Keep}};
  sub->add_option("--remesh-boundary", cmd->remesh.boundary,
                  "With --remesh: resample (default: border resampled along itself) or keep (every border vertex kept)")
      ->transform(CLI::CheckedTransformer(boundary_modes, CLI::ignore_case));
  sub->add_option("-r,--reference", cmd->reference,
                  "Reference for distances (default: the exact surface of a builtin, the surface of an input mesh, else the input points)");
  sub->add_flag("--no-analysis", cmd->no_analysis, "Skip the analysis of the output");
  sub->add_flag("--no-adaptive-retry", cmd->no_adaptive_retry,
                "One uniform-rho run, kept even when its result has holes the input has not, or more handles than "
                "a mesh input (by default a file's reconstruction first tries a rho that follows the local feature "
                "size, kept when its sheet needs no cut; then the uniform run, which runs again with --rho-adaptive "
                "when it fails and keeps the run with fewer defects)");
  sub->add_flag("--no-power-crust-fallback", cmd->no_power_crust_fallback,
                "Keep the envelope's result of an input without boundary curves (or with detected ones) even when "
                "it fails its checks (by default the direct Power Crust, which needs no normals and copes with "
                "sparser samples of a closed surface, then runs too and is kept if it has fewer defects and caps "
                "no hole; a file without boundary curves gets it first, kept when it has no defect at all)");
  sub->add_option("--report", cmd->report_file, "Also write the JSON report to this file");
  html::add_html_option(*sub, cmd->html_file,
                        "the result, each vertex coloured on demand by its distance to the nearest input point");
  add_common_flags(*sub, cmd->common);
  sub->footer(
      "Exit codes: 0 the result was written and passes its checks; 1 bad input, or a run refused before it\n"
      "started (e.g. a --rho the sampling cannot support), nothing written; 2 usage error (also an output\n"
      "that is the same file as an input); 3 internal error; 4 the result was written but fails its own\n"
      "checks: it is not a 2-manifold, it passes through itself, an input boundary curve is followed by no\n"
      "border (unless the curves were detected and the Power Crust fallback was kept: it closes them on\n"
      "purpose), or a border follows no input curve (the report's \"checks\" lists which; --no-analysis\n"
      "skips the checks).");
  sub->callback([cmd] { run_reconstruct(*cmd); });
}

void register_envelope(CLI::App& app) {
  auto cmd = std::make_shared<ReconstructCommand>();
  CLI::App* sub = app.add_subcommand("envelope", "Write the samples of the rho-envelope of a surface");
  add_input_options(*sub, *cmd);
  sub->add_option("-o,--output", cmd->output, "Output point file (.xyz/.ply; normals = offset directions)")
      ->required();
  add_common_flags(*sub, cmd->common);
  sub->callback([cmd] { run_envelope(*cmd); });
}

}  // namespace envcrust::cli
