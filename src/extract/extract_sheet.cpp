// extract_sheet: raw Voronoi sheet, triangles, cleaning, projection, then the repairs of
// sheet_repair.h (docs/method.md §8).
#include "envcrust/errors.h"
#include "envcrust/extract.h"

#include "sheet_mesh.h"
#include "sheet_projection.h"
#include "sheet_repair.h"
#include "voronoi_sheet.h"

#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"
#include "envcrust/progress.h"
#include "envcrust/topology.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <sstream>

namespace envcrust::extract {
namespace {

void validate(const SheetOptions& o) {
  auto fail = [](const std::string& field, double value) {
    std::ostringstream s;
    s << "SheetOptions::" << field << " out of range (got " << value << ")";
    throw InvalidOptions(s.str());
  };
  if (!(o.min_angle_deg > 90 && o.min_angle_deg < 180)) fail("min_angle_deg", o.min_angle_deg);
  if (!(o.fold_min_angle_deg >= 0 && o.fold_min_angle_deg < o.min_angle_deg))
    fail("fold_min_angle_deg", o.fold_min_angle_deg);
  if (!(o.fold_clearance_rel_rho > 0)) fail("fold_clearance_rel_rho", o.fold_clearance_rel_rho);
  if (!(o.crease_fold_min_angle_deg >= 0 && o.crease_fold_min_angle_deg < o.min_angle_deg))
    fail("crease_fold_min_angle_deg", o.crease_fold_min_angle_deg);
  if (!(o.crease_fold_reach_rel_rho >= 0)) fail("crease_fold_reach_rel_rho", o.crease_fold_reach_rel_rho);
  if (!(o.max_component_distance_rel_rho > 0)) fail("max_component_distance_rel_rho", o.max_component_distance_rel_rho);
  if (!(o.max_component_distance_rel_spacing >= 0))
    fail("max_component_distance_rel_spacing", o.max_component_distance_rel_spacing);
  if (!(o.min_component_area_fraction >= 0 && o.min_component_area_fraction < 1))
    fail("min_component_area_fraction", o.min_component_area_fraction);
  if (!(o.projection_neighbors >= 1)) fail("projection_neighbors", o.projection_neighbors);
  if (!(o.noisy_projection_neighbors >= 1)) fail("noisy_projection_neighbors", o.noisy_projection_neighbors);
  if (!(o.noisy_rel_rho >= 0)) fail("noisy_rel_rho", o.noisy_rel_rho);
  if (!(o.projection_retry_rounds >= 0)) fail("projection_retry_rounds", o.projection_retry_rounds);
  if (!(o.trim_reach_rel_rho > 0)) fail("trim_reach_rel_rho", o.trim_reach_rel_rho);
  if (!(o.max_face_distance_rel_rho >= 0)) fail("max_face_distance_rel_rho", o.max_face_distance_rel_rho);
  if (!(o.fill_loops_shorter_than_rel_rho >= 0)) fail("fill_loops_shorter_than_rel_rho", o.fill_loops_shorter_than_rel_rho);
  if (!(o.orientable_cut_rel_rho > 0)) fail("orientable_cut_rel_rho", o.orientable_cut_rel_rho);
  if (!(o.orientable_max_twist_loop_rel_rho > 0))
    fail("orientable_max_twist_loop_rel_rho", o.orientable_max_twist_loop_rel_rho);
  if (!(o.cut_handles_rel_rho >= 0)) fail("cut_handles_rel_rho", o.cut_handles_rel_rho);
  if (!(o.self_intersection_cut_rel_rho >= 0)) fail("self_intersection_cut_rel_rho", o.self_intersection_cut_rel_rho);
}

// The envelope radius at surface sample i: its local rho (adaptive) or the one rho.
double rho_at(const envelope::EnvelopeSamples& envelope, std::size_t i, std::size_t samples) {
  return envelope.local_rho.size() == samples ? envelope.local_rho[i] : envelope.rho;
}

// Per surface sample: how far a face of the sheet may lie from it, the larger of
// max_face_distance_rel_rho times its rho and its distance to the 8th nearest sample (where
// the input is sparse, the sheet spans gaps wider than rho; the envelope measured it).
std::vector<double> far_distances(const envelope::EnvelopeSamples& envelope, const envelope::SurfaceSamples& surface,
                                  const NearestIndex& index, const SheetOptions& options) {
  const auto& pts = surface.points;
  std::vector<double> out(pts.size());
  const auto& spacing = envelope.input_neighbour_distance;
  const bool known = spacing.size() == pts.size();
  const auto k = static_cast<unsigned>(std::min<std::size_t>(pts.size(), 9));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pts.size(), 1024), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const double gap = known ? spacing[i] : index.nearest(pts[i], k).back().second;
      out[i] = std::max(options.max_face_distance_rel_rho * rho_at(envelope, i, pts.size()), gap);
    }
  });
  return out;
}

// Per surface sample: how far the median vertex of a kept component may lie from it, the
// larger of max_component_distance_rel_rho times its rho and max_component_distance_rel_spacing
// times its distance to the nearest other sample (a point of M lies about that far from the
// nearest sample, whatever rho), at most rho.
std::vector<double> component_distances(const envelope::EnvelopeSamples& envelope,
                                        const envelope::SurfaceSamples& surface, const NearestIndex& index,
                                        const SheetOptions& options) {
  const auto& pts = surface.points;
  std::vector<double> out(pts.size());
  const bool use_spacing = options.max_component_distance_rel_spacing > 0 && pts.size() > 1;
  const auto& nearest = envelope.input_nearest_distance;
  const bool known = nearest.size() == pts.size();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pts.size(), 1024), [&](const auto& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      const double rho = rho_at(envelope, i, pts.size());
      const double spacing = !use_spacing ? 0.0 : known ? nearest[i] : index.nearest(pts[i], 2).back().second;
      out[i] = std::max(options.max_component_distance_rel_rho * rho,
                        std::min(options.max_component_distance_rel_spacing * spacing, rho));
    }
  });
  return out;
}

}  // namespace

SheetResult extract_sheet(const envelope::EnvelopeSamples& envelope,
                          const envelope::SurfaceSamples& surface, const SheetOptions& options,
                          const Progress& progress) {
  validate(options);
  SheetResult result;
  auto& seconds = result.stats.seconds;
  Stopwatch clock;
  // Each step is announced with the share of the stage done before it (the steps' shares of
  // the bunny's extraction time).
  progress.report("sheet: Voronoi polygons", 0.0);
  const RawSheet raw = voronoi_sheet(envelope, options.min_angle_deg,
                                     FoldPairs{.min_angle_deg = options.fold_min_angle_deg,
                                               .crease_min_angle_deg = options.crease_fold_min_angle_deg,
                                               .crease_reach_rel_rho = options.crease_fold_reach_rel_rho,
                                               .clearance_rel_rho = options.fold_clearance_rel_rho,
                                               .creases = &surface.creases});
  result.stats.delaunay_edges = raw.delaunay_edges;
  result.stats.crossing_edges = raw.crossing_edges;
  result.stats.polygons = raw.polygons.size();

  TaggedMesh sheet = triangulate_sheet(raw);
  seconds.voronoi = clock.lap();
  progress.report("sheet: cleaning", 0.14);
  // One kd-tree of the surface samples for every step below.
  const NearestIndex samples(surface.points);
  // Distances that scale with rho use the local rho of the nearest sample (adaptive rho).
  const std::vector<double> max_distance = component_distances(envelope, surface, samples, options);
  const RepairSite site = make_repair_site(envelope, surface, samples, max_distance);
  // Holes below the envelope's resolution where they are: shorter than 2 pi times the local
  // rho along them (adaptive rho), or than 2 pi rho.
  auto fill_small_holes = [&] { return extract::fill_small_holes(sheet, site, options.fill_loops_shorter_than_rel_rho); };
  if (options.max_face_distance_rel_rho > 0)
    result.stats.far_faces_removed = drop_far_faces(sheet, samples, far_distances(envelope, surface, samples, options));
  // Outer medial-axis pieces go first: they would otherwise meet the sheet at non-manifold
  // edges and take part in the repairs.
  result.stats.components_dropped += filter_components(
      sheet, samples, max_distance, 0.0);
  result.stats.non_manifold_faces_removed = resolve_non_manifold_edges(sheet);
  result.stats.vertices_split = split_pinched_vertices(sheet);
  result.stats.components_dropped += filter_components(
      sheet, samples, max_distance, options.min_component_area_fraction);
  if (options.fill_loops_shorter_than_rel_rho > 0) {
    result.stats.holes_filled = fill_small_holes();
    // Filling can pinch where a hole touched another loop.
    result.stats.vertices_split += split_pinched_vertices(sheet);
  }
  compact_vertices(sheet);
  seconds.cleaning = clock.lap();
  progress.report("sheet: projection", 0.24);
  if (options.use_projection) {
    const bool is_noisy = envelope.noise > options.noisy_rel_rho * envelope.rho;
    const auto moved = project_onto_samples(
        sheet, surface, samples, envelope.rho,
        static_cast<unsigned>(is_noisy ? options.noisy_projection_neighbors : options.projection_neighbors),
        static_cast<unsigned>(options.projection_retry_rounds));
    trim_beyond_boundary(sheet, surface, options.trim_reach_rel_rho * envelope.rho);
    // Trimming cuts off crumbs and leaves pinholes where single faces reached past the
    // boundary.
    result.stats.components_dropped += filter_components(
        sheet, samples, max_distance, options.min_component_area_fraction);
    if (options.fill_loops_shorter_than_rel_rho > 0)
      result.stats.holes_filled += fill_small_holes();
    if (options.use_fill_away_from_boundary)
      result.stats.holes_filled += fill_loops_away_from_boundary(sheet, site.boundary_points, 2.0 * envelope.rho, HoleFill::Fan);
    result.stats.vertices_split += split_pinched_vertices(sheet);
    compact_vertices(sheet);
    const auto snapped = snap_border(sheet, surface, envelope.rho,
                                      static_cast<unsigned>(options.projection_retry_rounds));
    result.stats.vertices_projected = moved.moved + snapped.moved;
    result.stats.projections_refused = moved.refused + snapped.refused;
  }
  seconds.projection = clock.lap();
  progress.report("sheet: manifold check", 0.42);
  // Every step above can leave a defect that the next ones do not see (moves put vertices on
  // one point, a fan over a loop through a pinched vertex), so the result is checked as the
  // analyzer reads it, and repaired.
  const ManifoldRepairStats repair = make_manifold(sheet);
  result.stats.vertices_welded = repair.vertices_welded;
  result.stats.final_defects_repaired = repair.non_manifold_edges_found + repair.non_manifold_vertices_found;
  result.stats.faces_dropped_at_defects = repair.faces_dropped;
  result.stats.non_manifold_faces_removed += repair.non_manifold_faces_removed;
  result.stats.vertices_split += repair.vertices_split;
  if (repair.faces_dropped > 0)
    result.warnings.push_back(std::to_string(repair.faces_dropped) +
                              " faces dropped at non-manifold edges or vertices that could not be repaired");
  seconds.manifold_check = clock.lap();
  progress.report("sheet: orientation cut", 0.44);
  // The repairs, last: each closes the holes it leaves.
  const CutHoleOptions holes{.fill_loops_shorter_than_rel_rho = options.fill_loops_shorter_than_rel_rho,
                             .min_component_area_fraction = options.min_component_area_fraction,
                             .fill_cut_holes = options.fill_cut_holes,
                             .close_cut_notches = options.close_cut_notches};
  auto count_holes = [&](const CutHoleStats& h) {
    result.stats.components_dropped += h.components_dropped;
    result.stats.holes_filled += h.small_holes_filled;
    result.stats.cut_holes_filled += h.discs;
    result.stats.cut_notches_closed += h.notches_closed;
  };
  if (options.cut_to_orientable) {
    const OrientationRepairStats r = repair_orientation(
        sheet, site,
        {.cut_rel_rho = options.orientable_cut_rel_rho,
         .max_twist_loop_rel_rho = options.orientable_max_twist_loop_rel_rho},
        holes, result.warnings);
    result.stats.orientation_seams = r.cut.seams;
    result.stats.faces_removed_at_seams = r.cut.faces_removed;
    result.stats.orientation_twists_kept = r.cut.twists_kept;
    count_holes(r.holes);
  }
  seconds.orientable_cut = clock.lap();
  // The sheet as it is once a cut was needed, for a caller that drops it then.
  auto stop = [&] {
    result.stats.stopped_after_cut = true;
    result.mesh = std::move(sheet.mesh);
    return std::move(result);  // captured by reference: a plain return would copy the mesh
  };
  if (options.stop_after_cut && result.stats.orientation_seams > 0) return stop();
  progress.report("sheet: handle cut", 0.66);
  if (options.cut_handles_rel_rho > 0) {
    const HandleRepairStats r =
        repair_handles(sheet, site, {.radius_rel_rho = options.cut_handles_rel_rho}, holes, result.warnings);
    result.stats.handle_balls = r.cut.balls;
    result.stats.faces_removed_at_handles = r.cut.faces_removed;
    count_holes(r.holes);
  }
  seconds.handle_cut = clock.lap();
  if (options.stop_after_cut && result.stats.handle_balls > 0) return stop();
  if (options.self_intersection_cut_rel_rho > 0) {
    progress.report("sheet: self-intersections", 0.9);
    const SelfIntersectionRepairStats r = repair_self_intersections(
        sheet, site,
        {.cut_rel_rho = options.self_intersection_cut_rel_rho, .rounds = options.self_intersection_cut_rounds},
        holes, result.warnings);
    result.stats.self_intersections_found = r.found;
    result.stats.self_intersections_smoothed = r.smoothed;
    result.stats.self_intersections_cut = r.cut;
    result.stats.self_intersection_cut_rounds = r.rounds;
    result.stats.self_intersection_cut_widenings = r.widenings;
    result.stats.faces_removed_at_self_intersections = r.faces_removed;
    result.stats.self_intersections_left = r.left;
    count_holes(r.holes);
  }
  seconds.self_intersection_cut = clock.lap();
  result.mesh = std::move(sheet.mesh);
  // The Voronoi polygons come wound as their Delaunay edges happen to run.
  topology::orient_faces(result.mesh);
  if (result.mesh.triangles.empty())
    result.warnings.push_back("the extracted sheet is empty: the envelope is too sparse for rho");
  return result;
}

}  // namespace envcrust::extract
