// Stray samples of a point cloud: points that lie off the surface their neighbours describe,
// or far from every other point (scanner ghosts, specks in the air).
#pragma once

#include "envcrust/neighbour_table.h"
#include "envcrust/types.h"

#include <cstddef>
#include <vector>

namespace envcrust::outliers {

/// Options of find_outliers. A point p with k nearest other points N is an outlier if
///  - it stands off their plane: its distance r to the least-squares plane of N exceeds both
///    `off_plane_rel_radius` times the radius of N (the distance to the farthest of them) and
///    `off_plane_rel_noise` times the plane residual typical around p (the median, over p and
///    N, of each one's robust residual); or
///  - it is isolated: its mean distance to N exceeds `isolated_rel_spacing` times the median
///    of the same value over N.
/// A point on the surface is within its neighbours' spread of their plane (r about curvature
/// times radius squared, or the noise); a stray point's neighbours are surface points it does
/// not belong to. Thin parts (two sheets in one neighbourhood) widen the residual and keep
/// their points. Defaults measured in tests/outliers: no sample of a built-in surface flagged
/// (1k and 10k samples, clean or with 0.25% noise); of 20 lone samples moved off the surface
/// by 2 average spacings, 18-20 flagged on clean samples, by 4-8 spacings 16-20 (all 20 on
/// the cylinder, trefoil ribbon and sphere), and from about 12 noise sigmas on noisy ones.
struct OutlierOptions {
  unsigned neighbors = 16;              ///< k, >= 6
  double off_plane_rel_radius = 0.5;    ///< r / radius of the neighbourhood, in (0, 1]
  double off_plane_rel_noise = 8.0;     ///< r / typical robust residual, > 0
  double isolated_rel_spacing = 4.0;    ///< mean distance / neighbours' median of it, > 1
};

/// What find_outliers found: a flag per input point and the counts per reason.
struct OutlierReport {
  std::vector<char> is_outlier;  ///< per input point, 1 = outlier
  std::size_t off_plane = 0;     ///< flagged for standing off their neighbours' plane
  std::size_t isolated = 0;      ///< flagged for being far from all others (not off_plane)
  [[nodiscard]] std::size_t count() const { return off_plane + isolated; }
};

/// Flag the outliers of `points` (in parallel; the result does not depend on the threads).
/// With at most `neighbors` + 1 points nothing is flagged.
/// @throws InvalidOptions naming the field and value.
OutlierReport find_outliers(const std::vector<Point3>& points, const OutlierOptions& options = {});

/// The same with the neighbours searched already (a table of `points` with k >= `neighbors`;
/// the first `neighbors` of each row are used): a point file's stages share one search.
/// @throws InvalidOptions also if the table's size or k does not fit.
OutlierReport find_outliers(const std::vector<Point3>& points, const NeighbourTable& table,
                            const OutlierOptions& options = {});

}  // namespace envcrust::outliers
