// reconstruct: composes envelope sampling, the Power Crust and the sheet extraction.
#include "envcrust/pipeline.h"

#include "envcrust/distance.h"
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"
#include "envcrust/topology.h"
#include "envcrust/union_find.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

std::string topology_summary(const topology::MeshTopology& t) {
  const auto loops = t.boundary_loops.size();
  const auto pieces = t.components.size();
  return "chi " + std::to_string(t.euler_characteristic) + ", " + std::to_string(loops) +
         (loops == 1 ? " loop, " : " loops, ") + std::to_string(pieces) + (pieces == 1 ? " piece, " : " pieces, ") +
         (t.is_orientable ? "orientable" : "non-orientable") + (t.is_manifold() ? "" : ", not a manifold");
}

// Each face from its smallest vertex on (its winding kept), the faces sorted: the orientation
// steps flip faces in an order that may follow the heap's layout, and one input then gives one
// file, whatever the process's environment.
void write_in_canonical_order(TriangleMesh& mesh) {
  for (auto& t : mesh.triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
}

// The samples meshed along the sheet, in place of the sheet when the topologies agree.
void mesh_samples_result(ReconstructResult& out, const envelope::SurfaceSamples& samples,
                         const interpolate::InterpolateOptions& options, const Progress& progress) {
  if (out.mesh.triangles.empty()) return;
  if (!out.topology) out.topology = topology::analyze_topology(out.mesh);
  // An advancing front winds each face from its neighbour's: it makes only orientable
  // surfaces, so a non-orientable sheet (a Moebius band) can never be matched, and the front
  // can take most of the run on such samples (45 of 47 s on a Moebius mesh's 11,200 points).
  if (!out.topology->is_orientable) {
    SampleMeshing report;
    report.sheet_topology = topology_summary(*out.topology);
    report.samples_topology = "no mesh (an advancing front makes only orientable surfaces)";
    out.sample_meshing = std::move(report);
    return;
  }
  progress.report("mesh samples", 0.0);
  interpolate::InterpolateResult meshed = interpolate::mesh_samples(samples.points, out.mesh, options);
  // The front's winding depends on where it started: turned by the rule the sheet follows (a
  // closed piece outward, an open one out of the volume its capped borders close), and then,
  // with the samples' normals signed, along them as the sheet would be.
  topology::orient_faces(meshed.mesh);
  SampleMeshing report;
  report.stats = meshed.stats;
  topology::MeshTopology mine = topology::analyze_topology(meshed.mesh);
  report.sheet_topology = topology_summary(*out.topology);
  report.samples_topology = topology_summary(mine);
  report.is_kept = !meshed.mesh.triangles.empty() && mine.is_manifold() && mine.duplicate_faces == 0 &&
                   mine.misoriented_edges == 0 && report.samples_topology == report.sheet_topology;
  // Nor may the samples' mesh pass through itself where the sheet does not (a rim's corner
  // folded over by the front, a hole closed across a fold).
  if (report.is_kept) {
    const std::size_t crossings = mesh::self_intersections(meshed.mesh, 0).face_pairs;
    if (crossings > 0 && crossings > mesh::self_intersections(out.mesh, 0).face_pairs) {
      report.is_kept = false;
      report.samples_topology += ", passes through itself (" + std::to_string(crossings) + " pairs of faces)";
    }
  }
  if (report.is_kept) {
    out.mesh = std::move(meshed.mesh);
    out.topology = std::move(mine);
  }
  out.sample_meshing = std::move(report);
  progress.report("mesh samples", 1.0);
}

// The sheet (or the Power Crust that replaced it) where the samples' mesh was not kept:
// simplified to about as many vertices as there are samples. As extracted it has ten to
// forty times as many (Voronoi vertices, several per envelope sample); a user asked for a
// surface at the resolution of the points given. remesh::simplify keeps the topology and
// passes through itself nowhere the sheet does not, or gives the sheet back.
void simplify_to_samples(ReconstructResult& out, std::size_t samples, const Progress& progress) {
  if (out.mesh.triangles.empty() || samples == 0) return;
  progress.report("simplify", 0.0);
  remesh::SimplifyResult r = remesh::simplify(out.mesh, {.target_vertices = samples});
  out.simplify_stats = r.stats;
  out.seconds.simplify = r.stats.seconds;
  for (auto& w : r.warnings) out.warnings.push_back(std::move(w));
  if (r.stats.is_simplified) {
    out.mesh = std::move(r.mesh);
    out.topology.reset();  // the same numbers, but on other vertices
  }
  progress.report("simplify", 1.0);
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
  const bool is_point_file = !input.is_builtin && !input.is_orientable.has_value();
  // A point file's reach is read off measured positions and boundary curves fitted to its rim
  // samples, whose frames tilt with the rim's wiggles whatever the normals are: the minimum
  // over pairs reads a wiggle, not the surface. Measured on 20,000 samples of the hemisphere
  // (a reach of 1) with its exact normals in the file: the minimum read 0.087 (a rim vertex's
  // conormal tilted 14 degrees by the curve), the 5th percentile 0.95 as without normals.
  if (input.are_normals_estimated || is_point_file) options.envelope.reach_quantile = 0.05;
  if (input.are_normals_estimated) options.use_normal_orientation = input.are_signs_given;
  if (!input.is_builtin) {
    options.sheet.cut_handles_rel_rho = kScanCutHandlesRelRho;
    options.sheet.cut_to_orientable = input.is_orientable.value_or(true);
    options.sheet.orientable_max_twist_loop_rel_rho =
        is_point_file ? extract::kTwistMinLoopRelRho : std::numeric_limits<double>::infinity();
  }
  // A file's samples are the output's vertices (docs/method.md §8.8); a built-in surface's
  // sampling is the caller's choice, and its sheet is the surface to within its exact offsets.
  if (!input.is_builtin) options.mesh_samples = interpolate::InterpolateOptions{};
  options.use_adaptive_retry = !options.envelope.rho.has_value();
  options.use_power_crust_fallback = options.use_adaptive_retry;
  // A built-in surface's rho is the experiments' subject; a file's is chosen for it.
  options.use_local_rho_first = options.use_adaptive_retry && !input.is_builtin;
  options.use_power_crust_first = options.use_local_rho_first;
  options.are_curves_detected = input.is_boundary_detected;
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

// The sets the samples form within 2 rho, counted once and only when a result has several
// pieces (a kd-tree over the input costs about a second per million points).
class SampleGroups {
 public:
  SampleGroups(const envelope::SurfaceSamples& samples, double rho) : samples_(samples), rho_(rho) {}
  std::size_t count() {
    if (!count_) count_ = sample_groups(samples_.points, 2.0 * rho_);
    return *count_;
  }

 private:
  const envelope::SurfaceSamples& samples_;
  double rho_;
  std::optional<std::size_t> count_;
};

// The checks of one run; its topology is kept in run.topology for the report. The border is
// checked against the envelope run's rho (`envelope`: the run's own, or for a Power Crust run
// the envelope run it competes with).
RunDefects defects_of(ReconstructResult& run, const envelope::SurfaceSamples& samples,
                      const envelope::EnvelopeSamples& envelope, SampleGroups& groups) {
  RunDefects d;
  d.is_empty = run.mesh.triangles.empty();
  if (d.is_empty) return d;
  const topology::MeshTopology& t = run.topology.emplace(topology::analyze_topology(run.mesh));
  d.genus = topology::total_genus(t);
  const analysis::BoundaryCheck check = check_result_boundary(t, samples, envelope);
  d.missing_curves = check.missing_curves.size() + check.unresolved_curves.size();
  d.extra_loops = check.extra_loops.size();
  if (t.components.size() > 1) d.extra_pieces = t.components.size() - std::min(t.components.size(), groups.count());
  return d;
}

// A run fails when its result is no manifold, has holes the input has not, more handles than
// the known genus, or any handle while rho had to be raised above half the reach to bridge
// the input's gaps (where the envelope may fold into handles: the uniform rho is too large
// for the thin parts and too small for the sparse ones, which adaptive rho is for).
bool fails(const RunDefects& d, const envelope::EnvelopeSamples& envelope, std::optional<long> max_genus) {
  if (!d.genus || d.extra_loops > 0 || d.extra_pieces > 0) return true;
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
  return missing_curves + extra_loops + extra_pieces + uncovered_patches +
         static_cast<std::size_t>(excess_genus(*genus, max_genus));
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

ResultChecks check_result(const analysis::AnalysisReport& report, const envelope::SurfaceSamples& samples,
                          const ReconstructResult& result, bool are_curves_detected) {
  ResultChecks checks;
  if (result.method == Method::Envelope) {
    checks.boundary = check_result_boundary(report.topology, samples, result.envelope);
  } else {
    std::vector<Polyline> curves;
    for (const BoundaryCurve& c : samples.boundary) curves.push_back(c.polyline());
    checks.boundary = analysis::check_boundary(report.topology, curves, 0.01 * mesh::bbox_diagonal(samples.points));
  }
  const bool are_closed_curves_accepted =
      are_curves_detected && result.power_crust_fallback && result.power_crust_fallback->kept_power_crust;
  const auto& t = report.topology;
  const auto& check = checks.boundary;
  auto& failed = checks.failed;
  if (!t.is_manifold())
    failed.push_back("not a 2-manifold (" + std::to_string(t.non_manifold_edges) + " non-manifold edges, " +
                     std::to_string(t.non_manifold_vertices) + " non-manifold vertices)");
  if (report.self_intersections && report.self_intersections->face_pairs > 0)
    failed.push_back("passes through itself (" + std::to_string(report.self_intersections->face_pairs) +
                     " pairs of faces)");
  if (!check.missing_curves.empty() && !are_closed_curves_accepted)
    failed.push_back(std::to_string(check.missing_curves.size()) + " of the input's " +
                     std::to_string(check.matches.size()) + " boundary curves followed by no border");
  if (!check.extra_loops.empty())
    failed.push_back(std::to_string(check.extra_loops.size()) +
                     (check.extra_loops.size() == 1 ? " border that follows" : " borders that follow") +
                     " no boundary curve of the input (a hole it has not)");
  checks.uncovered_patches = uncovered_patches(result.mesh, samples.points, result.envelope.rho);
  return checks;
}

namespace {

// The set of each point (label, from 0) when each is joined to those of its 8 nearest that lie
// within `reach`; returns the number of sets.
std::size_t label_groups(const std::vector<Point3>& points, double reach, std::vector<std::uint32_t>& label) {
  label.clear();
  if (points.empty()) return 0;
  const NearestIndex index(points);
  topology::UnionFind groups(points.size());
  const auto k = static_cast<unsigned>(std::min<std::size_t>(9, points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    for (const auto& [j, d] : index.nearest(points[i], k))
      if (d <= reach) groups.unite(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
  return groups.label_sets(label);
}

}  // namespace

std::size_t sample_groups(const std::vector<Point3>& points, double reach) {
  std::vector<std::uint32_t> label;
  return label_groups(points, reach, label);
}

std::size_t uncovered_patches(const TriangleMesh& mesh, const std::vector<Point3>& points, double rho) {
  const std::vector<double> d = distance::distances_to_mesh(points, mesh);
  if (d.empty() || !(rho > 0)) return 0;
  std::vector<Point3> far;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (d[i] > 2.0 * rho) far.push_back(points[i]);
  if (far.size() < kMinUncoveredPatch) return 0;
  std::vector<std::uint32_t> label;
  std::vector<std::size_t> size(label_groups(far, 2.0 * rho, label), 0);
  for (const auto l : label) ++size[l];
  return static_cast<std::size_t>(
      std::count_if(size.begin(), size.end(), [](std::size_t n) { return n >= kMinUncoveredPatch; }));
}

namespace {

// The farthest vertex or face centre of `mesh` from the nearest of `points`.
double farthest_from(const TriangleMesh& mesh, const std::vector<Point3>& points) {
  const NearestIndex index(points);
  double farthest = 0;
  for (const auto& v : mesh.vertices) farthest = std::max(farthest, index.nearest(v).second);
  for (const auto& t : mesh.triangles) {
    const Point3 centre = CGAL::centroid(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    farthest = std::max(farthest, index.nearest(centre).second);
  }
  return farthest;
}

// The samples' gap size from each one's distance to its 8th nearest (`rk`): 99% of them are
// at most this far (the quantile the automatic rho bridges, EnvelopeOptions::gap_quantile).
double gap_size(std::vector<double> rk) {
  if (rk.empty()) return 0;
  const auto at = std::min(rk.size() - 1, static_cast<std::size_t>(0.99 * static_cast<double>(rk.size())));
  std::nth_element(rk.begin(), rk.begin() + static_cast<std::ptrdiff_t>(at), rk.end());
  return rk[at];
}

// The direct Power Crust of the samples; `failure` says why it gave nothing, if it threw.
ReconstructResult direct_power_crust(const envelope::SurfaceSamples& samples, const ReconstructOptions& options,
                                     std::string& failure, const Progress& progress) {
  ReconstructOptions direct = options;
  direct.method = Method::PowerCrust;
  direct.remesh.reset();
  try {
    return reconstruct_once(samples, direct, progress);
  } catch (const DegenerateInput& e) {  // coplanar samples: no solid to bound
    failure = e.what();
  } catch (const NumericalFailure& e) {
    failure = e.what();
  }
  return {};
}

// A direct Power Crust already run (the Power Crust first, not kept), reused by the fallback.
struct DirectCrust {
  ReconstructResult run;
  std::string failure;
};

// The direct Power Crust of the samples, in place of a failed envelope run when it has fewer
// defects (ReconstructOptions::use_power_crust_fallback). `earlier`: its run, if made before.
void power_crust_fallback(ReconstructResult& out, const RunDefects& envelope_defects,
                          const envelope::SurfaceSamples& samples, const ReconstructOptions& options,
                          SampleGroups& groups, std::optional<DirectCrust> earlier, const Progress& progress) {
  PowerCrustFallback fallback;
  fallback.input_curves = samples.boundary.size();
  fallback.envelope = envelope_defects;
  ReconstructResult crust;
  if (earlier) {
    crust = std::move(earlier->run);
    fallback.power_crust_failure = std::move(earlier->failure);
  } else {
    crust = direct_power_crust(samples, options, fallback.power_crust_failure, progress);
  }
  fallback.power_crust = defects_of(crust, samples, out.envelope, groups);
  fallback.power_crust.uncovered_patches = uncovered_patches(crust.mesh, samples.points, out.envelope.rho);
  fallback.sample_groups = groups.count();
  fallback.kept_power_crust = fallback.power_crust.is_better_than(fallback.envelope, options.max_genus);
  if (fallback.kept_power_crust) {
    fallback.crust_farthest_from_samples = farthest_from(crust.mesh, samples.points);
    fallback.crust_allowed_distance = gap_size(out.envelope.input_neighbour_distance);
    fallback.kept_power_crust = fallback.crust_farthest_from_samples <= fallback.crust_allowed_distance;
  }
  if (fallback.kept_power_crust) {
    out.mesh = std::move(crust.mesh);
    out.topology = std::move(crust.topology);
    out.power_crust_stats = crust.power_crust_stats;
    out.method = Method::PowerCrust;
    out.warnings = std::move(crust.warnings);  // the envelope run's no longer describe the result
  }
  // A crust run first was counted there.
  if (!earlier) out.seconds.power_crust += crust.seconds.power_crust;
  out.power_crust_fallback = fallback;
}

// The envelope's sheets bridge gaps up to this many rho (as in envelope::sample_envelope).
constexpr double kGapsPerRho = 2.5;

// The gap size of the samples themselves, before any envelope run: the largest distance of
// 99% of them to their 8th nearest (what an envelope run reads from its own distances).
double sample_gap_size(const std::vector<Point3>& points) {
  if (points.size() < 2) return 0;
  const NearestIndex index(points);
  const auto k = static_cast<unsigned>(std::min<std::size_t>(9, points.size()));
  std::vector<double> rk(points.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1024), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      double farthest = 0;
      for (const auto& [j, d] : index.nearest(points[i], k)) farthest = std::max(farthest, d);
      rk[i] = farthest;
    }
  });
  return gap_size(std::move(rk));
}

// The Power Crust first (a closed input): its result when it has no defect at all, else
// nothing, and the run in `tried` for the fallback to reuse; what it did goes in `report`.
std::optional<ReconstructResult> power_crust_first(const envelope::SurfaceSamples& samples,
                                                   const ReconstructOptions& once, PowerCrustFirst& report,
                                                   std::optional<DirectCrust>& tried, const Progress& progress) {
  Stopwatch clock;
  DirectCrust crust;
  crust.run = direct_power_crust(samples, once, crust.failure, progress);
  report.failure = crust.failure;
  // No envelope run yet: the checks read the rho that bridges the samples' gaps.
  envelope::EnvelopeSamples bridging;
  report.allowed_distance = sample_gap_size(samples.points);
  bridging.rho = bridging.rho_min = report.allowed_distance / kGapsPerRho;
  SampleGroups groups(samples, bridging.rho);
  report.defects = defects_of(crust.run, samples, bridging, groups);
  if (!report.defects.is_empty) {
    report.defects.uncovered_patches = uncovered_patches(crust.run.mesh, samples.points, bridging.rho);
    report.farthest_from_samples = farthest_from(crust.run.mesh, samples.points);
  }
  // As the envelope reads it: the rho that bridges the gaps beyond the cap on the reach (80
  // points of an open cylinder give a closed tube without a defect).
  report.is_input_too_sparse =
      bridging.rho > once.envelope.max_reach_rel_diag * mesh::bbox_diagonal(samples.points);
  report.is_kept = !report.defects.is_empty && report.defects.count(once.max_genus) == 0 &&
                   report.farthest_from_samples <= report.allowed_distance && !report.is_input_too_sparse;
  report.seconds = clock.lap();
  if (report.is_kept) {
    crust.run.method = Method::PowerCrust;
    return std::move(crust.run);
  }
  tried = std::move(crust);
  return std::nullopt;
}

// The local-rho first run (ReconstructOptions::use_local_rho_first): its result, or nothing
// when it is not kept; what it did goes in `report` either way.
std::optional<ReconstructResult> local_rho_run(const envelope::SurfaceSamples& samples, const ReconstructOptions& once,
                                               LocalRhoFirst& report, const Progress& progress) {
  Stopwatch clock;
  ReconstructOptions local = once;
  local.envelope.rho = kLocalRhoCeilingRelDiag * mesh::bbox_diagonal(samples.points);
  local.envelope.rho_mode = envelope::RhoMode::Adaptive;
  local.envelope.adaptive_min_rel_rho = kLocalRhoFloorRelCeiling;
  // A cut sized by a rho up to 5% of the diagonal takes real parts with it, and the uniform
  // run's smaller rho needs none there: only a sheet that needed no cut is kept, and the
  // extraction stops at the first one (on broken sheets the repairs after it cost the most).
  local.sheet.stop_after_cut = true;
  ReconstructResult run = reconstruct_once(samples, local, progress);
  report.rho_min = run.envelope.rho_min;
  report.rho_max = run.envelope.rho;
  report.envelope_samples = run.envelope.samples.size();
  if (run.sheet_stats && !run.sheet_stats->stopped_after_cut) {
    SampleGroups groups(samples, run.envelope.rho);
    report.defects = defects_of(run, samples, run.envelope, groups);
    report.is_kept = report.defects->missing_curves == 0 && !fails(*report.defects, run.envelope, local.max_genus);
  }
  if (run.sheet_stats) {
    report.orientation_seams = run.sheet_stats->orientation_seams;
    report.handle_balls = run.sheet_stats->handle_balls;
  }
  report.seconds = clock.lap();
  if (!report.is_kept) return std::nullopt;
  return run;
}

}  // namespace

ReconstructResult reconstruct(const envelope::SurfaceSamples& samples,
                              const ReconstructOptions& options, const Progress& progress) {
  ReconstructOptions once = options;
  once.remesh.reset();
  const bool is_sheet_run = options.method == Method::Envelope && options.extraction == Extraction::Sheet;
  const bool is_rho_automatic = !options.envelope.rho && options.envelope.rho_mode == envelope::RhoMode::Uniform;
  std::optional<PowerCrustFirst> crust_report;
  std::optional<DirectCrust> crust_tried;
  std::optional<ReconstructResult> first;  // the Power Crust first's or the local run's, kept
  if (options.use_power_crust_first && is_sheet_run && is_rho_automatic && samples.boundary.empty() &&
      samples.points.size() >= 4)
    first = power_crust_first(samples, once, crust_report.emplace(), crust_tried, progress);
  std::optional<LocalRhoFirst> local_report;
  if (!first && options.use_local_rho_first && is_sheet_run && is_rho_automatic && samples.points.size() >= 2)
    first = local_rho_run(samples, once, local_report.emplace(), progress);
  const bool is_first_kept = first.has_value();  // then no uniform run, retry or fallback
  ReconstructResult out = first ? std::move(*first) : reconstruct_once(samples, once, progress);
  if (!crust_report || !crust_report->is_kept) out.method = options.method;
  SampleGroups groups(samples, out.envelope.rho);
  std::optional<RunDefects> kept;  // the checks of the kept envelope run, when made
  if (!is_first_kept && options.use_adaptive_retry && is_sheet_run && options.envelope.rho_mode == envelope::RhoMode::Uniform) {
    AdaptiveRetry retry;
    retry.max_genus = options.max_genus;
    retry.uniform = defects_of(out, samples, out.envelope, groups);
    kept = retry.uniform;
    if (fails(retry.uniform, out.envelope, options.max_genus)) {
      once.envelope.rho_mode = envelope::RhoMode::Adaptive;
      ReconstructResult adaptive = reconstruct_once(samples, once, progress);
      retry.adaptive = defects_of(adaptive, samples, adaptive.envelope, groups);
      retry.kept_adaptive = retry.adaptive.is_better_than(retry.uniform, options.max_genus);
      if (retry.kept_adaptive) {
        adaptive.seconds.envelope += out.seconds.envelope;
        adaptive.seconds.extraction += out.seconds.extraction;
        adaptive.method = out.method;
        out = std::move(adaptive);
        kept = retry.adaptive;
      }
      out.adaptive_retry = retry;
    }
  }
  if (!is_first_kept && options.use_power_crust_fallback && is_sheet_run &&
      (samples.boundary.empty() || options.are_curves_detected)) {
    if (!kept) kept = defects_of(out, samples, out.envelope, groups);
    kept->uncovered_patches = uncovered_patches(out.mesh, samples.points, out.envelope.rho);
    // An input too sparse for its size (gaps of a tenth of its diagonal and more) does not
    // tell its shape: the Power Crust of 80 points on the open cylinder is a closed tube.
    // The Power Crust's closed result leaves every curve unfollowed: with as many curves as
    // the envelope run has defects it cannot do better (a range scan's dozen holes).
    if ((fails(*kept, out.envelope, options.max_genus) || kept->uncovered_patches > 0) &&
        !out.envelope.is_input_too_sparse &&
        samples.boundary.size() < kept->count(options.max_genus))
      power_crust_fallback(out, *kept, samples, options, groups, std::move(crust_tried), progress);
  }
  // Set after the retries, which may replace `out` with their own run.
  if (local_report && !local_report->is_kept) out.seconds.envelope += local_report->seconds;
  out.local_rho_first = local_report;
  // The Power Crust first's time, with its checks: the result's own when kept, else added.
  if (crust_report && crust_report->is_kept) out.seconds.power_crust = crust_report->seconds;
  else if (crust_report) out.seconds.power_crust += crust_report->seconds;
  out.power_crust_first = crust_report;
  // The Power Crust's surface, where it replaced the sheet, guides the samples' mesh as well:
  // it too lies on the samples, ten times as finely.
  if (options.mesh_samples && !options.remesh && is_sheet_run) {
    mesh_samples_result(out, samples, *options.mesh_samples, progress);
    if (!out.sample_meshing || !out.sample_meshing->is_kept) simplify_to_samples(out, samples.points.size(), progress);
  }
  remesh_result(out, options.remesh, progress);
  if (options.use_normal_orientation && out.method == Method::Envelope && is_sheet_run)
    topology::orient_along_normals(out.mesh, samples.points, samples.normals);
  if (out.sample_meshing && out.sample_meshing->is_kept) write_in_canonical_order(out.mesh);
  return out;
}

}  // namespace envcrust::pipeline
