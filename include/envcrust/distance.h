// Distances between a mesh and a reference (mesh or point set), both ways, and between curves.
#pragma once

#include "envcrust/types.h"

#include <cstdint>
#include <vector>

namespace envcrust::distance {

/// One-sided distance from a set of query points to a target.
struct DirectedDistance {
  double max = 0.0;
  double mean = 0.0;
  std::size_t samples = 0;
  Point3 worst_point = Point3(0, 0, 0);  ///< query point realizing `max`
};

/// Two-sided comparison of a mesh with a reference.
struct DistanceReport {
  DirectedDistance mesh_to_reference;
  DirectedDistance reference_to_mesh;
  double hausdorff = 0.0;            ///< max of both directions
  double reference_diagonal = 0.0;   ///< bounding-box diagonal of the reference
  [[nodiscard]] double relative(double d) const {
    return reference_diagonal > 0 ? d / reference_diagonal : 0.0;
  }
};

/// Options of the comparisons.
struct DistanceOptions {
  std::size_t samples = 200000;  ///< area samples per mesh side, besides all vertices
  std::uint64_t seed = 1;        ///< seed of the area sampling
};

/// Distance of each point to the nearest point of the mesh's non-degenerate triangles (AABB
/// tree, parallel), in the order of `points`; empty when there is no such triangle or point.
std::vector<double> distances_to_mesh(const std::vector<Point3>& points, const TriangleMesh& mesh);

/// Distance of each point to the nearest reference point (kd-tree, parallel), in the order of
/// `points`; empty when either set is empty.
std::vector<double> distances_to_points(const std::vector<Point3>& points, const std::vector<Point3>& reference);

/// Distance of each point to the nearest point of the triangles (AABB tree, parallel).
DirectedDistance points_to_mesh(const std::vector<Point3>& points, const TriangleMesh& mesh);

/// Distance of each point to the nearest reference point (kd-tree, parallel).
DirectedDistance points_to_points(const std::vector<Point3>& points,
                                  const std::vector<Point3>& reference);

/// Distance of closed curves to the nearest of a set of points, over the curves' vertices and
/// points along their segments at most `max_step` apart (> 0). With a surface's true boundary
/// and its samples: how far the samples leave the boundary, which no reconstruction from them
/// can locate more closely.
/// @throws InvalidInput if max_step is not positive.
DirectedDistance curves_to_points(const std::vector<Polyline>& curves, const std::vector<Point3>& points,
                                  double max_step);

/// Mesh against a reference mesh: vertices plus `samples` area samples on each side.
/// @throws InvalidInput if either mesh has no triangle.
DistanceReport compare_to_mesh(const TriangleMesh& mesh, const TriangleMesh& reference,
                               const DistanceOptions& options = {});

/// Mesh against a reference point set: mesh samples to the nearest reference point (this
/// includes the reference's sampling gaps), and every reference point to the mesh.
/// @throws InvalidInput if the mesh has no triangle or the point set is empty.
DistanceReport compare_to_points(const TriangleMesh& mesh, const std::vector<Point3>& reference,
                                 const DistanceOptions& options = {});

/// Symmetric Hausdorff distance between two closed polylines (vertices and points along
/// segments at 1/8 of the shorter curve's mean edge length, or at 1/200,000 of a curve's
/// length if that is longer, against segments).
double closed_polyline_hausdorff(const Polyline& a, const Polyline& b);

/// The same with the worst (1 - fraction) of each curve's length left out: the largest over
/// both directions of the distance within which `fraction` of the points along one curve
/// (evenly spaced) lie from the other. fraction 1 is the Hausdorff distance.
/// @throws InvalidInput if fraction is not in (0, 1].
double closed_polyline_partial_hausdorff(const Polyline& a, const Polyline& b, double fraction);

}  // namespace envcrust::distance
