// The raw medial sheet: Voronoi polygons dual to Delaunay edges of the envelope samples that
// cross the shell, one vertex per Delaunay cell.
#pragma once

#include "envcrust/envelope.h"

#include <vector>

namespace envcrust::extract {

struct RawSheet {
  std::vector<Point3> vertices;               ///< one per Delaunay cell used
  std::vector<std::vector<Index>> polygons;   ///< cell vertices around each selected edge
  std::vector<double> polygon_dot;            ///< u_p . u_q of the polygon's Delaunay edge
  std::size_t delaunay_edges = 0;
  std::size_t crossing_edges = 0;
};

/// Build the Delaunay triangulation of the envelope samples and collect the dual polygons of
/// the edges whose offset directions make at least `min_angle_deg`. A cell's vertex is the
/// mean of the midpoints of its selected edges: the midpoint of a crossing edge lies on M to
/// first order, while circumcentres of slivers are thrown far off (METHOD.md §5 c1 probe).
/// An edge whose directions make less than `min_angle_deg` but at least `fold_min_angle_deg`
/// is also taken when the segment pq passes within `fold_clearance_rel_rho` rho of a
/// generator (a point of M): it crosses M at a sharp fold (0 disables).
RawSheet voronoi_sheet(const envelope::EnvelopeSamples& envelope, double min_angle_deg,
                       double fold_min_angle_deg = 0.0, double fold_clearance_rel_rho = 0.25);

}  // namespace envcrust::extract
