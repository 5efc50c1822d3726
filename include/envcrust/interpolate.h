// The output at the input's resolution: the samples themselves meshed by CGAL's advancing
// front, with only the candidate triangles that lie along the extracted sheet allowed. The
// sheet (the envelope's medial axis) decides where the surface is and where it ends; the
// samples give the vertices. docs/method.md §8.8.
#pragma once

#include "envcrust/types.h"

#include <cstddef>
#include <vector>

namespace envcrust::interpolate {

/// Options of mesh_samples.
struct InterpolateOptions {
  /// A candidate triangle is refused when its centre lies farther than this many local
  /// spacings (of its corners, the largest; a sample's local spacing is its mean distance to
  /// its 6 nearest) from the sheet. A triangle
  /// that follows the surface lies within a small fraction of a spacing of it; one across a
  /// hole, a gap between two parts or the inside of a thin part lies about half the gap away.
  double max_sheet_distance_rel_spacing = 0.5;
  /// A candidate triangle is refused when its normal line and the sheet's there are more than
  /// acos(this) apart (0.5: 60 degrees): a triangle standing across the surface.
  double min_normal_cosine = 0.5;
  /// Holes of the meshed samples whose vertices lie, at the median, farther than this many
  /// local spacings (the largest along the hole) from the sheet's border are closed (the front
  /// stopped short of triangles the sheet covers). Of the loops along one border loop of the
  /// sheet the closest is the surface's boundary and stays; the others are closed too.
  double border_reach_rel_spacing = 3.0;
  /// Holes longer than this many local spacings are left open (and the result then disagrees with
  /// the sheet's topology): a flat patch over a large gap would not follow the surface.
  double max_filled_hole_rel_spacing = 24.0;
  /// Samples farther off the sheet than this many local spacings are moved towards it, to
  /// this distance, before they are meshed: the sheet, built from all the samples, is where a
  /// noisy surface lies. Noise of half a spacing lies 0.44 spacing off at the median, and
  /// pulled in to 0.25 the front stops zig-zagging across it.
  double max_sample_offset_rel_spacing = 0.25;
  /// ... when the samples lie, at the median, this many local spacings or more off the sheet
  /// (noise). Closer, they are exact (median 0.003-0.03 on the development set; noise of half a
  /// spacing reads 0.44): their far ones lie at creases and corners, which the sheet rounds off
  /// and the samples have right, and none is moved.
  double min_noise_offset_rel_spacing = 0.1;
  /// Samples farther off the sheet than this many local spacings (or, when noisy, this many
  /// times the samples' median offset) are left out of the mesh: the sheet, and with it the
  /// surface, does not pass by them. Creases leave exact samples up to 0.93 spacing off on the
  /// development set (fandisk); strays the outlier filter kept lie farther, and pulled in they
  /// crowd the sheet's border (a cylinder's rim then passes through itself).
  double max_meshed_offset_rel_spacing = 1.5;
};

/// What mesh_samples did.
struct InterpolateStats {
  double spacing = 0.0;                  ///< median local spacing of the samples
  std::size_t candidates_refused = 0;    ///< candidate triangles the sheet refused
  std::size_t holes_filled = 0;          ///< holes closed off the sheet's border
  std::size_t holes_left = 0;            ///< holes off the sheet's border too long to close
  std::size_t samples_moved = 0;         ///< samples moved towards the sheet (see max_sample_offset_rel_spacing)
  std::size_t samples_left_out = 0;      ///< samples too far off the sheet to mesh (max_meshed_offset_rel_spacing)
  double median_offset_rel_spacing = 0;  ///< median distance of the samples to the sheet, in local spacings
  double seconds = 0.0;
};

/// The meshed samples: vertices are the used samples (in their input order; noisy ones moved
/// towards the sheet, see InterpolateOptions::max_sample_offset_rel_spacing), faces wound
/// consistently where the piece is orientable. Samples farther off the sheet than
/// InterpolateOptions::max_meshed_offset_rel_spacing, and those no face reached, are not
/// vertices (InterpolateStats::samples_left_out counts the first). `sample_of[v]` is the
/// index in `samples` of vertex v.
struct InterpolateResult {
  TriangleMesh mesh;
  std::vector<std::size_t> sample_of;
  InterpolateStats stats;
};

/// Mesh `samples` along `sheet` (the extracted medial sheet of their envelope). The advancing
/// front makes an orientable surface: a non-orientable sheet (a Moebius band) is not followed
/// across its twist, which the caller sees as a different topology. Empty result for fewer
/// than 3 samples or an empty sheet.
InterpolateResult mesh_samples(const std::vector<Point3>& samples, const TriangleMesh& sheet,
                               const InterpolateOptions& options = {});

}  // namespace envcrust::interpolate
