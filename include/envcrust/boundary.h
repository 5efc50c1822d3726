// Boundary curves of a surface: detected in a point cloud with normal lines (angle-gap test,
// linking, ordering, frames; docs/method.md §6.3-6.5), or read off a triangle mesh (§3.2).
#pragma once

#include "envcrust/neighbour_table.h"
#include "envcrust/types.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::boundary {

/// Options of detect_boundary. Distances are in units of the average spacing s of the cloud
/// (normals::average_spacing, k 6) unless a field says otherwise.
struct BoundaryOptions {
  /// Neighbours of the angle-gap test, >= 8. 32: at 10k random points k 16 flags ~9% of the
  /// interior (random voids), k 32 ~0.1% while still finding most boundary points (docs/method.md §6.3).
  int neighbors = 32;
  /// A point is a boundary candidate if the largest circular gap between the polar angles of
  /// its neighbours (projected on the tangent plane) exceeds this, degrees in (0, 360).
  /// 110: a boundary point's gap is ~180, random interior voids rarely reach 110 with k 32.
  double gap_threshold_deg = 110.0;
  /// Unflag candidates at a step in the sampling density: the rim of a densely sampled part
  /// where the same sheet goes on, sampled more sparsely (its samples' nearest neighbours all
  /// lie on the dense side, so the angle-gap test flags them). A candidate is at a step if,
  /// past its neighbourhood (the `neighbors` nearest) and up to 8 times as far, in the wedge
  /// within 45 degrees of its conormal (and of its tangent plane, normal lines within 30
  /// degrees), lie at least 2 samples (not counting those flagged facing the same way, a
  /// rim's) whose median own spacing (average distance to their 6 nearest) is over twice
  /// the local spacing of the candidate's neighbourhood, and none of the nearest across the
  /// gap is flagged facing back (a hole's far rim). Measured: a square with a hole whose half
  /// is sampled 10 times more densely (20k points): 89 of the dense half's samples along the
  /// step were boundary points, none is (with link_in_local_spacing, both loops come out
  /// whole); the curves of evenly sampled clouds are unchanged (29 of the detection tests'
  /// 30 clouds byte-identical, the 30th in its last digits). Off by default: on the real
  /// scans the curves moved and the results with them, both ways (the face scan's points
  /// grew a piece of genus 1, the LiDAR tile kept 98 crossings; the bunny view bun000 and
  /// the face came closer to their truth).
  bool drop_density_steps = false;
  /// Link candidates within link_distance local spacings where the surface is sampled more
  /// sparsely than on average (the local spacing of a point: the median over it and its
  /// `neighbors` nearest of their average distance to their 6 nearest; used where it exceeds
  /// 1.5 s, s below 1.33 s, a ramp between), and measure min_loop_length and the smoothing
  /// window in it too. A rim sampled 3 times more sparsely than the average otherwise falls
  /// into pieces, each too short to be kept. Off by default: measured on an annulus whose
  /// half is sampled 10 times more sparsely (20k points), the result is chi 0 with both loops
  /// with it and a disc with one loop 4.46 long without; evenly sampled clouds give the same
  /// curves either way; but on the range scans, whose density varies with the surface's
  /// slope, the rims came out whole where they had fallen into pieces, and the results moved
  /// both ways (the bunny view bun000 and the LiDAR tile b9 each grew a piece with handles).
  bool link_in_local_spacing = false;
  /// Hysteresis: candidates with a gap above this (degrees, in (0, gap_threshold_deg]) are
  /// kept when linked (link_distance, consistent conormals) to a chain reaching a candidate
  /// above gap_threshold_deg. Densifies the boundary band without admitting isolated voids.
  double weak_gap_threshold_deg = 90.0;
  /// The two conormal estimates (neighbour centroid, gap bisector) may differ by at most this
  /// many degrees, in (0, 180]; else the candidate is unreliable and dropped (docs/method.md §6.3).
  double conormal_agreement_deg = 60.0;
  /// Keep a candidate only if, within `support_radius`, other candidates with a consistent
  /// conormal (c_i . c_j > link_min_conormal_dot) exist on both sides along the tangent
  /// t = n x c. Off: measured at 10k points it removes few interior points (false positives are
  /// already ~0.03% with hysteresis) but cuts the sparse boundary chains into pieces (cylinder
  /// 5 loops instead of 2, trefoil ribbon 26 instead of 2).
  bool require_two_sided_support = false;
  /// Radius of the support test, in s, > 0. 3: a few neighbours along a boundary at any N.
  double support_radius = 3.0;
  /// Candidates closer than this (in s, > 0) with consistent conormals are linked into one
  /// curve (with link_in_local_spacing, in the local spacing where that is larger). 5:
  /// 2.5 s would do for s = the nearest-neighbour distance; with CGAL's s the flagged band has
  /// random gaps beyond 2.5 s (10k points: cylinder 12 pieces at 2.5, 2 loops at 4;
  /// 50k points: saddle, Moebius, unknot ribbon still cut once at 4, whole at 5 and 6).
  double link_distance = 5.0;
  /// Linked candidates need c_i . c_j above this, in [-1, 1). 0.5 (60 degrees) separates the
  /// two edges of a thin strip and still follows a 90-degree corner through its diagonal.
  double link_min_conormal_dot = 0.5;
  /// A component's ordered path is closed if its ends are within this (in s, > 0); farther
  /// ends are joined anyway (the boundary of a surface is closed) with a warning. 5: the ends
  /// of a whole loop's path are up to a link length apart (measured 3.5-4.7 s at 50k points).
  double close_distance = 5.0;
  /// Half-width of the moving average applied to the curve resampled at spacing s, >= 0
  /// vertices. 3 (docs/method.md §6.4): removes the band's zig-zag, shrinks a radius-R arc by ~(3s)^2/R.
  int smoothing_half_window = 3;
  /// Components whose ordered centreline (without the closing segment) is shorter than this
  /// (in s, >= 0) are dropped and counted (scan holes, interior voids). 20: at 50k points
  /// chains of false candidates around voids reach 10 s (sphere: 4 false loops at 10 s); a
  /// hole of circumference < 20 s is also below the envelope's resolution (rho ~ 4.5 s fills
  /// holes shorter than 2 pi rho, docs/method.md §8.4). The final loop is held to it too (a
  /// path out and back along one chain, its switchbacks removed, can be left shorter).
  double min_loop_length = 20.0;
  /// Loops narrower than this many local spacings are sampling gaps, not holes, and are
  /// dropped (counted in dropped_loops). Width = 4 area / perimeter of the fitted loop (a disc
  /// reads its diameter, a slot of width w about 2w); local spacing = median over the loop's
  /// points of the distance to their 6th neighbour. 0 (default) keeps every loop. Measured:
  /// the foot scan's ankle reads 13.4, two unsampled stripes on its sole 4.6 and 5.3; the
  /// bunny's base holes 7.3, 8.2 and 3.9 (two holes fused into one loop; measured before open
  /// arcs were joined, when its slots came out as pairs of thin loops). >= 0.
  double min_loop_width = 0.0;
  /// Outer rims beyond which the same sheet goes on at more than this fraction of their
  /// vertices are dropped (counted in dropped_loops, with a warning), in [0, 1]; 1 keeps
  /// every loop. An outer rim: a loop whose conormals point out of it (on average within 60
  /// degrees of away from its centroid); holes are never dropped, since nothing tells a hole
  /// from a gap in the sampling. Beyond a vertex means: in a ball of radius w/4 centred w/2
  /// out along its conormal (w = the loop's width, 4 area / perimeter), within w/8 of its
  /// tangent plane, with a normal line within 30 degrees. Nothing lies there beyond the outer
  /// rim of a surface, but the sparse samples do around a densely sampled patch, whose rim
  /// the angle-gap test flags (all its nearest neighbours lie on the dense side). Measured:
  /// built-in surfaces 0-1% (10k and 50k points, clean and 0.25% noise, where the loops come
  /// out whole), the lion head scan's two dense patches 30% and 32%, the dragon range scan's
  /// outer rims 0-24% but for 4 of 31 (all of them ragged strip borders).
  double max_sampled_beyond = 0.25;
  /// Move each curve vertex along its conormal out to the outermost flagged samples beside it
  /// (less an allowance for their noise): the smoothed centre line of the flagged band lies
  /// inside the band, and the true boundary beyond it. Measured on clean point files of 10
  /// built-in open surfaces (19 runs: 10k points, seeds 1 and 3, and 50k): the reconstruction's
  /// distance from the true boundary (truth to mesh) then stays below 1.1 times the largest gap
  /// between the true boundary and the nearest sample in every run, where the centre line
  /// exceeded it on the cylinder (2.66% of the diagonal against 2.27%), the trefoil ribbon, the
  /// square and the Moebius strip; with 0.25% noise 2 of 16 runs stay over it (by 2% and 4%,
  /// against 2 runs by 15% and 23% on the centre line).
  /// false: the curve stays on the centre line (mean offset about -0.8 s from the truth).
  bool fit_to_outer_samples = true;
  /// With fit_to_outer_samples: then bulge the curve out past any sample, flagged or not,
  /// still beyond it where it runs straight (a lone sample on the rim beside a void, which
  /// the fit's median over 5 vertices leaves out) by more than 3 times the samples' scatter,
  /// where that moves the curve at least a quarter spacing further out. On 60 point files (10
  /// open surfaces, seeds 1, 3, 5, clean and 0.25% noise) truth to mesh fell by 0.03% of the
  /// diagonal on average, up to 0.43% (the clean square, seed 3: 1.88% -> 1.45%, bar 1.86%),
  /// while mesh to truth rose by 0.005% on average. Off by default: on the real scans the
  /// results moved both ways (the bunny 2.27% -> 1.51% truth to mesh but 103 crossings left
  /// at its ear tips; bun045 1.77% -> 4.33%), far from where the curves moved: an
  /// undersampled scan's sheet comes out differently from small changes at its rim.
  bool take_in_samples_beyond = false;
  /// Cut narrow inlets off the detected curves across their mouths: a random void in the
  /// samples beside the rim is flagged like the rim, and the ordered band runs into it and
  /// back out, leaving a slot in the result. An inlet: a section of the curve entered and left
  /// through a mouth (the chord between its ends) at most 0.7 of its length, where the curve
  /// on either side runs the same way (conormals within 60 degrees: not the two sides of a
  /// narrow hole, not an inner corner), going in against that conormal (not a tongue of the
  /// surface), and which with its mouth is shorter than min_loop_length (the length below
  /// which a loop of its own is dropped as a void). Measured on a point file of the cylinder
  /// (10k points, 0.25% noise, seed 3): a void 3 spacings wide beside the top rim made a slot
  /// 0.27 deep (7.6% of the diagonal) in the curve and in the result.
  bool close_narrow_inlets = true;
  /// Output curve vertex spacing (arc length, absolute units, > 0); nullopt: spacing s.
  std::optional<double> curve_spacing;
  /// Move the output curves by this many s along their outward conormal, in [-5, 5], after
  /// fit_to_outer_samples. The samples never reach the true boundary: measured mean offset of
  /// the curve from it -0.78..-0.87 s on the centre line (clean clouds, 10k and 50k), and
  /// about -0.4 s once fitted to the outermost samples (see the detection tests' printout).
  /// The default 0 keeps the curve on the samples (docs/method.md §6.5).
  double outward_offset = 0.0;
};

/// Result of detect_boundary.
struct BoundaryDetection {
  /// Per input point: a boundary candidate (angle gap, hysteresis, optional support test)
  /// in a kept component, i.e. one of the points the returned curves were fitted to.
  std::vector<bool> is_boundary_point;
  /// Per input point: the unit outward conormal estimated at a boundary point, else (0,0,0).
  std::vector<Vector3> conormals;
  /// The boundary loops, each closed, resampled at the output spacing, with t, n, c frames.
  std::vector<BoundaryCurve> curves;
  /// Linked components shorter than min_loop_length (scan holes, interior false positives).
  std::size_t dropped_loops = 0;
  /// Narrow inlets cut off the curves (BoundaryOptions::close_narrow_inlets).
  std::size_t closed_inlets = 0;
  /// Human-readable notes (curves closed across a gap, inconsistent conormals, ...).
  std::vector<std::string> warnings;
  /// The average spacing s of the cloud (k 6), the unit of the options.
  double spacing = 0.0;
  /// Per curve: its width 4 * area / perimeter in local spacings (the median 6th-neighbour
  /// distance of its points), the measure BoundaryOptions::min_loop_width is compared with.
  std::vector<double> loop_widths;
  /// Per curve: the fraction of its vertices beyond which the sheet goes on, 0 for a hole
  /// (see BoundaryOptions::max_sampled_beyond).
  std::vector<double> sampled_beyond;
};

/// Detect the boundary of the surface sampled by `points` with unit normal lines (one per
/// point, sign ignored). Deterministic and independent of the thread count.
/// @throws InvalidOptions naming the field and value; InvalidInput on a size mismatch, a
/// non-finite coordinate or a zero normal; DegenerateInput with fewer points than
/// `neighbors` + 1.
BoundaryDetection detect_boundary(const std::vector<Point3>& points,
                                  const std::vector<Vector3>& normal_lines,
                                  const BoundaryOptions& options = {});

/// The same with the neighbours searched already (a table of `points` with k >= max(6,
/// `neighbors`)): a point file's stages share one search.
/// @throws also InvalidOptions if the table's size or k does not fit.
BoundaryDetection detect_boundary(const std::vector<Point3>& points, const std::vector<Vector3>& normal_lines,
                                  const NeighbourTable& table, const BoundaryOptions& options = {});

/// Boundary curves through boundary points the user gives instead of detecting them (a loop
/// picked in a viewer, the vertices of a known cut, or a `--boundary-out` file edited by hand).
/// Each given point marks its nearest sample, which must lie within `link_distance` spacings;
/// the marked samples are linked, ordered, smoothed and framed as detected ones are. Their
/// outward conormal comes from `given.normals` when present (made tangent to the sample's
/// normal line), else from the direction away from the centroid of the `neighbors` nearest
/// samples. Links reach at least twice the median distance between given points, so a loop
/// may be given sparsely. No loop is dropped for being short or narrow: a group that orders
/// into fewer than 3 curve points is dropped with a warning.
/// @throws InvalidOptions as detect_boundary; InvalidInput if `given` is empty, has a
/// non-finite coordinate, a conormal list of the wrong size, or a point farther than
/// `link_distance` spacings from every sample ("boundary point 12 at (1, 2, 3) is 8.1
/// spacings from the nearest sample").
BoundaryDetection boundary_from_points(const std::vector<Point3>& points,
                                       const std::vector<Vector3>& normal_lines, const PointSet& given,
                                       const BoundaryOptions& options = {});

/// The boundary loops of a triangle mesh (edges with exactly one face), in the order of their
/// first edge in the face list. Per vertex: t along the loop, n = the vertex normal line made
/// perpendicular to t (signs propagated continuously along the loop), c = +-t x n pointing away
/// from the boundary face's third vertex. Where the loop turns by more than 30 degrees the
/// vertex is a corner: t and c belong to the arriving edge, conormal_next to the leaving one.
/// @throws InvalidInput on a bad vertex index, a normal list of the wrong size, or a
/// non-edge-manifold mesh ("edge (12, 40) has 3 faces: the mesh is not a surface").
std::vector<BoundaryCurve> mesh_boundary_curves(const TriangleMesh& mesh,
                                                const std::vector<Vector3>& vertex_normal_lines);

/// The curve resampled so that consecutive vertices are at most `max_spacing` apart (arc
/// length along the polyline), equally spaced between corners; corners are kept as vertices
/// with their frames; t, n, c are interpolated between the old vertices and re-orthonormalised
/// (n aligned in sign with the previous vertex first). @throws InvalidOptions if max_spacing
/// is not > 0; InvalidInput on a curve with fewer than 2 vertices.
BoundaryCurve resample_curve(const BoundaryCurve& curve, double max_spacing);

}  // namespace envcrust::boundary
