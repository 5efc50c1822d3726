// The Power Crust (Amenta, Choi, Kolluri 2001) on CGAL: poles, power diagram, inner/outer
// labels, the crust surface and the power shape (docs/method.md §7).
#pragma once

#include "envcrust/progress.h"
#include "envcrust/types.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::powercrust {

/// Label of a pole: inside or outside the reconstructed solid.
enum class PoleLabel : std::uint8_t { Unknown, In, Out };

/// Marks "no pole" in index fields (a Delaunay cell that is no sample's pole).
inline constexpr Index kNoPole = std::numeric_limits<Index>::max();

/// Threshold presets of the labeling (docs/method.md §7.6): the values the original program runs
/// with (`Code`: theta 0, theta2 0, no -R) or the ones its README claims (`Readme`: 0.4 / 0.3,
/// sampling_estimate 0.6).
enum class LabelPreset { Code, Readme };

/// Options of power_crust. Defaults reproduce the original program's behaviour, except that
/// resolve_unknown is on (the original leaves Unknown poles, which can open the crust).
struct PowerCrustOptions {
  /// Half-width of the bounding cube of the 8 extra points, in units of the largest extent
  /// of the input's bounding box (docs/method.md §7.2). Range (1, 1000]: farther corners make the
  /// poles of the hull samples so large that their power tests lose the input's detail (at
  /// 1e12 a sphere's crust passed through itself).
  double bounding_box_scale = 4.0;
  /// Neighbour-rule threshold on w_pq (original -t). Range [-1, 1]. Set by `preset`
  /// unless overridden.
  std::optional<double> neighbor_threshold;
  /// Second-pass threshold (original -w). Range [-1, 1].
  std::optional<double> second_pass_threshold;
  LabelPreset preset = LabelPreset::Code;
  /// Build the crust surface (the power-diagram faces between In and Out cells).
  bool build_crust = true;
  /// Build the power shape (regular-triangulation simplices among In poles).
  bool build_power_shape = true;
  /// Poles still Unknown after the second pass copy the label of their most deeply
  /// intersecting labeled neighbour, so the crust stays closed (the original leaves them).
  bool resolve_unknown = true;
  /// Keep every finite Delaunay cell with its Voronoi vertex in PowerCrustResult (costs
  /// memory: about 6.5 cells per sample).
  bool keep_delaunay_cells = false;
  /// Point count from which the triangulations are built by parallel insertion, when at least
  /// 4 threads are available (a lock grid costs more than it gains on small inputs or on 2
  /// cores; 0 forces it whatever the thread count). The result is the same either way.
  std::size_t parallel_insertion_from = 200000;
  /// The power diagram is built of the poles moved by a deterministic pseudo-random offset of
  /// up to this fraction of the smaller of each pole's radius and the samples' bounding-box
  /// diagonal, per coordinate (Pole::center stays exact; crust vertices are the moved
  /// diagram's, so the crust moves by about as much). 0 turns it off. Range [0, 1e-2]. Exact
  /// samples put whole families of poles in degenerate position: a sphere's inner poles all at
  /// its centre (the regular triangulation falls back to exact arithmetic: 17 s instead of
  /// 1.6 s at 300k samples), a torus's on its core circle and the hole's outer poles on its
  /// axis, where every axis pole's power cell touches every core pole's (exact torus, 100k
  /// samples: 411 s and 14.5 GB without it, 21 s and 0.4 GB with 1e-4). Poles the offsets
  /// hide take the label of the pole that hides them.
  double pole_joggle = 1e-4;
  /// Noisy input: poles whose radius is below this many local sample spacings (per sample,
  /// the median of the nearest-neighbour distances of it and its Delaunay neighbours) are left
  /// out of the power diagram, as the big-Delaunay-ball filter of Dey and Goswami for noisy
  /// samples does: noise makes small Voronoi balls near the surface whose labels are
  /// unreliable, and each mislabelled one is a handle or a bubble in the crust (measured:
  /// sphere and torus, 50k samples with 0.1% noise, 3 seeds each: chi -12..-2 off, right at 3).
  /// They are kept as hidden poles (labelled like the pole whose cell holds them). 0: off
  /// (the original program's behaviour). Range >= 0.
  double min_pole_radius_rel_spacing = 0.0;
  /// The original's -R r, an estimate of the sampling density (the input an r-sample): per
  /// sample s, every Voronoi vertex v of its cell seen from s within 2r radians of the tangent
  /// plane (|cos angle(v - s, p+ - s)| < cos 2r) bounds lfs(s) from below by
  /// |v - s| (sin angle - r) / r, and a second pole nearer to s than that bound is bad: left
  /// out of the power diagram unless another sample keeps it (then hidden, labelled like the
  /// pole that holds it) and not paired with p+ for the opposite rule. 1 is off (what the
  /// original's main() runs); unset: the preset's (Code 1, Readme 0.6, the value its README
  /// gives). Range (0, 1].
  std::optional<double> sampling_estimate;
  /// With sampling_estimate < 1: a sample with a bad second pole loses its first pole too
  /// (the original's -B).
  bool drop_both_bad_poles = false;
  /// With sampling_estimate < 1 and not drop_both_bad_poles: the first poles of samples with a
  /// bad second pole are labeled last (the original's -D, advised for open surfaces): the
  /// priority queue passes them by, and the second pass decides them from their neighbours.
  bool defer_bad_first_poles = false;
};

/// One pole: a Voronoi vertex of the samples (a Delaunay cell's circumcentre) chosen as p+ or
/// p- of at least one sample, with its polar-ball radius and label.
struct Pole {
  Point3 center;
  double radius = 0.0;
  PoleLabel label = PoleLabel::Unknown;
  bool is_hidden = false;  ///< empty power cell: not a vertex of the regular triangulation
};

/// The two poles of a sample (indices into PowerCrustResult::poles) and the cosine-based
/// weight w = -cos angle(p+ - s, p- - s) in [0, 1].
struct SamplePoles {
  Index outer = 0;  ///< p+: farthest Voronoi vertex of the sample's cell
  Index inner = 0;  ///< p-: farthest on the other side
  double weight = 0.0;
  /// False when the second pole was bad (PowerCrustOptions::sampling_estimate): the pair
  /// takes no part in the opposite rule.
  bool is_paired = true;
};

/// A finite cell of the Delaunay triangulation of the samples and the 8 bounding points, with
/// its circumcentre (a Voronoi vertex). Vertex ids below samples.size() are samples; id
/// samples.size() + k is PowerCrustResult::bounding_points[k].
struct DelaunayCell {
  std::array<Index, 4> vertices{};  ///< ascending
  Point3 center;
  double radius = 0.0;
  Index pole = kNoPole;  ///< the pole this cell became (after welding), or kNoPole
};

/// The power shape: simplices of the regular triangulation whose vertices are all In poles
/// (the approximate interior medial axis), deduplicated, indices into `poles`.
struct PowerShape {
  std::vector<std::array<Index, 2>> edges;
  std::vector<std::array<Index, 3>> triangles;
  std::vector<std::array<Index, 4>> tetrahedra;
};

/// Time per stage in seconds and counts, for reports.
struct PowerCrustStats {
  std::size_t input_points = 0;
  std::size_t duplicate_points = 0;  ///< exact duplicates merged
  std::size_t delaunay_cells = 0;
  std::size_t poles = 0;
  std::size_t welded_poles = 0;  ///< distinct cells whose circumcentre equals an earlier pole's
  /// unknown_poles: left Unknown by the second pass (as the original would);
  /// resolved_unknown_poles: of those, labeled by options.resolve_unknown.
  std::size_t inner_poles = 0, outer_poles = 0, unknown_poles = 0, hidden_poles = 0;
  std::size_t filtered_poles = 0;  ///< left out by min_pole_radius_rel_spacing (counted as hidden too)
  /// Samples whose second pole was bad (sampling_estimate), and poles left out for it
  /// (counted as hidden too).
  std::size_t bad_second_poles = 0, bad_poles_left_out = 0;
  std::size_t deferred_poles = 0;  ///< first poles labeled last (defer_bad_first_poles)
  std::size_t resolved_unknown_poles = 0;
  std::size_t power_diagram_cells = 0;   ///< finite cells of the regular triangulation
  std::size_t crust_polygons = 0;        ///< power faces between In and Out cells
  std::size_t unbounded_crust_faces = 0; ///< In-Out faces reaching infinity (skipped)
  std::size_t crust_faces = 0;           ///< triangles of the crust
  double seconds_delaunay = 0, seconds_poles = 0, seconds_power_diagram = 0,
         seconds_labeling = 0, seconds_crust = 0, seconds_power_shape = 0;
};

/// Everything power_crust computes.
struct PowerCrustResult {
  std::vector<Point3> samples;             ///< distinct input points (duplicates merged)
  std::vector<Index> input_to_sample;      ///< for each input point, its sample
  std::vector<SamplePoles> sample_poles;   ///< per sample
  std::vector<Pole> poles;
  std::array<Point3, 8> bounding_points{}; ///< corners of the bounding cube (docs/method.md §7.2)
  std::vector<DelaunayCell> delaunay_cells;///< when options.keep_delaunay_cells, sorted by vertices
  /// The crust (when built): fan-triangulated power faces between In and Out cells, outward
  /// oriented. One vertex per power-diagram vertex (regular-triangulation cell): each sample
  /// is a degenerate power vertex that several cells share, so a few vertices coincide in
  /// position there. As indexed, the mesh is a closed oriented surface; welding by position
  /// can pinch it where noise splits the In cells around a sample (analyze it with
  /// TopologyOptions::weld_identical_vertices = false).
  TriangleMesh crust;
  /// Per crust triangle: the {In pole, Out pole} regular-triangulation edge whose dual power
  /// face it triangulates (the face's outward normal points from the first to the second).
  std::vector<std::array<Index, 2>> crust_face_poles;
  PowerShape power_shape;                  ///< when built
  PowerCrustStats stats;
  std::vector<std::string> warnings;
};

/// Run the Power Crust on a point sample of a closed surface.
/// @throws InvalidInput on a non-finite coordinate ("point 12 has a non-finite coordinate").
/// Deterministic: the result does not depend on the number of threads.
/// @throws DegenerateInput with fewer than 5 distinct points or when all are coplanar or
/// collinear ("all 100 points are coplanar: nothing to reconstruct").
/// @throws Error "power crust cancelled" when progress.cancel is set (checked between stages).
/// @throws InvalidOptions on an out-of-range option (names the field and value).
PowerCrustResult power_crust(const std::vector<Point3>& points,
                             const PowerCrustOptions& options = {}, const Progress& progress = {});

}  // namespace envcrust::powercrust
