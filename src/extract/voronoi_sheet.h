// The raw medial sheet: Voronoi polygons dual to Delaunay edges of the envelope samples that
// cross the shell, one vertex per Delaunay cell.
#pragma once

#include "envcrust/envelope.h"

#include <array>
#include <vector>

namespace envcrust::extract {

struct RawSheet {
  std::vector<Point3> vertices;               ///< one per Delaunay cell used
  std::vector<std::vector<Index>> polygons;   ///< cell vertices around each selected edge
  std::vector<double> polygon_dot;            ///< u_p . u_q of the polygon's Delaunay edge
  std::size_t delaunay_edges = 0;
  std::size_t crossing_edges = 0;
};

/// Which edges below `min_angle_deg` are also taken: those whose directions make at least a
/// fold angle and whose segment pq passes within `clearance_rel_rho` rho of a generator (a
/// point of M), so that it crosses M at a sharp fold.
struct FoldPairs {
  double min_angle_deg = 0.0;         ///< everywhere; 0 disables
  double crease_min_angle_deg = 0.0;  ///< for pairs with a generator near `creases`; 0 disables
  double crease_reach_rel_rho = 2.0;  ///< "near": within this many rho of a crease segment
  double clearance_rel_rho = 0.25;
  const std::vector<CreaseSegment>* creases = nullptr;
};

/// Build the Delaunay triangulation of the envelope samples and collect the dual polygons of
/// the edges whose offset directions make at least `min_angle_deg`, and the fold pairs. A
/// cell's vertex is the mean of the midpoints of its selected edges: the midpoint of a
/// crossing edge lies on M to first order, while circumcentres of slivers are thrown far off
/// (docs/method.md §8.3).
RawSheet voronoi_sheet(const envelope::EnvelopeSamples& envelope, double min_angle_deg, const FoldPairs& folds = {});

}  // namespace envcrust::extract
