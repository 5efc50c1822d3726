// reconstruct: composes envelope sampling, the Power Crust and the sheet extraction.
#include "envcrust/pipeline.h"

#include "envcrust/topology.h"

#include <algorithm>
#include <limits>
#include <numbers>


namespace envcrust::pipeline {
namespace {

// The optional last step: remesh out.mesh in place (the input comes back on a skip).
void remesh_result(ReconstructResult& out, const std::optional<remesh::RemeshOptions>& options,
                   const Progress& progress) {
  if (!options) return;
  out.topology.reset();
  progress.report("remesh", 0.0);
  auto r = remesh::remesh(out.mesh, *options);
  out.mesh = std::move(r.mesh);
  out.remesh_stats = r.stats;
  out.seconds.remesh = r.stats.seconds;
  for (auto& w : r.warnings) out.warnings.push_back(std::move(w));
  progress.report("remesh", 1.0);
}

}  // namespace

TriangleMesh power_shape_mesh(const powercrust::PowerCrustResult& result) {
  TriangleMesh mesh;
  std::vector<Index> vertex_of(result.poles.size(), powercrust::kNoPole);
  for (std::size_t p = 0; p < result.poles.size(); ++p) {
    if (result.poles[p].label != powercrust::PoleLabel::In) continue;
    vertex_of[p] = static_cast<Index>(mesh.vertices.size());
    mesh.vertices.push_back(result.poles[p].center);
  }
  for (const auto& t : result.power_shape.triangles) mesh.triangles.push_back({vertex_of[t[0]], vertex_of[t[1]], vertex_of[t[2]]});
  return mesh;
}

ReconstructOptions options_for_input(const InputKind& input, ReconstructOptions options) {
  if (input.are_normals_estimated) {
    options.envelope.reach_quantile = 0.05;
    options.use_normal_orientation = false;
  }
  if (!input.is_builtin) {
    const bool is_point_file = !input.is_orientable.has_value();
    options.sheet.cut_handles_rel_rho = kScanCutHandlesRelRho;
    options.sheet.cut_to_orientable = input.is_orientable.value_or(true);
    options.sheet.orientable_max_twist_loop_rel_rho =
        is_point_file ? extract::kTwistMinLoopRelRho : std::numeric_limits<double>::infinity();
  }
  options.use_adaptive_retry = !options.envelope.rho.has_value();
  options.max_genus = input.genus;
  return options;
}

namespace {

// One run of the stages, without the max_genus check and the remeshing.
ReconstructResult reconstruct_once(const envelope::SurfaceSamples& samples, const ReconstructOptions& options,
                                   const Progress& progress) {
  ReconstructResult out;
  if (options.method == Method::PowerCrust) {
    progress.report("power crust", 0.0);
    Stopwatch clock;
    auto pc_options = options.power_crust;
    pc_options.build_power_shape = false;
    auto pc = powercrust::power_crust(samples.points, pc_options, progress);
    out.seconds.power_crust = clock.lap();
    out.mesh = std::move(pc.crust);
    out.power_crust_stats = pc.stats;
    out.warnings = std::move(pc.warnings);
    progress.report("power crust", 1.0);
    return out;
  }

  progress.report("envelope", 0.0);
  Stopwatch clock;
  out.envelope = envelope::sample_envelope(samples, options.envelope);
  out.seconds.envelope = clock.lap();
  out.warnings = out.envelope.warnings;
  progress.report("envelope", 1.0);
  // Too few envelope samples for any triangulation (rho far beyond the input's size leaves
  // none clear of it): an empty result, which the caller explains.
  if (out.envelope.samples.size() < 5) {
    out.warnings.push_back("the envelope has " + std::to_string(out.envelope.samples.size()) +
                           " samples: nothing to extract");
    return out;
  }

  const bool need_crust =
      options.extraction == Extraction::PowerShape || options.use_envelope_crust_check;
  if (need_crust) {
    progress.report("power crust of E", 0.0);
    clock.lap();
    auto pc_options = options.power_crust;
    pc_options.build_power_shape = options.extraction == Extraction::PowerShape;
    auto pc = powercrust::power_crust(out.envelope.points(), pc_options, progress);
    out.seconds.power_crust = clock.lap();
    out.power_crust_stats = pc.stats;
    for (auto& w : pc.warnings) out.warnings.push_back("power crust of the envelope: " + w);
    if (options.extraction == Extraction::PowerShape) out.mesh = power_shape_mesh(pc);
    out.envelope_crust = std::move(pc.crust);
    progress.report("power crust of E", 1.0);
  }
  if (options.extraction == Extraction::Sheet) {
    progress.report("medial sheet", 0.0);
    clock.lap();
    auto sheet = extract::extract_sheet(out.envelope, samples, options.sheet, progress);
    out.seconds.extraction = clock.lap();
    out.mesh = std::move(sheet.mesh);
    out.sheet_stats = sheet.stats;
    for (auto& w : sheet.warnings) out.warnings.push_back(std::move(w));
    progress.report("medial sheet", 1.0);
  }
  return out;
}

// The checks of one run; its topology is kept in run.topology for the report.
RunDefects defects_of(ReconstructResult& run, const envelope::SurfaceSamples& samples) {
  RunDefects d;
  d.is_empty = run.mesh.triangles.empty();
  if (d.is_empty) return d;
  const topology::MeshTopology& t = run.topology.emplace(topology::analyze_topology(run.mesh));
  d.genus = topology::total_genus(t);
  const analysis::BoundaryCheck check = check_result_boundary(t, samples, run.envelope);
  d.missing_curves = check.missing_curves.size() + check.unresolved_curves.size();
  d.extra_loops = check.extra_loops.size();
  return d;
}

// A run fails when its result is no manifold, has holes the input has not, more handles than
// the known genus, or any handle while rho had to be raised above half the reach to bridge
// the input's gaps (where the envelope may fold into handles: the uniform rho is too large
// for the thin parts and too small for the sparse ones, which adaptive rho is for).
bool fails(const RunDefects& d, const envelope::EnvelopeSamples& envelope, std::optional<long> max_genus) {
  if (!d.genus || d.extra_loops > 0) return true;
  if (max_genus) return *d.genus > *max_genus;
  return *d.genus > 0 && envelope.is_rho_gap_bound;
}

}  // namespace

namespace {

// Handles and cross-caps of a manifold run beyond the bound (all of them when it is unknown).
long excess_genus(long genus, std::optional<long> max_genus) { return std::max(0L, genus - max_genus.value_or(0)); }

}  // namespace

std::size_t RunDefects::count(std::optional<long> max_genus) const {
  if (!genus) return std::numeric_limits<std::size_t>::max();
  return missing_curves + extra_loops + static_cast<std::size_t>(excess_genus(*genus, max_genus));
}

bool RunDefects::is_better_than(const RunDefects& other, std::optional<long> max_genus) const {
  const std::size_t mine = count(max_genus), theirs = other.count(max_genus);
  if (mine != theirs) return mine < theirs;
  if (!genus || !other.genus) return false;
  return excess_genus(*genus, max_genus) < excess_genus(*other.genus, max_genus);
}

analysis::BoundaryCheck check_result_boundary(const topology::MeshTopology& result,
                                              const envelope::SurfaceSamples& samples,
                                              const envelope::EnvelopeSamples& envelope) {
  std::vector<Polyline> curves;
  curves.reserve(samples.boundary.size());
  for (const BoundaryCurve& c : samples.boundary) curves.push_back(c.polyline());
  const double rho_min = envelope.rho_min > 0 ? envelope.rho_min : envelope.rho;
  return analysis::check_boundary(result, curves, 2.0 * envelope.rho, 0.9, 2.0 * std::numbers::pi * rho_min);
}

ReconstructResult reconstruct(const envelope::SurfaceSamples& samples,
                              const ReconstructOptions& options, const Progress& progress) {
  ReconstructOptions once = options;
  once.remesh.reset();
  ReconstructResult out = reconstruct_once(samples, once, progress);
  if (options.use_adaptive_retry && options.method == Method::Envelope && options.extraction == Extraction::Sheet &&
      options.envelope.rho_mode == envelope::RhoMode::Uniform) {
    AdaptiveRetry retry;
    retry.max_genus = options.max_genus;
    retry.uniform = defects_of(out, samples);
    if (fails(retry.uniform, out.envelope, options.max_genus)) {
      once.envelope.rho_mode = envelope::RhoMode::Adaptive;
      ReconstructResult adaptive = reconstruct_once(samples, once, progress);
      retry.adaptive = defects_of(adaptive, samples);
      retry.kept_adaptive = retry.adaptive.is_better_than(retry.uniform, options.max_genus);
      if (retry.kept_adaptive) {
        adaptive.seconds.envelope += out.seconds.envelope;
        adaptive.seconds.extraction += out.seconds.extraction;
        out = std::move(adaptive);
      }
      out.adaptive_retry = retry;
    }
  }
  remesh_result(out, options.remesh, progress);
  if (options.use_normal_orientation && options.method == Method::Envelope && options.extraction == Extraction::Sheet)
    topology::orient_along_normals(out.mesh, samples.points, samples.normals);
  return out;
}

}  // namespace envcrust::pipeline
