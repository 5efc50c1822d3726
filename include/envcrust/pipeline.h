// The main job composed from the stages: samples of M -> envelope -> (Power Crust) -> M.
// This header holds no algorithm; each step is a stage of its own module.
#pragma once

#include "envcrust/envelope.h"
#include "envcrust/extract.h"
#include "envcrust/power_crust.h"
#include "envcrust/progress.h"
#include "envcrust/remesh.h"

#include <optional>
#include <string>
#include <vector>

namespace envcrust::pipeline {

/// How M is reconstructed.
enum class Method {
  Envelope,   ///< the paper's method: sample E_rho(M), reconstruct, take its inner medial axis
  PowerCrust  ///< the direct Power Crust of the input points (closes every boundary)
};

/// How M is taken from the envelope's reconstruction (Method::Envelope only).
enum class Extraction {
  Sheet,      ///< clean 2-manifold medial sheet (METHOD.md §5 c1), the default
  PowerShape  ///< the paper's expedient: the raw inner power shape, for comparison
};

/// Options of reconstruct.
struct ReconstructOptions {
  Method method = Method::Envelope;
  Extraction extraction = Extraction::Sheet;
  envelope::EnvelopeOptions envelope;
  extract::SheetOptions sheet;
  powercrust::PowerCrustOptions power_crust;
  /// Also run the Power Crust on the envelope samples and report its topology as a
  /// self-check (chi(E) = 2 chi(M), METHOD.md F3). Costs about one more reconstruction.
  bool use_envelope_crust_check = false;
  /// Remesh the result isotropically as a last step (keeps its topology and boundary; a
  /// non-orientable result is cut along a seam and welded back; skipped with a warning for
  /// non-manifold results). nullopt: no remeshing.
  std::optional<remesh::RemeshOptions> remesh;
  /// The genus M is known to have at most (a mesh input's own: handles and cross-caps summed
  /// over components). When a uniform-rho envelope run gives the sheet more, it runs again
  /// with adaptive rho (small where M is thin, large where it is sparse) and the run with the
  /// lower genus is kept (ReconstructResult::adaptive_retry). nullopt: no check.
  std::optional<long> max_genus;
};

/// What the max_genus check did.
struct AdaptiveRetry {
  long max_genus = 0;
  std::optional<long> uniform_genus, adaptive_genus;  ///< unset: not a manifold (or empty)
  bool kept_adaptive = false;
};

/// Seconds spent per stage.
struct StageTimes {
  double envelope = 0, power_crust = 0, extraction = 0, remesh = 0;
};

/// Result of reconstruct.
struct ReconstructResult {
  TriangleMesh mesh;                       ///< the reconstruction of M
  envelope::EnvelopeSamples envelope;      ///< Method::Envelope only
  std::optional<extract::SheetStats> sheet_stats;
  std::optional<powercrust::PowerCrustStats> power_crust_stats;
  std::optional<TriangleMesh> envelope_crust;  ///< the Power Crust of the envelope, if run
  std::optional<remesh::RemeshStats> remesh_stats;  ///< set when options.remesh is
  std::optional<AdaptiveRetry> adaptive_retry;    ///< set when the max_genus check reran
  StageTimes seconds;
  std::vector<std::string> warnings;
};

/// Reconstruct M from its samples (points with normal lines and boundary curves): one run,
/// a second with adaptive rho if the first exceeds options.max_genus, then the remeshing.
/// @throws InvalidInput, DegenerateInput, InvalidOptions from the stages.
ReconstructResult reconstruct(const envelope::SurfaceSamples& samples,
                              const ReconstructOptions& options = {}, const Progress& progress = {});

/// The power shape's triangles as a mesh over the In poles (the paper's output).
TriangleMesh power_shape_mesh(const powercrust::PowerCrustResult& result);

}  // namespace envcrust::pipeline
