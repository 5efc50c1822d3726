// Small operations on indexed meshes and point lists: bounding boxes, area sampling, welding.
#pragma once

#include "envcrust/types.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace envcrust::mesh {

/// Diagonal of the axis-aligned bounding box of the points (0 for fewer than 2 points).
double bbox_diagonal(const std::vector<Point3>& points);

/// Distinct points in order of first occurrence, and the map from input to them.
struct MergedPoints {
  std::vector<Point3> points;
  std::vector<Index> input_to_merged;
  std::size_t duplicates = 0;  ///< input points dropped as exact copies of an earlier one
};

/// Largest coordinate magnitude the geometry accepts: the power tests of the Power Crust
/// square squared weights (radius^4), which overflow a double near 1e77 (a sphere of radius
/// 1e80 crashed the Power Crust, 1e60 still worked; 1e-25 to 1e25 give the unit sphere's
/// crust and reconstruction exactly, measured 2026-11-28).
inline constexpr double kMaxCoordinate = 1e30;
/// Smallest extent (bounding-box diagonal) accepted, for the same reason at the other end:
/// fourth powers of 1e-80 underflow (a sphere of radius 1e-150 left one pole).
inline constexpr double kMinExtent = 1e-30;
/// Smallest extent accepted as a fraction of the largest coordinate magnitude: a unit
/// sphere moved 1e12 from the origin keeps 4 significant digits, and its Power Crust had
/// degenerate faces and passed through itself.
inline constexpr double kMinExtentRelMagnitude = 1e-9;

/// Refuses points the geometry cannot handle (InvalidInput): a non-finite coordinate ("point
/// 12 has a non-finite coordinate"), one beyond kMaxCoordinate in magnitude ("point 12 (from
/// 0) has a coordinate of magnitude 1e+100, beyond 1e+30: scale the input down"), or points
/// spanning less than kMinExtent, or less than kMinExtentRelMagnitude of their coordinates
/// ("... move the input near the origin"). Points that are all equal pass (counted later).
/// `item` names one point in the messages ("vertex 12 ..." for a mesh's vertices).
void check_coordinates(const std::vector<Point3>& points, const std::string& item = "point");

/// Merge exact duplicates: each group of equal points is represented by its first occurrence.
/// Deterministic whatever the thread schedule.
/// @throws InvalidInput on a coordinate check_coordinates refuses.
MergedPoints merge_duplicate_points(const std::vector<Point3>& points);

/// How many independent directions the points spread in by more than `tolerance` (0 to 3):
/// 0 when all lie within it of one point, 1 of a line, 2 of a plane. Greedy: the farthest
/// point from the first, then from their line, then from the plane of the three.
int spread_dimension(const std::vector<Point3>& points, double tolerance);

/// Total area of the triangles.
double total_area(const TriangleMesh& mesh);

/// Length of a closed polyline (the segment from the last point back to the first included).
double closed_length(const Polyline& curve);

/// Fan-triangulate every polygon around its first vertex (polygons assumed convex-ish).
TriangleMesh triangulate_polygons(const PolygonMesh& mesh);

/// Merge vertices with identical coordinates (exact comparison) and drop vertices that no
/// triangle uses. Triangle indices are remapped; triangle order is kept.
TriangleMesh weld_identical_vertices(const TriangleMesh& mesh);

/// The number of distinct vertex indices the triangles use (what weld_identical_vertices
/// keeps when no two of them coincide).
std::size_t used_vertex_count(const TriangleMesh& mesh);

/// Where a triangle mesh passes through itself: face pairs that meet other than along the
/// vertices and the edge they share (coincident vertices count as shared). A 2-manifold
/// mesh without them is an embedded surface.
struct SelfIntersections {
  std::size_t face_pairs = 0;     ///< intersecting pairs
  std::size_t faces = 0;          ///< faces in at least one pair
  std::vector<Index> face_list;   ///< those faces' indices in the input mesh, ascending
  std::vector<Point3> examples;   ///< centroids of a face of some pairs (sorted; at most max_examples)
};

/// Find the self-intersections (candidates by bounding boxes; each decided in parallel by a
/// separating plane in interval arithmetic, else exact predicates).
/// Degenerate faces, faces with a repeated vertex and repeated faces are left out. With
/// `only_faces` (one flag per face), only the pairs with a flagged face are looked for: a
/// re-check after a local change.
SelfIntersections self_intersections(const TriangleMesh& mesh, std::size_t max_examples = 8,
                                     const std::vector<char>* only_faces = nullptr);

/// Per face, 1 when it has a repeated vertex index or the same vertex set as an earlier face
/// (whatever the winding): what remove_duplicate_faces drops.
std::vector<char> repeated_or_degenerate_faces(const TriangleMesh& mesh);

/// Drop faces with a repeated vertex index and faces with the same vertex set as an earlier
/// face (whatever their winding): scans often repeat triangles, which makes their edges look
/// shared by more than two faces. Returns the number of faces dropped; order is kept.
std::size_t remove_duplicate_faces(TriangleMesh& mesh);

/// The indices of `points` along a Hilbert curve (CGAL's hilbert_sort, deterministic). Loops
/// of neighbour queries in this order stay in one part of a kd-tree: over a point file in
/// random order each query missed the cache (1M points: normal fits 3.9 -> 2.0 s, angle-gap
/// tests 5.2 -> 2.9 s on 2 cores).
std::vector<std::size_t> hilbert_order(const std::vector<Point3>& points);

/// A mesh in an order that keeps neighbours close in memory, and where its vertices came from.
struct SpatiallyOrdered {
  TriangleMesh mesh;
  std::vector<Index> old_vertex;  ///< per vertex of `mesh`, its index in the input
};

/// Renumber the vertices along a Hilbert curve (CGAL's hilbert_sort, deterministic; not its
/// spatial_sort, whose rounds of a randomized order undo the locality) and sort
/// the faces by their smallest new vertex index (stable, windings kept). Meshes built from
/// Voronoi cells come in an order unrelated to space; halfedge algorithms that walk
/// neighbourhoods (edge collapse, remeshing) then miss the cache at every step.
SpatiallyOrdered order_spatially(const TriangleMesh& mesh);

/// The edges along which a mesh bends sharply (creases, as of a CAD part or a folded sheet).
struct SharpEdges {
  std::size_t count = 0;         ///< edges of two faces bent by more than the threshold
  double total_length = 0.0;     ///< their summed length
  double max_bend_deg = 0.0;     ///< the largest bend found (over all edges of two faces)
  std::optional<Point3> sharpest;  ///< the midpoint of the most bent edge, when count > 0
  std::vector<CreaseSegment> segments;  ///< the edges bent by more than the threshold
};

/// The edges shared by exactly two faces (welded by exact coordinates) whose normals make
/// more than `min_bend_deg`: 0 for a flat continuation, 180 for a sheet folded back onto
/// itself. Faces that run the edge the same way (an inconsistent or non-orientable winding)
/// are compared with one normal reversed, so the bend does not depend on the winding.
/// Degenerate faces are left out.
SharpEdges sharp_edges(const TriangleMesh& mesh, double min_bend_deg);

/// `count` points drawn uniformly by area on the triangles, deterministic for `seed`.
std::vector<Point3> sample_by_area(const TriangleMesh& mesh, std::size_t count,
                                   std::uint64_t seed);

}  // namespace envcrust::mesh
