// reconstruct: composes envelope sampling, the Power Crust and the sheet extraction.
#include "envcrust/pipeline.h"

#include "envcrust/topology.h"


namespace envcrust::pipeline {
namespace {

// The optional last step: remesh out.mesh in place (the input comes back on a skip).
void remesh_result(ReconstructResult& out, const std::optional<remesh::RemeshOptions>& options,
                   const Progress& progress) {
  if (!options) return;
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
  for (const auto& pole : result.poles) mesh.vertices.push_back(pole.center);
  mesh.triangles = result.power_shape.triangles;
  return mesh;
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
    auto sheet = extract::extract_sheet(out.envelope, samples, options.sheet);
    out.seconds.extraction = clock.lap();
    out.mesh = std::move(sheet.mesh);
    out.sheet_stats = sheet.stats;
    for (auto& w : sheet.warnings) out.warnings.push_back(std::move(w));
    progress.report("medial sheet", 1.0);
  }
  return out;
}

std::optional<long> genus_of(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return std::nullopt;
  return topology::total_genus(topology::analyze_topology(mesh));
}

}  // namespace

ReconstructResult reconstruct(const envelope::SurfaceSamples& samples,
                              const ReconstructOptions& options, const Progress& progress) {
  ReconstructOptions once = options;
  once.remesh.reset();
  ReconstructResult out = reconstruct_once(samples, once, progress);
  if (options.max_genus && options.method == Method::Envelope && options.extraction == Extraction::Sheet &&
      options.envelope.rho_mode == envelope::RhoMode::Uniform && !out.mesh.triangles.empty()) {
    AdaptiveRetry retry;
    retry.max_genus = *options.max_genus;
    retry.uniform_genus = genus_of(out.mesh);
    if (!retry.uniform_genus || *retry.uniform_genus > retry.max_genus) {
      once.envelope.rho_mode = envelope::RhoMode::Adaptive;
      ReconstructResult adaptive = reconstruct_once(samples, once, progress);
      retry.adaptive_genus = genus_of(adaptive.mesh);
      retry.kept_adaptive =
          retry.adaptive_genus && (!retry.uniform_genus || *retry.adaptive_genus < *retry.uniform_genus);
      if (retry.kept_adaptive) {
        adaptive.seconds.envelope += out.seconds.envelope;
        adaptive.seconds.extraction += out.seconds.extraction;
        out = std::move(adaptive);
      }
      out.adaptive_retry = retry;
    }
  }
  remesh_result(out, options.remesh, progress);
  return out;
}

}  // namespace envcrust::pipeline
