// The main job composed from the stages: samples of M -> envelope -> (Power Crust) -> M.
// This header holds no algorithm; each step is a stage of its own module.
#pragma once

#include "envcrust/analysis.h"
#include "envcrust/envelope.h"
#include "envcrust/extract.h"
#include "envcrust/interpolate.h"
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
  Sheet,      ///< clean 2-manifold medial sheet (docs/method.md §8), the default
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
  /// self-check (chi(E) = 2 chi(M), docs/method.md §2.3, §9.6). Costs about one more reconstruction.
  bool use_envelope_crust_check = false;
  /// Remesh the result isotropically as a last step (keeps its topology and boundary; a
  /// non-orientable result is cut along a seam and welded back; skipped with a warning for
  /// non-manifold results). nullopt: no remeshing.
  std::optional<remesh::RemeshOptions> remesh;
  /// Mesh the samples themselves along the extracted sheet (interpolate::mesh_samples) and
  /// keep that mesh in place of the sheet when its topology is the sheet's: the same Euler
  /// characteristic, border loops, pieces and orientability, a manifold. The output then has
  /// the input's resolution and the envelope's topology (ReconstructResult::sample_meshing);
  /// otherwise the sheet is simplified to about as many vertices as there are samples
  /// (ReconstructResult::simplify_stats). Method::Envelope with Extraction::Sheet, without
  /// remeshing. nullopt: the sheet itself.
  std::optional<interpolate::InterpolateOptions> mesh_samples;
  /// Check a uniform-rho run (Method::Envelope, Extraction::Sheet) and, when it fails, run
  /// again with adaptive rho (small where M is thin, large where it is sparse) and keep the
  /// run with fewer defects (RunDefects::is_better_than; ReconstructResult::adaptive_retry). It fails
  /// when its result is empty or no manifold, has a border loop that follows no boundary curve of the
  /// input within 2 rho (a hole where the input is too sparse for one rho), or more handles
  /// and cross-caps than max_genus; without max_genus, any when rho had to be raised above
  /// half the reach to bridge the input's gaps (the envelope may fold into handles there).
  /// Off: one run.
  bool use_adaptive_retry = false;
  /// With automatic rho, try first one run whose rho follows the local feature size up to
  /// kLocalRhoCeilingRelDiag of the samples' diagonal (adaptive rho down to
  /// kLocalRhoFloorRelCeiling of that), and keep it when its raw sheet needed neither an
  /// orientation nor a handle cut and its result has no defect (RunDefects: a manifold, every
  /// input curve followed, no hole, piece or handle too many); otherwise the uniform run and
  /// its retries follow (ReconstructResult::local_rho_first). Where the sheet comes out clean,
  /// a rho as large as each place allows makes the envelope several times smaller. Off: the
  /// uniform run first. Method::Envelope with Extraction::Sheet and RhoMode::Uniform only.
  bool use_local_rho_first = false;
  /// With automatic rho and an input without boundary curves, run the direct Power Crust before
  /// any envelope run, and keep its result when it has no defect at all (ReconstructResult::
  /// power_crust_first): a closed surface is its home ground, and it costs a fraction of an
  /// envelope run. Not kept, it is reused by the fallback. Method::Envelope with
  /// Extraction::Sheet and RhoMode::Uniform only.
  bool use_power_crust_first = false;
  /// When the input has no boundary curves (a closed surface), or only curves detected from its
  /// points (are_curves_detected), and the envelope's result, after the adaptive retry if that
  /// ran, fails the same check (empty, no manifold, more pieces than the samples form, handles
  /// while rho was raised for gaps) or leaves a patch of samples out (RunDefects::
  /// uncovered_patches), run the direct Power Crust too and keep its result if it
  /// has fewer defects (each input curve it closes counts as one; ReconstructResult::
  /// power_crust_fallback) and spans no hole (stays within the samples' gap size of them). A closed sample too sparse for the envelope (its gaps need a rho
  /// beyond the reach) is the Power Crust's home ground: it needs no normals and no rho, and
  /// curves detected in such a sample are often false ones. Not for an input too sparse for
  /// its size (EnvelopeSamples::is_input_too_sparse: no method can tell its shape). Method::
  /// Envelope with Extraction::Sheet only.
  bool use_power_crust_fallback = false;
  /// The input's boundary curves were detected from its points, not given: the fallback may
  /// close them (a mesh's or a built-in surface's own curves, or curves given, are trusted).
  bool are_curves_detected = false;
  /// Turn each piece of a medial-sheet result to face like the input's normals
  /// (topology::orient_along_normals); the sheet itself comes out with either side up. Off for
  /// estimated normal lines, whose signs are arbitrary (options_for_input).
  bool use_normal_orientation = true;
  /// The genus M is known to have at most (a mesh input's own: handles and cross-caps summed
  /// over components); nullopt: unknown, and the defect count takes every handle as one.
  std::optional<long> max_genus;
};

/// Where the samples came from: reconstruct's defaults (options_for_input) depend on it.
struct InputKind {
  bool is_builtin = true;              ///< drawn from a built-in surface (false: a point file or mesh, a "scan")
  bool are_normals_estimated = false;  ///< normal lines estimated from the points, not given
  /// Estimated normal lines turned to agree with normals the file gave (and set aside for
  /// jumping across sharp creases): their signs still say which way the output faces.
  bool are_signs_given = false;
  std::optional<bool> is_orientable;   ///< a mesh input's own; unknown for point files and built-in samples
  std::optional<long> genus;           ///< a mesh input's own, handles and cross-caps summed over components
  bool is_boundary_detected = false;   ///< boundary curves detected from the points (maybe false ones)
};

/// Handle cuts of a scan's medial sheet (SheetOptions::cut_handles_rel_rho): at rho <= reach/2
/// every ball of radius 1.5 rho meets the true surface in a disc, so the sheet fails to be one
/// there only at a defect.
inline constexpr double kScanCutHandlesRelRho = 1.5;

/// `options` with the settings for such input, as `envcrust reconstruct` runs it: estimated
/// normals, and every point file whatever its normals (the frames of curves fitted to its rim
/// samples scatter the reach as much), take the 5th percentile of the per-sample reach
/// (docs/method.md §4.3); estimated normals leave the result's orientation as it comes (their signs
/// are arbitrary);
/// the medial sheet of a scan is cut at handles (kScanCutHandlesRelRho) and to an orientable
/// sheet, at every seam for an orientable mesh and for a point file (which does not say) only
/// at seams an orientation-reversing loop shorter than extract::kTwistMinLoopRelRho crosses;
/// the adaptive retry and the Power Crust fallback are on when rho is automatic, with a mesh's
/// genus as max_genus; a file's samples are meshed along the sheet (mesh_samples, the output at
/// the input's resolution). Built-in
/// samples keep the method as it is (the experiments measure it) apart from the retry.
ReconstructOptions options_for_input(const InputKind& input, ReconstructOptions options = {});

/// What is wrong with one run's result, by the checks the adaptive retry makes.
struct RunDefects {
  bool is_empty = false;           ///< the run gave no faces (genus unset)
  std::optional<long> genus;       ///< handles and cross-caps over components; unset: no manifold
  /// Input boundary curves no border loop follows within 2 rho, those below the envelope's
  /// resolution too: the adaptive run's smaller rho may resolve what the uniform one cannot.
  std::size_t missing_curves = 0;
  std::size_t extra_loops = 0;     ///< border loops that follow no input boundary curve within 2 rho
  /// Pieces of the result beyond the sets the samples form (sample_groups within 2 rho, where
  /// the envelope's balls overlap): the result fell apart where the samples hold together.
  std::size_t extra_pieces = 0;
  /// Patches of the samples (sets within 2 rho, of at least kMinUncoveredPatch samples) all
  /// farther than 2 rho from the result: parts of the sample the result left out (an ear cut
  /// off). Measured for the Power Crust fallback's two runs only (0 elsewhere).
  std::size_t uncovered_patches = 0;
  /// missing_curves + extra_loops + extra_pieces + uncovered_patches + the handles and cross-caps beyond max_genus (all of them
  /// when it is unknown); the largest value for no manifold.
  [[nodiscard]] std::size_t count(std::optional<long> max_genus) const;
  /// Fewer defects than `other`, or as many with fewer handles and cross-caps beyond
  /// max_genus: handles are what the retry's smaller rho is for (a uniform rho too large for
  /// the thin parts), and on a tie the run without them is kept.
  [[nodiscard]] bool is_better_than(const RunDefects& other, std::optional<long> max_genus) const;
};

/// Ceiling of the local-rho first run (ReconstructOptions::use_local_rho_first): half the
/// automatic reach's cap (EnvelopeOptions::max_reach_rel_diag), the largest rho the automatic
/// choice can give.
inline constexpr double kLocalRhoCeilingRelDiag = 0.05;
/// Its floor as a fraction of the ceiling: 0.1% of the diagonal, the floor of the local-rho
/// runs measured on the development set (docs/real-shapes.md).
inline constexpr double kLocalRhoFloorRelCeiling = 0.02;

/// What the local-rho first run did (ReconstructOptions::use_local_rho_first).
struct LocalRhoFirst {
  /// Its result's check; unset when its sheet needed a cut (the run stopped there).
  std::optional<RunDefects> defects;
  std::size_t orientation_seams = 0;  ///< of its raw sheet (extract::SheetStats)
  std::size_t handle_balls = 0;       ///< of its raw sheet
  double rho_min = 0, rho_max = 0;    ///< its local rho's range
  std::size_t envelope_samples = 0;
  double seconds = 0;                 ///< spent on it, kept or not
  bool is_kept = false;
};

/// What the adaptive retry did.
struct AdaptiveRetry {
  std::optional<long> max_genus;
  RunDefects uniform, adaptive;
  bool kept_adaptive = false;
};

/// Fewer samples than this far from the result are strays, not a part left out
/// (RunDefects::uncovered_patches): the 8 nearest neighbours of one sample.
inline constexpr std::size_t kMinUncoveredPatch = 9;

/// What the Power Crust fallback did (ReconstructOptions::use_power_crust_fallback).
struct PowerCrustFallback {
  std::size_t input_curves = 0;    ///< the input's boundary curves (detected ones: may be false)
  std::size_t sample_groups = 0;   ///< sets the samples form within 2 rho
  RunDefects envelope, power_crust;
  /// The Power Crust's result must stay near the samples: a cap across a hole does not (the
  /// hole was real, detected or not). Its farthest vertex or face centre from the nearest
  /// sample, and the bound: the largest distance of 99% of the samples to their 8th nearest
  /// (the envelope's gap measure). Zero when the Power Crust had more defects (not measured).
  double crust_farthest_from_samples = 0, crust_allowed_distance = 0;
  /// Why the Power Crust gave no result, if it threw (DegenerateInput on coplanar samples,
  /// NumericalFailure); its run then counts as empty.
  std::string power_crust_failure;
  bool kept_power_crust = false;
};

/// What the Power Crust first did (ReconstructOptions::use_power_crust_first): the direct
/// Power Crust of a closed input, tried before any envelope run and kept when its result has
/// no defect at all.
struct PowerCrustFirst {
  /// Its result's check: manifold, no border, no piece more than the samples' sets (within
  /// 2 rho, rho = the gap size / 2.5, what bridges the gaps), no handle beyond the known genus
  /// (none when unknown), no sample set left uncovered.
  RunDefects defects;
  /// Its farthest vertex or face centre from the nearest sample, and the bound (the gap size:
  /// the largest distance of 99% of the samples to their 8th nearest).
  double farthest_from_samples = 0, allowed_distance = 0;
  std::string failure;  ///< why the Power Crust threw, if it did (the run then counts as empty)
  /// The samples' gaps need a rho beyond what resolves their size (EnvelopeSamples::
  /// is_input_too_sparse): no method can tell the shape, and a closed crust is not kept.
  bool is_input_too_sparse = false;
  double seconds = 0;   ///< spent on it, kept or not
  bool is_kept = false;
};

/// Seconds spent per stage.
struct StageTimes {
  double envelope = 0, power_crust = 0, extraction = 0, remesh = 0, simplify = 0;
};

/// What became of the samples' mesh (ReconstructOptions::mesh_samples).
struct SampleMeshing {
  interpolate::InterpolateStats stats;
  bool is_kept = false;          ///< it replaced the sheet
  std::string sheet_topology;    ///< e.g. "chi -1, 3 loops, 1 piece, orientable"
  std::string samples_topology;  ///< the same for the samples' mesh
};

/// Result of reconstruct.
struct ReconstructResult {
  TriangleMesh mesh;                       ///< the reconstruction of M
  envelope::EnvelopeSamples envelope;      ///< Method::Envelope only
  std::optional<extract::SheetStats> sheet_stats;
  std::optional<powercrust::PowerCrustStats> power_crust_stats;
  std::optional<TriangleMesh> envelope_crust;  ///< the Power Crust of the envelope, if run
  std::optional<remesh::RemeshStats> remesh_stats;  ///< set when options.remesh is
  std::optional<PowerCrustFirst> power_crust_first;  ///< set when a closed input's Power Crust was tried first
  std::optional<LocalRhoFirst> local_rho_first;   ///< set when the local-rho run was tried
  std::optional<AdaptiveRetry> adaptive_retry;    ///< set when the uniform run failed its check
  std::optional<PowerCrustFallback> power_crust_fallback;  ///< set when the fallback ran
  std::optional<SampleMeshing> sample_meshing;  ///< set when the samples were meshed
  /// Set when the samples' mesh was not kept: the sheet (or Power Crust) simplified to about
  /// the samples' number of vertices (remesh::simplify), unless that folded it through itself.
  std::optional<remesh::SimplifyStats> simplify_stats;
  /// The method whose result `mesh` is: options.method, or PowerCrust when the fallback's run
  /// was kept (then `envelope` and `sheet_stats` describe the envelope run it replaced) or
  /// the Power Crust first (then no envelope run was made: `envelope` is empty).
  Method method = Method::Envelope;
  /// The topology of `mesh` when the retry check computed it (and no remeshing changed the
  /// mesh since): analysis::analyze_mesh takes it instead of computing it again.
  std::optional<topology::MeshTopology> topology;
  StageTimes seconds;
  std::vector<std::string> warnings;
};

/// Reconstruct M from its samples (points with normal lines and boundary curves): with
/// options.use_power_crust_first, for an input without boundary curves the direct Power Crust
/// kept when it has no defect; with options.use_local_rho_first a local-rho run kept when its
/// sheet is clean; otherwise one run,
/// a second with adaptive rho if the first fails the check of options.use_adaptive_retry,
/// the direct Power Crust if the input has no boundary curves and the kept run still fails
/// (options.use_power_crust_fallback), then the samples' mesh (options.mesh_samples) or the
/// remeshing.
/// @throws InvalidInput, DegenerateInput, InvalidOptions from the stages.
ReconstructResult reconstruct(const envelope::SurfaceSamples& samples,
                              const ReconstructOptions& options = {}, const Progress& progress = {});

/// The border loops of a result against the input's boundary curves, within 2 rho (the
/// envelope's rho; in adaptive mode its largest): the check of the adaptive retry and of the
/// CLI's report. Curves shorter than 2 pi times the smallest rho are below the envelope's
/// resolution: closed, they are unresolved, not missing.
analysis::BoundaryCheck check_result_boundary(const topology::MeshTopology& result,
                                              const envelope::SurfaceSamples& samples,
                                              const envelope::EnvelopeSamples& envelope);

/// A result's own checks, as the CLI's and Python's reports give them ("checks").
struct ResultChecks {
  /// The result's borders against the input's curves: check_result_boundary for an envelope
  /// result, within 1% of the samples' diagonal for a Power Crust one.
  analysis::BoundaryCheck boundary;
  /// One line per failed check: not a 2-manifold, passing through itself, an input curve
  /// followed by no border, a border along no curve. Empty: passed.
  std::vector<std::string> failed;
  /// uncovered_patches of the result: said, not failed (repairs leave such patches on real
  /// scans, e.g. 5 on the lion head's points, in results that otherwise pass).
  std::size_t uncovered_patches = 0;
};

/// The checks of `result` from its analysis (`report`, with self-intersections when they were
/// computed). Detected curves (maybe false ones) that the Power Crust fallback chose to close
/// are no failure: the fallback counted each one it closed as a defect and still kept it.
ResultChecks check_result(const analysis::AnalysisReport& report, const envelope::SurfaceSamples& samples,
                          const ReconstructResult& result, bool are_curves_detected);

/// Sets of samples joined by chains of neighbours (each one with its 8 nearest) no farther
/// apart than `reach`: at least as many as the pieces of the union of the balls of radius
/// reach / 2 around them, so an envelope of radius rho around them has at least as many
/// pieces as they form within 2 rho, and a result of more pieces fell apart.
std::size_t sample_groups(const std::vector<Point3>& points, double reach);

/// Patches of at least kMinUncoveredPatch samples (sets joined within 2 rho as in
/// sample_groups) lying farther than 2 rho from `mesh`: parts of the sample a result left out
/// (RunDefects::uncovered_patches). 0 for an empty mesh or rho <= 0.
std::size_t uncovered_patches(const TriangleMesh& mesh, const std::vector<Point3>& points, double rho);

/// The power shape's triangles as a mesh whose vertices are the In poles, in pole order (the
/// paper's output; the power shape holds only In poles).
TriangleMesh power_shape_mesh(const powercrust::PowerCrustResult& result);

}  // namespace envcrust::pipeline
