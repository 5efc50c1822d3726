// The repairs of the cleaned sheet (docs/method.md §8.6-8.7): each a free function with its
// own options and stats, run last, after the cleaning and the projection, and counted.
#pragma once

#include "sheet_mesh.h"

#include "envcrust/envelope.h"
#include "envcrust/nearest_index.h"

#include <cstddef>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace envcrust::extract {

/// Where the sheet is repaired: the samples of M, and the lengths the repairs measure in.
struct RepairSite {
  const envelope::SurfaceSamples& surface;
  const NearestIndex& samples;  ///< kd-tree of surface.points
  /// Per surface sample: how far a kept component's median vertex may lie from it
  /// (filter_components).
  const std::vector<double>& max_component_distance;
  std::vector<Point3> boundary_points;  ///< the vertices of surface.boundary's curves
  double rho = 0;                       ///< the envelope's rho (with a local rho, its largest)
  /// The local rho at a point (adaptive rho: that of the nearest sample); empty when rho is
  /// one number.
  std::function<double(const Point3&)> local_rho;
};

/// The site of `surface` and its envelope.
RepairSite make_repair_site(const envelope::EnvelopeSamples& envelope, const envelope::SurfaceSamples& surface,
                            const NearestIndex& samples, const std::vector<double>& max_component_distance);

/// Fill the holes below the envelope's resolution where they are: border loops shorter than
/// `max_length_rel_rho` times the median local rho along each (fill_short_loops), or times
/// rho. 0 fills none. Returns the number filled.
std::size_t fill_small_holes(TaggedMesh& sheet, const RepairSite& site, double max_length_rel_rho);

/// How the holes a cut leaves are closed (the SheetOptions fields of the same names).
struct CutHoleOptions {
  double fill_loops_shorter_than_rel_rho = 2.0 * std::numbers::pi;
  double min_component_area_fraction = 0.01;
  bool fill_cut_holes = true;
  bool close_cut_notches = true;
};

/// What the closing after a cut did.
struct CutHoleStats {
  std::size_t components_dropped = 0;  ///< crumbs, and pieces cut off from every curve
  std::size_t small_holes_filled = 0;  ///< pinholes fanned (fill_small_holes)
  std::size_t discs = 0;               ///< holes away from the boundary closed with a disc
  std::size_t notches_closed = 0;      ///< notches in the rim closed back to the curve
  CutHoleStats& operator+=(const CutHoleStats& o);
};

/// After a cut: the crumbs between the removed bands or balls dropped, the pinholes fanned,
/// and (with fill_cut_holes) the pieces cut off from every boundary curve dropped and every
/// hole away from the curves closed by a smooth disc, notches in the rim closed back to the
/// curve; then the manifold repaired, and what that repair opened closed the same way.
CutHoleStats close_cut_holes(TaggedMesh& sheet, const RepairSite& site, const CutHoleOptions& options);

/// Cut around orientation seams (cut_to_orientable), in rho.
struct OrientationRepairOptions {
  double cut_rel_rho = 1.0;  ///< > 0
  /// Seams no reversing loop shorter than this crosses are twists of M, kept. > 0.
  double max_twist_loop_rel_rho = std::numeric_limits<double>::infinity();
};
struct OrientationRepairStats {
  OrientableCutStats cut;
  CutHoleStats holes;
};
/// Remove the faces around the sheet's orientation seams and close the holes; warnings say
/// what was cut and what was kept as a twist.
OrientationRepairStats repair_orientation(TaggedMesh& sheet, const RepairSite& site,
                                          const OrientationRepairOptions& options, const CutHoleOptions& holes,
                                          std::vector<std::string>& warnings);

/// Cut the balls where the sheet is not a disc (cut_local_handles), in rho.
struct HandleRepairOptions {
  double radius_rel_rho = 0.0;  ///< > 0
};
struct HandleRepairStats {
  HandleCutStats cut;
  CutHoleStats holes;
};
HandleRepairStats repair_handles(TaggedMesh& sheet, const RepairSite& site, const HandleRepairOptions& options,
                                 const CutHoleOptions& holes, std::vector<std::string>& warnings);

/// Relax, then cut in rounds, where the sheet passes through itself.
struct SelfIntersectionRepairOptions {
  double cut_rel_rho = 0.5;  ///< > 0
  int rounds = 3;            ///< >= 1
};
struct SelfIntersectionRepairStats {
  std::size_t found = 0;     ///< face pairs crossing at the start
  std::size_t smoothed = 0;  ///< opened by relaxing the vertices
  std::size_t cut = 0;       ///< left to the first cut round (0 when no round was kept)
  int rounds = 0;            ///< cut rounds kept
  std::size_t widenings = 0;  ///< rounds undone and tried again with twice the radius
  std::size_t faces_removed = 0;
  std::size_t left = 0;  ///< pairs left in the sheet
  CutHoleStats holes;
};
/// Where faces pass through each other, relax the vertices; where that is not enough, remove
/// the faces within cut_rel_rho rho of the pairs and close the holes, in rounds, each kept only
/// when it leaves fewer pairs (one that leaves no fewer is tried with twice the radius, up to 4
/// times the first), and undone when it would leave less than 3/4 of the faces.
SelfIntersectionRepairStats repair_self_intersections(TaggedMesh& sheet, const RepairSite& site,
                                                      const SelfIntersectionRepairOptions& options,
                                                      const CutHoleOptions& holes, std::vector<std::string>& warnings);

}  // namespace envcrust::extract
