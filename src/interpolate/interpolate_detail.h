// Internals of mesh_samples: the sheet as a guide, the guided advancing front, hole closing.
#pragma once

#include "envcrust/interpolate.h"
#include "envcrust/nearest_index.h"

#include <array>
#include <cstddef>
#include <vector>

namespace envcrust::interpolate::detail {

/// The sheet as the front's guide: distance to it and its normal line near a point.
class SheetGuide {
 public:
  explicit SheetGuide(const TriangleMesh& sheet);
  /// Whether a triangle abc lies along the sheet: its centre within `max_distance` of the
  /// sheet and its normal line within acos(min_cosine) of the sheet's there.
  [[nodiscard]] bool allows(const Point3& a, const Point3& b, const Point3& c, double max_distance,
                            double min_cosine) const;
  /// The nearest point of the sheet to p among the faces round its nearest sheet vertex (the
  /// sheet is several times denser than the samples, so that is the nearest point but where
  /// the sheet is coarse); p itself when only degenerate faces are there.
  [[nodiscard]] Point3 nearest_point(const Point3& p) const;

 private:
  // The nearest point to p of the non-degenerate faces round p's nearest sheet vertex, its
  // squared distance (infinite if none) and that face's normal.
  struct Nearest {
    Point3 point;
    double squared_distance;
    Vector3 normal;
  };
  [[nodiscard]] Nearest nearest_on_faces(const Point3& p) const;

  const TriangleMesh& sheet_;
  std::vector<Index> original_;  // the sheet's index of each of used_
  std::vector<Point3> used_;     // the vertices some face uses
  NearestIndex vertex_index_;    // over used_
  std::vector<std::size_t> face_start_;   // CSR: faces of vertex v at face_list_[face_start_[v] ..]
  std::vector<std::size_t> face_list_;
};

/// Candidates with an edge longer than this many local spacings (of their corners, the
/// largest) are refused: the front then closes such a gap by the hole closing, over the
/// samples round it, instead of with a long triangle that cuts a corner of the surface.
/// Measured on 30k-point samples of the development set (largest distance to the truth,
/// unlimited -> 3): nefertiti 0.38 -> 0.22%, holes 0.40 -> 0.32%, head 0.49 -> 0.46%, mushroom,
/// knot1, bear unchanged, same topology, and the stage 1.5-2 times faster. 2 closes about 700
/// holes per 30k samples and is worse on the bear (0.31 -> 0.39%).
inline constexpr double kMaxEdgeRelSpacing = 3.0;

/// The advancing front over `samples` (CGAL's, its default parameters) with the candidates
/// the guide refuses taken out: those farther from the sheet than max_distance_rel_spacing
/// times the largest `spacing` of their corners. Faces index `samples`. Adds the refusals to
/// `refused`.
std::vector<std::array<Index, 3>> guided_front(const std::vector<Point3>& samples,
                                               const std::vector<double>& spacing, const SheetGuide& guide,
                                               const InterpolateOptions& options, std::size_t& refused);

/// Close the holes of `mesh` that lie off the sheet's border (see InterpolateOptions) with
/// CGAL's hole triangulation over their own vertices; counts into `stats`.
void close_holes_off_border(TriangleMesh& mesh, const std::vector<double>& spacing, const TriangleMesh& sheet,
                            const InterpolateOptions& options, InterpolateStats& stats);

/// The samples as the front meshes them: noisy ones (see min_noise_offset_rel_spacing) moved
/// towards the sheet to max_sample_offset_rel_spacing times their local spacing from it, and
/// those farther off than max_meshed_offset_rel_spacing (or, when noisy, as many times their
/// median offset) left out: `is_meshed[i]` says which. Counts into `stats`.
std::vector<Point3> pull_towards_sheet(const std::vector<Point3>& samples, const std::vector<double>& spacing,
                                       const SheetGuide& guide, const InterpolateOptions& options,
                                       std::vector<char>& is_meshed, InterpolateStats& stats);

/// Each sample's mean distance to its 6 nearest others.
std::vector<double> local_spacing(const std::vector<Point3>& samples);

}  // namespace envcrust::interpolate::detail
