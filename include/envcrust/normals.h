// Normal lines of point clouds (CGAL jet/PCA fitting) and of indexed triangle meshes, and the
// average sample spacing of a point cloud (docs/method.md §3.3 and §6.2).
#pragma once

#include "envcrust/mesh.h"
#include "envcrust/neighbour_table.h"
#include "envcrust/types.h"

#include <vector>

namespace envcrust::normals {

/// Average spacing as CGAL::compute_average_spacing defines it (parallel): per point the sum
/// of the distances to its k nearest other points divided by k + 1, averaged over the cloud.
/// This is the "s" of docs/method.md §6.
/// @throws InvalidOptions if k < 2; InvalidInput on a non-finite coordinate;
/// DegenerateInput with fewer than 3 points. k is capped at the number of other points.
double average_spacing(const std::vector<Point3>& points, int k = 6);
/// The same from neighbours searched already (a table of `points` with k >= `k`).
/// @throws also InvalidOptions if the table's size or k does not fit.
double average_spacing(const std::vector<Point3>& points, const NeighbourTable& table, int k);

/// How normal lines are fitted to the k nearest neighbours.
enum class NormalMethod {
  Jet,  ///< CGAL::jet_estimate_normals, degree-2 jet (Monge form) through the neighbours
  Pca   ///< CGAL::pca_estimate_normals, smallest principal axis of the neighbours
};

/// Options of estimate_normal_lines.
///
/// Defaults from tests/normals/point_normals_test.cpp (MethodComparison): 10k seeded points,
/// angle to the exact normal line in degrees, mean / p95 / max; "noisy" = Gaussian noise of
/// sigma 0.25% of the bbox diagonal (about 0.3 s on the sphere, 0.5 s on the trefoil ribbon).
///
///   surface          PCA k16          PCA k24          PCA k32          jet k18
///   sphere  clean    0.52/1.10/2.1    0.48/1.01/1.9    0.46/0.94/2.0    0.001/0.002/0.006
///   sphere  noisy    4.3/8.8/17       2.9/5.8/10       2.2/4.3/8.0      4.6/9.6/35
///   moebius clean    0.36/0.85/2.5    0.36/0.85/2.7    0.36/0.91/2.8    0.013/0.037/0.37
///   moebius noisy    7.7/16/37        4.9/10/19        3.6/7.4/14       8.3/19/59
///   trefoil clean    0.29/0.79/3.3    0.30/0.85/3.3    0.32/0.95/3.9    0.007/0.020/0.09
///   trefoil noisy    11/24/88         7.0/14/76        5.1/10/21        12/29/85
///
/// Jet fitting is ~100x more accurate on exact samples, but PCA's ~0.5 degree is far below
/// what the envelope needs (docs/method.md §2.5: interior normal errors cost ~rho delta^2 / 2), while
/// under noise jet k18 is the worst (tails to 85 degrees). PCA improves with k under noise and
/// is flat in k on clean data; k 24 (not 32) keeps the fit local on sparse clouds, where the
/// neighbourhood radius approaches feature sizes such as the ribbons' width.
struct NormalOptions {
  /// Fitting method. PCA: robust under noise, accurate enough on clean data (table above).
  NormalMethod method = NormalMethod::Pca;
  /// Neighbours per fit (k nearest others; the fit takes the point itself too), >= 6 (a degree-2
  /// jet needs 6). 24: half the noisy error of k 16 at no cost on clean data (table above).
  int neighbors = 24;
  /// Degree of the jet for NormalMethod::Jet, 1..4 (ignored by PCA). 2 fits curvature.
  int jet_degree = 2;
};

/// Unit normal line per point (sign meaningless; no orientation step), in input order.
/// With fewer points than `neighbors` + 1 all points are used as neighbours.
/// @throws InvalidOptions naming the field and value; InvalidInput on a non-finite coordinate;
/// DegenerateInput with fewer than 3 points.
std::vector<Vector3> estimate_normal_lines(const std::vector<Point3>& points,
                                           const NormalOptions& options = {});

/// The same with the neighbours searched already (a table of `points` with k >= `neighbors`;
/// PCA fits each point and the first `neighbors` of its row, as CGAL's pca_estimate_normals
/// would): a point file's stages share one search. Jet fitting searches its own. @throws also InvalidOptions if the table's size or k does not fit.
std::vector<Vector3> estimate_normal_lines(const std::vector<Point3>& points, const NeighbourTable& table,
                                           const NormalOptions& options = {});

/// Per vertex the dominant eigenvector of sum(area_f * n_f n_f^T) over its incident faces:
/// sign-free, so non-orientable meshes (Moebius) work. The sign is chosen to agree with the
/// area-weighted sum of the faces' oriented normals as given (so a consistently oriented mesh
/// gets its usual outward/inward normals); a vertex without a non-degenerate face gets (0,0,0).
/// @throws InvalidInput if a face has a vertex index out of range.
std::vector<Vector3> mesh_vertex_normal_lines(const TriangleMesh& mesh);

/// Options of point_creases.
struct PointCreaseOptions {
  double min_bend_deg = 80.0;  ///< report bends above this (0 flat, 180 folded back), in (0, 180)
  /// Normal lines of a pair must make at least this angle for their planes to meet in a
  /// well-defined line; bends above 180 minus it (plates folded nearly flat) are not found.
  double min_line_angle_deg = 30.0;
  /// The bend read from the positions (the angle between the half-planes through the two
  /// samples) and from the normal lines must agree within this (a noisy normal on a smooth
  /// part reads a line angle that the positions do not bear out).
  double max_disagreement_deg = 20.0;
  int neighbors = 10;  ///< pairs are formed with the k nearest neighbours, k >= 1
};

/// Sharp creases of a sampled surface, from samples with normal lines that jump across them
/// (normals given with a scan of a CAD part, or exact ones): every pair of near neighbours
/// whose tangent planes meet in a line between them, bent by more than `min_bend_deg`, gives
/// a segment of that line twice as long as the pair is apart (so that the segments of
/// neighbouring pairs overlap), with the wedge bisector (from the line into the wedge between
/// the two half-planes). `total_length` is the length of the creases found (a minimum
/// spanning forest of the segments' midpoints, links up to 3 times the pairs' median length),
/// `max_bend_deg` the largest bend among them. Estimated normals (PCA) turn smoothly across a
/// crease and seldom jump enough to be read here.
/// @pre normal_lines.size() == points.size(), unit vectors (sign meaningless).
/// @throws InvalidOptions naming the field and value.
mesh::SharpEdges point_creases(const std::vector<Point3>& points, const std::vector<Vector3>& normal_lines,
                               const PointCreaseOptions& options = {});

}  // namespace envcrust::normals
