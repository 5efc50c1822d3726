// The sheet as an indexed triangle mesh with a per-face tag, and its cleaning steps.
#pragma once

#include "envcrust/extract.h"

#include "voronoi_sheet.h"

#include "envcrust/mesh.h"
#include "envcrust/mesh_graph.h"
#include "envcrust/nearest_index.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <unordered_set>
#include <vector>

namespace envcrust::extract {

/// Triangle mesh whose faces remember u_p . u_q of the Delaunay edge they came from.
struct TaggedMesh {
  TriangleMesh mesh;
  std::vector<double> face_dot;
};

/// Triangles: quads split along the shorter diagonal, larger polygons fanned around their
/// centroid (a new vertex), so non-planar polygons stay close to the sheet.
TaggedMesh triangulate_sheet(const RawSheet& sheet);

/// Remove the faces f with remove[f] (tags kept aligned). Returns the number removed.
std::size_t remove_faces(TaggedMesh& tagged, const std::vector<char>& remove);

/// Remove every face with a vertex within `radius` (along mesh edges) of a source vertex,
/// then repair the manifold (a removed band or ball can pinch vertices where it touched the
/// border). `graph` is the edge table of tagged.mesh. Returns the number of faces removed.
std::size_t remove_faces_near(TaggedMesh& tagged, const topology::MeshGraph& graph, std::span<const Index> sources,
                              double radius);

/// Remove duplicate faces; at an edge with >= 3 faces keep the two from the most opposite
/// Delaunay edges (smallest u_p . u_q). Returns the number of faces removed.
std::size_t resolve_non_manifold_edges(TaggedMesh& tagged);

/// Split every vertex whose faces form several fans: fans of fewer than 3 faces are dropped,
/// each other fan gets its own copy moved 1% of its mean edge towards the fan's centroid (so
/// that welding by position cannot pinch it again). Returns the number of copies made.
std::size_t split_pinched_vertices(TaggedMesh& tagged);

/// Keep the components whose median over vertices of d(v, s) / max_distance[s], s the nearest
/// surface sample in `samples` (one max_distance per sample: local rho and spacing set it), is
/// below 1 and whose area is at least `min_area_fraction` of the total, or which are islands:
/// a smaller piece whose vertices lie on at least 20 samples (their nearest, within
/// max_distance) that no vertex of a larger kept piece comes within max_distance of (a
/// speck of a scan apart from the rest, not a crumb of the sheet). Returns the number dropped.
std::size_t filter_components(TaggedMesh& tagged, const NearestIndex& samples,
                              const std::vector<double>& max_distance, double min_area_fraction);

/// Remove the faces whose centroid lies farther than max_distance[s] from its nearest surface
/// sample s: pieces of the medial axis of the region that M encloses (the inside of a foot)
/// hang on the sheet where they meet it and survive the component filter. Returns the count.
std::size_t drop_far_faces(TaggedMesh& tagged, const NearestIndex& samples,
                           const std::vector<double>& max_distance);

/// How a hole is closed.
enum class HoleFill {
  Fan,    ///< triangles from the loop's edges to its centroid (a new vertex)
  Patch,  ///< fill_hole: fill_with_patch, cycle by cycle where the loop passes a vertex
          ///< twice; a fan where no disc is found
};

/// Close the border loop `loop` (vertex ids in order) with a disc of smooth, even triangles:
/// CGAL's hole triangulation of the loop refined to its edge density, or, where CGAL finds
/// none or one that would put a third face on a sheet edge (long, twisted cut holes), rings
/// shrunk from the loop to its centroid relaxed to the membrane; then faired with the loop
/// fixed. New faces get the tag -1. False (nothing added) for a loop of
/// fewer than 3 vertices or through one vertex twice (no disc spans it without a pinch).
/// `sheet_edges` (edge_key) holds at least the sheet's edges between two of the loop's
/// vertices; without it they are looked up over the whole sheet.
bool fill_with_patch(TaggedMesh& tagged, const std::vector<Index>& loop);
bool fill_with_patch(TaggedMesh& tagged, const std::vector<Index>& loop,
                     const std::unordered_set<std::uint64_t>& sheet_edges);

/// Close a border loop with a smooth disc (fill_with_patch); where it passes a vertex twice,
/// one over each of its simple cycles (a fan over the whole loop was a star of slivers from
/// one point, split at the pinch by the repair after it); a fan where no disc is found.
void fill_hole(TaggedMesh& tagged, const std::vector<Index>& loop, const std::unordered_set<std::uint64_t>& sheet_edges);

/// An undirected edge as one key.
inline std::uint64_t edge_key(Index a, Index b) { return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b); }

/// The edges of `mesh` between two vertices of `loops` (edge_key): what fill_with_patch
/// needs for each of them, found in one pass over the faces.
std::unordered_set<std::uint64_t> edges_among(const TriangleMesh& mesh, const std::vector<std::vector<Index>>& loops);

/// Fill the border loops of which fewer than half the vertices lie within `max_distance` of
/// `boundary_points`: such a loop follows no boundary curve of M, so it is a hole of the
/// envelope where the input has a sampling gap, or one that a cut left (docs/method.md §9.6:
/// every border loop runs along a rim). Returns the number of loops filled.
std::size_t fill_loops_away_from_boundary(TaggedMesh& tagged, const std::vector<Point3>& boundary_points,
                                          double max_distance, HoleFill fill = HoleFill::Fan);

/// Remove the components that have border loops but none that runs along a boundary curve
/// (the rule of fill_loops_away_from_boundary): pieces a cut has separated from the rest,
/// which closing their holes would turn into closed shells; only those smaller than the
/// largest piece that does run along a curve (a false curve must not take the sheet with it).
/// Nothing when `boundary_points` is empty (a closed surface, where every hole is a cut's).
/// Returns the number removed.
std::size_t drop_pieces_away_from_boundary(TaggedMesh& tagged, const std::vector<Point3>& boundary_points,
                                           double max_distance);

/// Fill boundary loops shorter than `max_length` with a fan around their centroid, but not the
/// rim of a piece no larger than 1.5 times a flat disc of the loop's perimeter (a small
/// island, which filling would close into a doubled shell). With `unit`, `max_length` is in
/// its units: a loop's bound is max_length times the median of unit(v) over its vertices (the
/// local rho: a hole shorter than 2 pi local rho is below the envelope's resolution there).
/// Returns the number filled.
std::size_t fill_short_loops(TaggedMesh& tagged, double max_length,
                             const std::function<double(const Point3&)>& unit = {});

/// What make_manifold found and did.
struct ManifoldRepairStats {
  std::size_t vertices_welded = 0;           ///< vertices merged into one at the same position
  std::size_t degenerate_faces_removed = 0;  ///< repeated vertex or repeated face after welding
  std::size_t non_manifold_edges_found = 0;  ///< after welding, before the repair
  std::size_t non_manifold_vertices_found = 0;
  std::size_t non_manifold_faces_removed = 0;  ///< by resolve_non_manifold_edges
  std::size_t vertices_split = 0;              ///< by split_pinched_vertices
  std::size_t faces_dropped = 0;  ///< at defects still left after `max_rounds` repairs
  int rounds = 0;                 ///< repair rounds run
};

/// Make the mesh a 2-manifold as analyze_topology sees it, which welds vertices with
/// identical coordinates: projection and snapping can move two vertices (the copies of a
/// split vertex, two border vertices snapped to one curve point) onto one position, where
/// they meet at a non-manifold edge or vertex. Welds, drops faces with a repeated vertex and
/// repeated faces, then runs resolve_non_manifold_edges and split_pinched_vertices until no
/// defect is left (at most `max_rounds` times); the faces at any defect left after that are
/// dropped (counted in faces_dropped) until none is left. Unused vertices are dropped.
/// Run it after every step that moves vertices or changes faces.
ManifoldRepairStats make_manifold(TaggedMesh& tagged, int max_rounds = 4);

/// What cut_to_orientable did.
struct OrientableCutStats {
  std::size_t seams = 0;        ///< connected seams of orientation-reversing edges cut
  std::size_t twists_kept = 0;  ///< seams left: on a bordered piece, no reversing loop shorter than max_twist_loop
  std::size_t faces_removed = 0;
  bool still_non_orientable = false;  ///< seams to cut were left after max_rounds
};

/// Remove the faces within `radius` (along mesh edges) of the seams where no consistent
/// orientation exists, then repair the manifold; repeat up to `max_rounds` times while seams
/// remain. Only the seams crossed by an orientation-reversing loop (a closed path between
/// face centroids along which the winding comes back reversed) shorter than `max_twist_loop`
/// are cut: a cross-cap where the sheet crossed itself is a few rho across, a twist of the
/// surface itself (a Moebius strip) runs around it. Seams on a piece without border are cut
/// too: a closed surface in space is orientable. Infinity cuts every seam. Leaves the mesh
/// wound as consistently as it can be (orient_faces).
OrientableCutStats cut_to_orientable(TaggedMesh& tagged, double radius,
                                     double max_twist_loop = std::numeric_limits<double>::infinity(),
                                     int max_rounds = 3);

/// Where faces pass through each other (`found`, mesh::self_intersections of `mesh`), relax the vertices of
/// those faces and two rings around them (three umbrella steps; border vertices move along
/// the border only); repeat up to `rounds` times while any pair is left. When the last round
/// leaves more pairs than an earlier state (relaxing one fold can push the sheet through a
/// neighbouring one), the positions go back to the state with the fewest. Returns the pairs
/// left (each round re-checks only the faces that moved). The folds that noise or the border snap leave open this way without losing faces.
mesh::SelfIntersections smooth_self_intersections(TriangleMesh& mesh, mesh::SelfIntersections found, int rounds);

/// What cut_self_intersections did.
struct SelfIntersectionCutStats {
  std::size_t pairs = 0;          ///< face pairs passing through each other, found first
  std::size_t faces_removed = 0;
};

/// Remove the faces that pass through another face (`found`, mesh::self_intersections of the
/// mesh) and every face with a vertex within `radius` (along mesh edges) of theirs, then
/// repair the manifold. The holes are left to the caller.
SelfIntersectionCutStats cut_self_intersections(TaggedMesh& tagged, const mesh::SelfIntersections& found,
                                                double radius);

/// Flags the faces of `after` that `before` does not have: no face of `before` has the same
/// three corner positions (in any order). After a cut and its repairs, only these can pass
/// through the others when the faces kept did not.
std::vector<char> faces_not_in(const TriangleMesh& after, const TriangleMesh& before);

/// What cut_local_handles did.
struct HandleCutStats {
  std::size_t balls = 0;  ///< seed balls that were not discs
  std::size_t faces_removed = 0;
};

/// Remove the places where the sheet is not a disc at scale `radius`: around seeds such that
/// every vertex lies within `radius` / 2 of one along the mesh, the faces within `radius`
/// (along the mesh) form a disc or half-disc,
/// once every hole of the sheet lying wholly inside is capped; where they do not (a handle, a
/// cross-cap, or a tube thinner than the ball) and the ball of three times the radius is not a
/// disc either (around a finger thinner than the ball but shorter than about twice its radius
/// it is: it takes in the fingertip), the faces of the smallest ball that is not a disc are
/// removed. Then repairs the manifold.
HandleCutStats cut_local_handles(TaggedMesh& tagged, double radius);

/// Drop unused vertices (indices remapped).
void compact_vertices(TaggedMesh& tagged);

}  // namespace envcrust::extract

namespace envcrust::extract {

/// Cut the mesh along the zero set of a per-vertex function (linear on each triangle) and
/// keep the part where it is <= 0. Crossing edges get one new vertex each (shared by both
/// faces); kept pieces of quads are split into two triangles. A cut within 5% of an edge's
/// end goes through that end instead (no duplicate vertices, no slivers). Returns the new
/// vertices.
std::vector<Index> trim_mesh(TaggedMesh& tagged, const std::vector<double>& level);

}  // namespace envcrust::extract
