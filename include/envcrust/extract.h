// From the envelope back to M: the medial sheet of the envelope samples as a clean
// 2-manifold triangle mesh with boundary (docs/method.md §8).
#pragma once

#include "envcrust/envelope.h"
#include "envcrust/progress.h"
#include "envcrust/types.h"

#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace envcrust::extract {

/// The shortest orientation-reversing loop of a surface M, in units of an envelope radius
/// rho <= reach/2: 2 pi reach >= 4 pi rho (SheetOptions::orientable_max_twist_loop_rel_rho).
inline constexpr double kTwistMinLoopRelRho = 4.0 * std::numbers::pi;

/// Options of extract_sheet.
struct SheetOptions {
  /// A Delaunay edge pq of the envelope samples crosses the shell when the angle between the
  /// offset directions u_p and u_q is at least this (docs/method.md §8.2: 100 degrees; three
  /// pairwise-selected rim edges cannot fit on a half-circle). Range (90, 180).
  double min_angle_deg = 100.0;
  /// Across a sharp fold of M (a crease bent by b > 80 degrees) the samples either side make
  /// 180 - b < min_angle_deg: an edge whose directions make at least this is also taken when
  /// the segment pq passes within fold_clearance_rel_rho rho of M (the fin of the envelope's
  /// inner medial axis at the fold pairs samples b apart whose segment stays ~0.5 rho off M).
  /// 0 disables; below min_angle_deg.
  double fold_min_angle_deg = 0.0;
  double fold_clearance_rel_rho = 0.25;
  /// The same test where M has creases (SurfaceSamples::creases: a mesh bent by more than 80
  /// degrees along its edges), for the pairs whose generator lies within
  /// crease_fold_reach_rel_rho rho of one. 0 disables; below min_angle_deg.
  double crease_fold_min_angle_deg = 60.0;
  double crease_fold_reach_rel_rho = envelope::kCreaseReachRelRho;
  /// A component of the sheet is kept when the median distance of its vertices to the surface
  /// samples is below this fraction of rho (the outer medial axis of E lies >= R - rho away).
  double max_component_distance_rel_rho = 0.5;
  /// ... or below this many times the nearest sample's distance to its nearest neighbour, if
  /// larger, but at most rho: a point of M lies up to about one sample spacing from the
  /// nearest sample, which is more than 0.5 rho where rho is near the spacing (the face scan
  /// as a mesh, rho 0.51: 59% of M lies farther than 0.5 rho from a sample, and its whole
  /// sheet was dropped; with the spacing, the median ratio is 0.47). Past rho the envelope no
  /// longer bridges the samples' gaps (2.5 rho) and the sheet is not trusted: the cylinder
  /// at 2,000 points and rho 0.002 came out with chi -3190 and pieces 29% of the diagonal
  /// off without the cap. >= 0; 0: rho alone.
  double max_component_distance_rel_spacing = 1.0;
  /// Faces farther than this many (local) rho from every surface sample are dropped first
  /// (and at least the sample's distance to its 8th neighbour, for sparse input): the medial
  /// axis of the region M encloses (the inside of a scanned foot, >= R - rho away) otherwise
  /// stays attached to the sheet. The sheet itself lies within rho^2/64 of M inside and
  /// overshoots the boundary by up to ~0.6 rho (docs/method.md §8.5). >= 0; 0 disables.
  double max_face_distance_rel_rho = 2.0;
  /// Components with less than this fraction of the total area are dropped.
  double min_component_area_fraction = 0.01;
  /// Boundary loops shorter than this many rho are holes below the envelope's resolution
  /// and are filled (a true boundary is much longer than 2 pi rho). 0 disables.
  double fill_loops_shorter_than_rel_rho = 2.0 * 3.141592653589793;
  /// After projection, fill border loops that run along no boundary curve (fewer than half
  /// their vertices within 2 rho of one): holes where the input has a sampling gap wider than
  /// the envelope bridges (the foot scan's sole). Off when the boundary curves are incomplete
  /// and the sheet should show the rest (holes still filled then: only short ones).
  bool use_fill_away_from_boundary = true;
  /// Move interior vertices onto the sampled surface (a weighted least-squares quadric fitted
  /// to their nearest samples' positions and normals) and border vertices onto the nearest
  /// boundary curve, when no incident face folds over in the surface's tangent plane.
  bool use_projection = true;
  /// Samples per quadric fit on clean samples ... 6 (the quadric's unknowns) left the fit
  /// ill-conditioned on a tessellation's regular grid, the nearest six in two rows: measured
  /// on `sample moebius --mesh` (vertices and face centres), rho 0.15-0.18, mesh->truth
  /// 0.6-2.4% of the diagonal with 6, 0.01-0.05% with 12, 0.006-0.009% with 24.
  int projection_neighbors = 12;
  /// ... and on noisy ones (EnvelopeSamples::noise above `noisy_rel_rho` * rho), where the fit
  /// averages the noise over its neighbourhood: measured at 10k points, sigma 0.25% of the
  /// diagonal (seed 3), the largest mesh-to-truth distance is 0.31-0.37% with 12 samples and
  /// 0.14-0.19% with 48 (horn, trefoil and unknot ribbons, saddle, torus, cylinder); 96 gave
  /// 0.12-0.16% where the border did not limit it, at more time. On exact samples 12 give
  /// 0.005-0.031% (`reconstruct builtin:NAME`, every built-in; 6 gave 0.005-0.025%). Both >= 1.
  int noisy_projection_neighbors = 48;
  double noisy_rel_rho = 0.05;
  /// A projection or snap refused because a face would fold is retried up to this many
  /// times, after the neighbours have moved (a rough, noisy sheet unfolds as its vertices
  /// come down onto the surface). >= 0.
  int projection_retry_rounds = 4;
  /// After the projection, faces beyond the boundary curves (offset along the nearest curve
  /// point's outward conormal) are cut off, for vertices within this many rho of a curve;
  /// farther ones are not judged (a part of the surface curling round far from the curve).
  /// Sheet pieces of the rim reach up to about 2 rho out: measured on 10k-point files with
  /// 0.25% noise, 2 left a spike 1.7 rho beyond the trefoil and unknot ribbons' rims, 0.115
  /// from the curve (mesh->truth 1.9% and 2.1% of the diagonal); 3 cut both (0.42%, 0.34%).
  /// Range > 0.
  double trim_reach_rel_rho = 3.0;
  /// For surfaces known to be orientable (scans of solid objects): where the sheet comes out
  /// non-orientable (it crosses itself where a part is thinner than 2 rho or sampled too
  /// sparsely, and the cleaning joins the two sides with a twist), remove the faces within
  /// `orientable_cut_rel_rho` rho (along the mesh) of each orientation seam, leaving a hole
  /// there instead of a cross-cap. Off by default: a Moebius strip is non-orientable.
  bool cut_to_orientable = false;
  double orientable_cut_rel_rho = 1.0;  ///< > 0
  /// With cut_to_orientable: cut only the seams crossed by an orientation-reversing loop
  /// shorter than this (in rho) and keep the others as twists of the surface itself.
  /// Infinity (default): cut every seam. kTwistMinLoopRelRho separates the two when rho is
  /// at most half the reach: a twist of M is at least 2 pi reach long (Fenchel: the shortest
  /// loop in its class curves at most 1/reach), so at least 4 pi rho. > 0.
  double orientable_max_twist_loop_rel_rho = std::numeric_limits<double>::infinity();
  /// For surfaces that are discs at this scale (in rho) everywhere but at their holes: remove
  /// every geodesic ball of this radius that is not a disc once the sheet's own holes inside it
  /// are capped (handles and cross-caps where a thin part was sampled too sparsely; also any
  /// true tube thinner than the ball). 0: off (default). >= 0.
  double cut_handles_rel_rho = 0.0;
  /// After either cut: close each hole it left that runs along no boundary curve (see
  /// use_fill_away_from_boundary) with a smooth disc (refined and faired triangulation of the
  /// hole), so a handle or cross-cap becomes a cap instead of a hole. False keeps the holes.
  bool fill_cut_holes = true;
  /// With fill_cut_holes: a cut that reached the rim leaves a notch in it (a run of border
  /// vertices off the boundary curve, more than 0.25 rho deep, at most 4 rho wide along the
  /// curve), closed back to the curve with a smooth disc glued along the notch, its new border
  /// on the curve. The topology stays. Measured on a point file of the cylinder (10k points,
  /// 0.25% noise, seed 3): a fold at the bottom rim, cut out, left a notch 2.3% of the
  /// diagonal deep.
  bool close_cut_notches = true;
  /// Last: where faces pass through each other (folds that noise or a tight rim leave), relax
  /// the vertices there (smooth_self_intersections); where that is not enough, remove the
  /// faces within this radius (in rho, along the mesh) of them and close the holes away from
  /// the boundary curves with discs. 0: off. >= 0.
  double self_intersection_cut_rel_rho = 0.5;
  /// Cut rounds: after each, the faces the cut's repairs and discs made are checked, relaxed
  /// and cut again where they pass through the sheet; a round that leaves no fewer pairs than
  /// it found is undone and tried again with twice the radius, up to 4 times
  /// self_intersection_cut_rel_rho, then ends the cutting. >= 1.
  int self_intersection_cut_rounds = 3;
  /// Return right after the orientation or the handle cut when either removed anything,
  /// before the cuts that follow (SheetStats::stopped_after_cut): for a caller that drops
  /// such a sheet anyway (reconstruct's local-rho first run).
  bool stop_after_cut = false;
};

/// What extract_sheet did.
struct SheetStats {
  bool stopped_after_cut = false;       ///< SheetOptions::stop_after_cut ended the run early
  std::size_t delaunay_edges = 0;       ///< finite edges examined
  std::size_t crossing_edges = 0;       ///< edges selected by the angle test
  std::size_t polygons = 0;             ///< dual Voronoi polygons kept
  std::size_t components_dropped = 0;   ///< outer medial axis pieces and crumbs
  std::size_t far_faces_removed = 0;      ///< faces beyond max_face_distance_rel_rho
  std::size_t non_manifold_faces_removed = 0;
  std::size_t vertices_split = 0;       ///< pinched vertices split into one per fan
  std::size_t holes_filled = 0;
  std::size_t vertices_projected = 0;
  std::size_t projections_refused = 0;  ///< moves refused because a face would flip
  /// The final manifold check (after projection; vertices at one position count as one, as
  /// analyze_topology welds them): vertices merged, non-manifold edges plus pinched vertices
  /// it found and repaired, and faces it dropped where the repair failed (with a warning).
  std::size_t vertices_welded = 0;
  std::size_t final_defects_repaired = 0;
  std::size_t faces_dropped_at_defects = 0;
  /// SheetOptions::cut_to_orientable: orientation seams found and faces removed around them.
  std::size_t orientation_seams = 0;
  std::size_t faces_removed_at_seams = 0;
  /// Seams left because no reversing loop shorter than orientable_max_twist_loop_rel_rho
  /// crosses them: twists of the surface (a Moebius strip's).
  std::size_t orientation_twists_kept = 0;
  /// SheetOptions::cut_handles_rel_rho: balls that were not discs, and the faces removed.
  std::size_t handle_balls = 0;
  std::size_t faces_removed_at_handles = 0;
  /// SheetOptions::fill_cut_holes: holes left by the cuts closed with a disc.
  std::size_t cut_holes_filled = 0;
  /// Self-intersection cut rounds undone and retried with twice the radius.
  std::size_t self_intersection_cut_widenings = 0;
  /// SheetOptions::close_cut_notches: notches in the rim closed back to the curves.
  std::size_t cut_notches_closed = 0;
  /// SheetOptions::self_intersection_cut_rel_rho: intersecting face pairs found, those that
  /// relaxing the vertices opened, those left to the first cut, the cut rounds kept, the
  /// faces they removed, and the pairs left in the sheet.
  std::size_t self_intersections_found = 0;
  std::size_t self_intersections_smoothed = 0;
  std::size_t self_intersections_cut = 0;
  int self_intersection_cut_rounds = 0;
  std::size_t faces_removed_at_self_intersections = 0;
  std::size_t self_intersections_left = 0;
  /// Wall-clock seconds per step: the Delaunay triangulation of the envelope samples and
  /// the Voronoi polygons; cleaning (far faces, components, manifold repairs, small holes);
  /// projection onto the samples, trimming and the border snap; the final manifold check;
  /// the orientation cut, the handle cut and the self-intersection cut, each with the hole
  /// closing after it.
  struct Seconds {
    double voronoi = 0, cleaning = 0, projection = 0, manifold_check = 0, orientable_cut = 0, handle_cut = 0,
           self_intersection_cut = 0;
  } seconds;
};

/// The extracted sheet.
struct SheetResult {
  TriangleMesh mesh;
  SheetStats stats;
  std::vector<std::string> warnings;
};

/// Extract M from its envelope samples: Voronoi polygons dual to Delaunay edges that cross
/// the shell, one vertex per Delaunay cell, then cleaned into a 2-manifold (non-manifold
/// edges resolved, pinched vertices split, outer pieces and crumbs dropped, small holes
/// filled) and projected onto the surface samples. Works for non-orientable M.
/// @param surface the samples of M the envelope was built from (for distances/projection)
/// @param progress told each step as it begins ("sheet: projection", ...), with the share done
/// @throws DegenerateInput when the envelope has fewer than 5 samples or is flat.
SheetResult extract_sheet(const envelope::EnvelopeSamples& envelope,
                          const envelope::SurfaceSamples& surface,
                          const SheetOptions& options = {}, const Progress& progress = {});

}  // namespace envcrust::extract
