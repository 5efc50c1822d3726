// Internal steps of boundary detection and curve building, shared by the module's sources.
#pragma once

#include "envcrust/boundary.h"

#include "knn.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace envcrust::boundary::detail {

inline double dot(const Vector3& a, const Vector3& b) { return CGAL::scalar_product(a, b); }
inline Vector3 cross(const Vector3& a, const Vector3& b) { return CGAL::cross_product(a, b); }
inline double length(const Vector3& v) { return std::sqrt(v.squared_length()); }
/// v / |v|, or (0,0,0) for a zero vector.
inline Vector3 unit(const Vector3& v) {
  const double l = length(v);
  return l > 0 ? v / l : Vector3(0, 0, 0);
}
/// The part of v perpendicular to the unit vector u, normalised (zero if v is parallel to u).
inline Vector3 unit_perpendicular(const Vector3& v, const Vector3& u) {
  return unit(v - dot(v, u) * u);
}
std::string format_number(double value);

/// Result of the per-point angle-gap test.
struct Candidates {
  std::vector<char> flagged;        ///< per point: gap > weak threshold, conormals agree
  std::vector<char> strong;         ///< per point: flagged and gap > (strong) threshold
  std::vector<Vector3> conormals;   ///< per point: unit outward conormal if flagged
  std::size_t unreliable = 0;       ///< large gap but the two conormal estimates disagree
};

/// The flagged candidates: their indices into the point set and their positions, in order.
struct FlaggedSubset {
  std::vector<std::size_t> ids;
  std::vector<Point3> points;
};
FlaggedSubset flagged_subset(const std::vector<Point3>& points, const Candidates& candidates);

/// Unflags the candidates ids[a] with drop[a] != 0 (flag, strength, conormal); returns how
/// many (support_filter.cpp).
std::size_t unflag(Candidates& candidates, const std::vector<std::size_t>& ids, const std::vector<char>& drop);

/// Angle-gap test on the `neighbors` nearest points of each point (the first of its row of
/// `table`, which has at least as many; angle_gap.cpp).
Candidates angle_gap_candidates(const std::vector<Point3>& points,
                                const std::vector<Vector3>& normals, const NeighbourTable& table,
                                const BoundaryOptions& options);

/// How far boundary candidates link: two are linked if they lie within the longer of their
/// two reaches, one for all points or one per point (of the cloud).
class LinkReach {
 public:
  explicit LinkReach(double uniform) : uniform_(uniform) {}
  explicit LinkReach(std::vector<double> per_point) : per_point_(std::move(per_point)) {}
  double operator()(std::size_t i) const { return per_point_.empty() ? uniform_ : per_point_[i]; }
  /// One reach for all points.
  [[nodiscard]] bool is_uniform() const { return per_point_.empty(); }

 private:
  double uniform_ = 0.0;
  std::vector<double> per_point_;
};

/// Per point of the cloud: its average distance to its 6 nearest (`own`, as the average
/// spacing s is averaged) and the median of that over the point and its `neighbors` nearest
/// (`around`: the spacing of the part of the surface it lies in, not inflated at a rim, where
/// a point's nearest lie on one side) (curve_linking.cpp).
struct LocalSpacings {
  std::vector<double> own;
  std::vector<double> around;
};
LocalSpacings local_spacings(const std::vector<Point3>& points, const NeighbourTable& table, std::size_t neighbors);

/// Per point, `link_distance` times its `around` spacing where that is at least 1.5 s (s the
/// average spacing), times s where it is below 1.33 s, and a ramp between: where a part of
/// the surface is sampled more sparsely than the average its rim's samples are farther apart
/// than the average spacing, while an evenly sampled cloud links as within s (curve_linking.cpp).
LinkReach local_link_reach(const LocalSpacings& spacings, double link_distance, double spacing);

/// Unflag candidates at a step in the sampling density, where the same surface goes on past
/// their `neighbors` nearest points (rows of `table`) at a sparser spacing: among the samples
/// of the sheet (`index` over all points) in the wedge beyond the candidate (within 45 degrees
/// of its conormal, up to 8 neighbourhood radii), those past its neighbourhood (up to 3 times
/// as far as the first) are at least two, their median own spacing is over twice the
/// candidate's `around` spacing, and none of the nearest across the gap faces back (a hole's
/// far rim). Returns how many it unflagged (density_steps.cpp).
std::size_t unflag_density_steps(const std::vector<Point3>& points, const std::vector<Vector3>& normals,
                                 const NeighbourTable& table, const PointIndex& index, const LocalSpacings& spacings,
                                 Candidates& candidates, std::size_t neighbors);

/// A group of linked candidates whose neighbourhoods are no sheet is no rim (sheet_thickness.cpp).
/// Thickness of a point: the root of the smallest over the middle eigenvalue of the covariance
/// of it and its `neighbors` nearest (0 on a plane, about 1 in a ball). A group goes when the
/// median over its points exceeds kMaxGroupThickness and kMaxGroupThicknessRelCloud times the
/// median over the cloud (a noisy cloud is thick everywhere, its rims a little more). Measured
/// on 30,000 samples of 22 meshes (CGAL's example data): the false loops of the closed shapes
/// (armadillo, camel, femur, man, triceratops, pig's one false loop) read 0.41-0.79 on clouds
/// of 0.05-0.14; the true loops of the open shapes 0.01-0.27 (lion's ragged outer rim the
/// highest); rims of clouds with 0.5% and 1% noise of the diagonal 0.58-0.84 on clouds of
/// 0.51-0.77; rotor_small, thin blades all over (cloud 0.58), keeps its loops (0.83-0.89).
inline constexpr double kMaxGroupThickness = 0.35;
inline constexpr double kMaxGroupThicknessRelCloud = 2.0;
/// Removes such groups from `components`; returns how many, with their points in `dropped_points`.
std::size_t drop_thick_groups(const std::vector<Point3>& points, const NeighbourTable& table, std::size_t neighbors,
                              std::vector<std::vector<std::size_t>>& components, std::size_t& dropped_points);

/// The links between the flagged candidates (`subset` of them, numbered in it): pairs within
/// the longer of their reaches with c_i . c_j > min_dot, as adjacency lists (curve_linking.cpp).
std::vector<std::vector<std::size_t>> candidate_links(const FlaggedSubset& subset, const Candidates& candidates,
                                                      const LinkReach& reach, double min_dot);

/// Hysteresis: keep strong candidates and the weak ones reachable from a strong one through
/// links (candidate_links); unflag the rest (support_filter.cpp). Returns the number unflagged.
std::size_t keep_connected_to_strong(const std::vector<Point3>& points, Candidates& candidates,
                                     const LinkReach& reach, double min_dot);

/// Unflag candidates without consistent flagged neighbours on both sides along their tangent
/// within `radius` (support_filter.cpp). Returns the number unflagged.
std::size_t filter_two_sided_support(const std::vector<Point3>& points,
                                     const std::vector<Vector3>& normals, Candidates& candidates,
                                     double radius, double min_dot);

/// Connected components of the flagged points' links (candidate_links), each sorted by index,
/// components ordered by their smallest index (curve_linking.cpp).
std::vector<std::vector<std::size_t>> link_candidates(const std::vector<Point3>& points,
                                                      const Candidates& candidates,
                                                      const LinkReach& reach, double min_dot);

/// An ordered centreline through one component.
struct Centreline {
  Polyline points;         ///< ordered positions (bin averages of the component's points)
  double end_gap = 0.0;    ///< distance between the ends of the ordered diameter path
  double length = 0.0;     ///< length of the closed centreline
  double open_length = 0.0;  ///< its length without the closing segment (last to first)
  double join_gap = 0.0;     ///< made of open arcs: the longest of the joins, else 0
  std::size_t joined_arcs = 0;  ///< made of open arcs: how many, else 0
};

/// Bounds of join_open_arcs, absolute lengths.
struct ArcJoinLimits {
  double close_gap = 0.0;       ///< an arc is open if its ends are farther apart than this
  double min_arc = 0.0;         ///< shorter open arcs are not joined (false-candidate chains)
  double max_join = 0.0;        ///< a join may be this long anywhere ...
  double max_join_local = 0.0;  ///< ... or this many local spacings (6th-neighbour distance)
  double max_join_rel_arc = 0.0;  ///< ... or this fraction of the shorter of its two arcs
};

/// Open arcs (ordered bands whose ends stay apart, such as the flagged pieces of a sparsely
/// sampled rim or the two sides of a slot whose tight ends went unflagged) joined end to end
/// into closed loops: ends matched greedily, shortest join first, each join within the
/// limits; a cycle of arcs, or a chain of them closed across the gap between its free ends,
/// becomes one loop (merged into its first arc) if its joins and that gap are shorter in all
/// than its arcs' own closing gaps. Returns the number of loops made (arc_joining.cpp).
std::size_t join_open_arcs(std::vector<std::vector<std::size_t>>& components, std::vector<Centreline>& lines,
                           const std::vector<Point3>& points, const PointIndex& index, const ArcJoinLimits& limits);

/// Order a component along the diameter path of its linking-graph MST (links within the
/// longer of their ends' reaches), then replace the path by averages of all component points
/// binned by their arc-length position (curve_linking.cpp). With `conormals` (per point of
/// `points`), only links whose conormals make a dot product above `min_conormal_dot` enter
/// the tree, as link_candidates joined the component.
Centreline order_component(const std::vector<Point3>& points,
                           const std::vector<std::size_t>& component, const LinkReach& reach,
                           double bin_width, const std::vector<Vector3>* conormals = nullptr,
                           double min_conormal_dot = -1.0);

/// The NN-crust of points along curves (Dey & Kumar): each point is joined to its nearest
/// neighbour and to the nearest point on the other side of it (b with (b - a).(nearest - a)
/// < 0); then, longest first, joins between two points that both have more than two are
/// dropped (sharp corners). Reconstructs curves sampled unevenly, within a third of their
/// local feature size. Adjacency lists (curve_linking.cpp).
std::vector<std::vector<std::size_t>> nn_crust_edges(const std::vector<Point3>& points);

/// Curves through the flagged points of a given boundary: components of their NN-crust, each
/// with its centreline: a component whose every point has two joins is walked as a cycle
/// (points kept as given), another is ordered by order_component with links as long as its
/// longest join (curve_linking.cpp).
struct GivenCurves {
  std::vector<std::vector<std::size_t>> components;  ///< flagged point ids, sorted
  std::vector<Centreline> centrelines;
};
GivenCurves order_given_points(const std::vector<Point3>& points, const Candidates& candidates,
                               double bin_width);

/// The centre line of a band of boundary candidates as one closed cycle: the band thinned to
/// seeds `radius` apart (greedy, in index order), each seed replaced by the centroid of the
/// band points nearest to it, the centroids joined by their NN-crust, from which spurs and
/// rungs are pruned. nullopt unless that leaves a single cycle (curve_linking.cpp).
std::optional<Polyline> band_cycle(const std::vector<Point3>& points, const std::vector<std::size_t>& component,
                                   double radius);

/// A centreline of `band` along the closed `loop` (an ordering of it, with vertices closer
/// than `bin_width`): band points binned by the arc position of their nearest loop vertex,
/// `bin_width` long bins, each bin's average a vertex; end_gap is the loop's closing segment
/// (curve_linking.cpp).
Centreline bin_along_loop(const Polyline& band, const Polyline& loop, double bin_width);

/// Closed polyline resampled at equal arc length with ceil(L / spacing) vertices
/// (curve_frames.cpp).
Polyline resample_closed(const Polyline& curve, double spacing);

/// The closed polyline without the vertices at which it turns back (turn angle over 90
/// degrees), removed one at a time until none is left or 3 vertices remain: a fit that moves
/// neighbouring vertices by different amounts across a bend can fold the curve onto itself,
/// and a fold's reversed tangent flips the conormal there (curve_frames.cpp).
Polyline remove_switchbacks(const Polyline& curve);

/// Cyclic moving average over 2 h + 1 vertices (h at most (size - 1) / 2).
Polyline smooth_closed(const Polyline& curve, int half_window);
/// The same with h per vertex (`half_windows`, one per vertex of `curve`).
Polyline smooth_closed(const Polyline& curve, const std::vector<int>& half_windows);

/// Frames of a closed curve from the cloud: t by central differences, n = average of the
/// nearest points' normal lines made perpendicular to t (sign propagated along the curve),
/// c = +-t x n with the sign voted by the nearest flagged points' conormals. Appends a
/// warning if the vote is not clear.
BoundaryCurve frame_curve(const Polyline& curve, const std::vector<Point3>& points,
                          const std::vector<Vector3>& normals, const PointIndex& index,
                          const Candidates& candidates, const std::vector<std::size_t>& component,
                          std::size_t curve_id, std::vector<std::string>& warnings);

/// Moves each vertex of a framed curve along its conormal to the farthest of the band's
/// samples beside it (within `spacing` along the tangent and of the tangent plane, their
/// conormals within 60 degrees of the vertex's), less 1.5 times the samples' median scatter
/// across the tangent plane (noise), as a median over the vertex and two neighbours on either
/// side, limited to `max_move` either way; vertices with no such sample stay. Then, with
/// `take_in`, any sample of `points` (`index` over them) still beyond the curve where it runs
/// straight, by more than 3 scatters, is taken in: the curve bulges out past it (outer_fit.cpp).
void fit_to_outer_samples(BoundaryCurve& curve, const std::vector<Point3>& points, const PointIndex& index,
                          const Candidates& candidates, const std::vector<std::size_t>& component,
                          double spacing, double max_move, bool take_in);

/// The curve with each narrow inlet cut off across its mouth: a section entered and left
/// through a mouth at most 0.7 of the section's length, where the curve
/// on either side runs the same way (conormals within 60 degrees: not the two sides of a
/// narrow hole, not a corner), going in against that conormal (a void beside the rim, not a
/// tongue of the surface), and which with its mouth is shorter than `max_loop_length`.
/// Longest first, until none is left; adds the number cut to `closed` (inlets.cpp).
Polyline close_inlets(const BoundaryCurve& curve, double max_loop_length, std::size_t& closed);

}  // namespace envcrust::boundary::detail
