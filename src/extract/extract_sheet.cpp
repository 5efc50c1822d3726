// extract_sheet: raw Voronoi sheet, triangles, cleaning, projection (docs/method.md §8).
#include "envcrust/errors.h"
#include "envcrust/extract.h"

#include "sheet_mesh.h"
#include "sheet_projection.h"
#include "voronoi_sheet.h"

#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"
#include "envcrust/progress.h"
#include "envcrust/topology.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace envcrust::extract {
namespace {

// Notches a cut leaves in the rim (SheetOptions::close_cut_notches), in rho: border vertices
// within kNotchOnCurve of a curve lie on it (snapped ones lie on it exactly); a notch reaches
// kNotchMinDepth in (a cut ball of 0.5 rho, the self-intersection cut's, reaches about that
// far), and spans at most kNotchMaxWidth along the curve (a handle ball of 1.5 rho: 3 rho).
constexpr double kNotchOnCurve = 0.1;
constexpr double kNotchMinDepth = 0.25;
constexpr double kNotchMaxWidth = 4.0;
// A self-intersection cut round that leaves no fewer pairs is retried with twice the radius,
// up to this many times the first radius. Measured on the face scan's points:
// at 0.5 rho a round left its 84 pairs, at 1 rho none.
constexpr double kMaxCutWidening = 4.0;

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
  // Holes below the envelope's resolution where they are: shorter than 2 pi times the local
  // rho (that of the nearest sample; adaptive rho), or than 2 pi rho.
  const bool is_rho_local = envelope.local_rho.size() == surface.points.size();
  auto fill_small_holes = [&]() -> std::size_t {
    const double bound = options.fill_loops_shorter_than_rel_rho;
    if (!is_rho_local) return fill_short_loops(sheet, bound * envelope.rho);
    return fill_short_loops(sheet, bound, [&](const Point3& p) { return envelope.local_rho[samples.nearest(p).first]; });
  };
  std::vector<Point3> boundary_points;
  for (const auto& c : surface.boundary)
    for (const auto& b : c.vertices) boundary_points.push_back(b.position);
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
      result.stats.holes_filled += fill_loops_away_from_boundary(sheet, boundary_points, 2.0 * envelope.rho, HoleFill::Fan);
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
  // After a cut: the removed bands or balls leave crumbs between them (dropped) and
  // pinholes where a band or ball barely touched the sheet (fanned, as every hole below the
  // envelope's resolution is); with fill_cut_holes every hole away from the boundary curves
  // is closed by a smooth disc, once the pieces the cut has separated from every boundary
  // curve are dropped. Returns the text the cut's warning ends with.
  // Pinholes fanned, then (with fill_cut_holes) the holes away from the boundary curves
  // closed with discs, optionally once the pieces cut off from every curve are dropped.
  // Returns the number of discs.
  auto close_holes = [&](bool drop_cut_off_pieces) -> std::size_t {
    if (options.fill_loops_shorter_than_rel_rho > 0)
      result.stats.holes_filled += fill_small_holes();
    if (!options.fill_cut_holes) return 0;
    if (drop_cut_off_pieces)
      result.stats.components_dropped += drop_pieces_away_from_boundary(sheet, boundary_points, 2.0 * envelope.rho);
    const std::size_t filled = fill_loops_away_from_boundary(sheet, boundary_points, 2.0 * envelope.rho, HoleFill::Patch);
    // A cut that reached the rim opened a notch in it rather than a hole: closed back to the
    // curve (a disc glued along an arc of the border: the topology stays).
    if (options.close_cut_notches)
      result.stats.cut_notches_closed += close_border_notches(sheet, surface, kNotchOnCurve * envelope.rho,
                                                              kNotchMinDepth * envelope.rho,
                                                              kNotchMaxWidth * envelope.rho);
    return filled;
  };
  auto tidy_after_cut = [&]() -> std::string {
    result.stats.components_dropped +=
        filter_components(sheet, samples, max_distance, options.min_component_area_fraction);
    const std::size_t closed = close_holes(true);
    result.stats.cut_holes_filled += closed;
    // The repair can open holes of its own where it removes faces or splits a vertex:
    // pinholes, fanned too, and slits (on the bunny's ear tip a 4-vertex loop 23 mm long and
    // under 1 mm wide), closed like the cut holes.
    const ManifoldRepairStats repaired = make_manifold(sheet);
    if (repaired.faces_dropped + repaired.non_manifold_faces_removed + repaired.degenerate_faces_removed +
            repaired.vertices_split > 0) {
      result.stats.cut_holes_filled += close_holes(false);
      make_manifold(sheet);
    }
    if (closed == 0) return "";
    return "; " + std::to_string(closed) + " hole" + (closed == 1 ? "" : "s") + " closed with a disc";
  };
  if (options.cut_to_orientable) {
    const OrientableCutStats cut =
        cut_to_orientable(sheet, options.orientable_cut_rel_rho * envelope.rho,
                          options.orientable_max_twist_loop_rel_rho * envelope.rho);
    result.stats.orientation_seams = cut.seams;
    result.stats.faces_removed_at_seams = cut.faces_removed;
    result.stats.orientation_twists_kept = cut.twists_kept;
    if (cut.twists_kept > 0) {
      std::ostringstream w;
      w << "the sheet has " << cut.twists_kept << " orientation-reversing twist" << (cut.twists_kept == 1 ? "" : "s")
        << " that no loop shorter than " << std::setprecision(3) << options.orientable_max_twist_loop_rel_rho
        << " rho reverses: kept as part of the surface (a Moebius strip's twist), not cut";
      result.warnings.push_back(w.str());
    }
    if (cut.seams > 0) {
      const std::string closed = tidy_after_cut();
      result.warnings.push_back("the sheet was non-orientable: " + std::to_string(cut.faces_removed) +
                                " faces removed around " + std::to_string(cut.seams) + " orientation seam" +
                                (cut.seams == 1 ? "" : "s") +
                                (cut.still_non_orientable ? "; still non-orientable after 3 rounds" : "") + closed);
    }
  }
  seconds.orientable_cut = clock.lap();
  progress.report("sheet: handle cut", 0.66);
  if (options.cut_handles_rel_rho > 0) {
    const HandleCutStats cut = cut_local_handles(sheet, options.cut_handles_rel_rho * envelope.rho);
    result.stats.handle_balls = cut.balls;
    result.stats.faces_removed_at_handles = cut.faces_removed;
    if (cut.balls > 0) {
      const std::string closed = tidy_after_cut();
      std::ostringstream w;
      w << "the sheet was not a disc in " << cut.balls << " ball" << (cut.balls == 1 ? "" : "s") << " of radius "
        << options.cut_handles_rel_rho << " rho: " << cut.faces_removed << " faces removed there" << closed;
      result.warnings.push_back(w.str());
    }
  }
  seconds.handle_cut = clock.lap();
  if (options.self_intersection_cut_rel_rho > 0) {
    progress.report("sheet: self-intersections", 0.9);
    // Relaxed first: most folds open without losing faces; what is left is cut out and the
    // holes closed with discs, in rounds (below).
    mesh::SelfIntersections found = mesh::self_intersections(sheet.mesh, 0);
    result.stats.self_intersections_found = found.face_pairs;
    if (found.face_pairs > 0) {
      const std::size_t first = found.face_pairs;
      found = smooth_self_intersections(sheet.mesh, std::move(found), 3);
      result.stats.self_intersections_smoothed = first - std::min(first, found.face_pairs);
      result.stats.self_intersections_cut = found.face_pairs;
      // Each round cuts, closes the holes, then checks what that made: the cut removed every
      // face that passed through another, so only the faces the repairs and discs made can
      // now. A round is kept only when it leaves fewer pairs than it found. A round that would
      // leave less than 3/4 of the faces is undone too: a sheet that crosses itself nearly
      // everywhere (an input far too sparse for its size) is kept rather than cut away, and
      // the report says so.
      const std::size_t faces_at_start = sheet.mesh.triangles.size(), to_cut = found.face_pairs;
      const int max_rounds = std::max(1, options.self_intersection_cut_rounds);
      std::size_t removed = 0;
      int rounds = 0;
      // A round that leaves no fewer pairs is tried again with twice the radius (the discs
      // closing a small cut can pass through the folds around it; a wider cut takes them in),
      // up to kMaxCutWidening times the radius.
      double radius = options.self_intersection_cut_rel_rho * envelope.rho;
      const double max_radius = kMaxCutWidening * radius;
      while (found.face_pairs > 0 && rounds < max_rounds) {
        TaggedMesh previous = sheet;
        const std::size_t removed_now = cut_self_intersections(sheet, found, radius).faces_removed;
        tidy_after_cut();
        if (4 * sheet.mesh.triangles.size() < 3 * faces_at_start) {
          sheet = std::move(previous);
          if (rounds == 0)
            result.warnings.push_back("the sheet passes through itself at " + std::to_string(to_cut) +
                                      " face pairs, too many to cut out (" + std::to_string(removed_now) + " of " +
                                      std::to_string(faces_at_start) + " faces): left as it is");
          break;
        }
        const std::vector<char> made = faces_not_in(sheet.mesh, previous.mesh);
        mesh::SelfIntersections left =
            smooth_self_intersections(sheet.mesh, mesh::self_intersections(sheet.mesh, 0, &made), 3);
        if (left.face_pairs >= found.face_pairs) {
          sheet = std::move(previous);
          if (2 * radius > max_radius) break;
          radius *= 2;
          ++result.stats.self_intersection_cut_widenings;
          continue;
        }
        found = std::move(left);
        removed += removed_now;
        ++rounds;
      }
      if (rounds == 0) result.stats.self_intersections_cut = 0;
      result.stats.self_intersection_cut_rounds = rounds;
      result.stats.faces_removed_at_self_intersections = removed;
    }
    result.stats.self_intersections_left = found.face_pairs;
    if (result.stats.self_intersections_found > 0) {
      std::ostringstream w;
      w << "the sheet passed through itself at " << result.stats.self_intersections_found
        << " face pairs: relaxed there"
        << (result.stats.self_intersections_cut > 0
                ? ", then " + std::to_string(result.stats.faces_removed_at_self_intersections) + " faces removed around the " +
                      std::to_string(result.stats.self_intersections_cut) + " pairs that was not enough for, and the holes closed (" +
                      std::to_string(result.stats.self_intersection_cut_rounds) + " round" +
                      (result.stats.self_intersection_cut_rounds == 1 ? "" : "s") + ")"
                : std::string());
      result.warnings.push_back(w.str());
    }
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
