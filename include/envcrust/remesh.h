// Optional last stage: isotropic remeshing of the reconstruction (CGAL's edge collapse down
// to near the target size, then Polygon_mesh_processing::isotropic_remeshing) that keeps its
// topology and boundary loops, non-orientable ones included (cut open along a seam, welded
// back).
#pragma once

#include "envcrust/types.h"

#include <optional>
#include <string>
#include <vector>

namespace envcrust::remesh {

/// What happens to the boundary loops.
enum class BoundaryMode {
  /// Border edges are split and collapsed along the input's border polyline (CGAL's default
  /// for patch borders): the border is resampled at the target length, its new vertices lie
  /// on the old polyline, and no border vertex leaves it. Where a Möbius seam meets the
  /// border, the seam's end vertex stays.
  Resample,
  /// Every input border vertex is kept: border edges longer than 4/3 of the target are split
  /// first, then all border edges are protected (neither split nor collapsed again). The
  /// border stays as dense as the input's, which leaves thin "ears" along it (three
  /// consecutive border vertices): the smallest angle is not improved there.
  Keep
};

/// Options of remesh.
struct RemeshOptions {
  /// Target edge length, in the mesh's units, > 0. nullopt: `edge_length_rel_median` times
  /// the median edge length of the input.
  std::optional<double> target_edge_length;
  /// Used when target_edge_length is unset, > 0. The sheet's median edge is about rho/9
  /// (several Voronoi vertices per envelope sample); 3 (a target of about 0.35 rho) cuts the
  /// faces 6-8 fold and keeps the distance to the true surface within the sheet's own
  /// (measured at 10k samples: README).
  double edge_length_rel_median = 3.0;
  /// Split / collapse / flip / relax / project rounds, 1..100. CGAL's example uses 3.
  int iterations = 3;
  BoundaryMode boundary = BoundaryMode::Resample;
  /// Remeshing that would make more faces than this many times the input's (or 1M, whichever
  /// is more), counted as the area over an equilateral triangle of the target edge, is
  /// skipped with a warning: a tiny target would run for hours and fill the memory (a target
  /// of 0.001 on a unit hemisphere, 14M faces, passed 4 GB within 2 minutes). >= 1.
  double max_face_growth = 4.0;
};

/// What remesh did.
struct RemeshStats {
  bool is_remeshed = false;          ///< false: the input came back unchanged (see warnings)
  std::size_t faces_before = 0, faces_after = 0;
  double target_edge_length = 0.0;   ///< the length used
  double min_angle_deg_before = 0.0, min_angle_deg_after = 0.0;  ///< smallest triangle angle
  double seconds = 0.0;
};

/// The remeshed mesh.
struct RemeshResult {
  TriangleMesh mesh;
  RemeshStats stats;
  std::vector<std::string> warnings;
};

/// Remesh a manifold triangle mesh isotropically (its edges shorter than 0.8 of the target
/// collapsed first, no border vertex moving, then CGAL's remeshing rounds), keeping its Euler characteristic,
/// boundary loops, components and orientability: if any of them changes, the input is
/// returned unchanged with a warning. A non-orientable mesh (a Möbius band), which CGAL's
/// halfedge meshes cannot hold, is first cut open along its seam: the edges across which the
/// faces, oriented greedily breadth-first, disagree (for a Möbius band a path across it),
/// each seam vertex copied once per side. The seam is held fixed while the rest is remeshed
/// (its edges split to the target length, the same points on both sides; its vertices never
/// move or go; it is not a border for BoundaryMode), then both sides are welded back, so the
/// output is non-orientable again and has no vertex twice. The fixed seam keeps the input's
/// dense vertices and thin triangles, so a second round cuts along a seam half way round from
/// the first (through remeshed triangles), with the border fixed and vertices projected onto
/// the input, and remeshes the first seam's neighbourhood. Orientable meshes have an empty
/// seam and get one round (faces are wound consistently, the first one as given).
/// Non-manifold meshes are returned unchanged with a warning ("remeshing skipped: the mesh is
/// not a manifold (...)"), as are meshes with degenerate or duplicate faces or repeated
/// vertices.
/// @throws InvalidOptions when a field is out of range (the message names it and its value).
/// @throws InvalidInput when a face index is out of range.
RemeshResult remesh(const TriangleMesh& mesh, const RemeshOptions& options = {});

/// How many times simplify runs at most, each holding more of the input where the previous
/// run passed through itself.
inline constexpr int kSimplifyRounds = 3;

/// Options of simplify.
struct SimplifyOptions {
  std::size_t target_vertices = 0;  ///< about this many vertices are left, > 0
};

/// What simplify did.
struct SimplifyStats {
  bool is_simplified = false;  ///< false: the input came back unchanged (see warnings)
  std::size_t vertices_before = 0, vertices_after = 0;
  /// Input vertices held in place where an earlier round passed through itself.
  std::size_t vertices_held = 0;
  double seconds = 0.0;
};

/// The simplified mesh.
struct SimplifyResult {
  TriangleMesh mesh;
  SimplifyStats stats;
  std::vector<std::string> warnings;
};

/// Simplify a manifold triangle mesh to about `target_vertices` vertices by edge collapse,
/// least quadric error first (Garland and Heckbert: each collapse goes to the point nearest,
/// in squared distance, to the planes of the faces merged so far, so vertices go on flat parts
/// and stay at tips, creases and the border's turns). Collapses keep the topology (CGAL's link
/// condition), no face turns by more than 90 degrees, and border vertices stay on the
/// border's polyline. The mesh is collapsed as one piece, on one core. Where the result
/// passes through itself at more pairs of faces than the input, the input's vertices within
/// twice the longest edge of each crossing face are held in place and the whole is simplified
/// again, up to kSimplifyRounds times; a result that still crosses more than the input is
/// undone, with a warning. A non-orientable mesh is cut open along its orientation seam, which
/// keeps its vertices, and welded back (as in remesh). A mesh with no more vertices than the
/// target comes back unchanged, without a warning; one that remesh would skip (not a manifold,
/// degenerate or duplicate faces, repeated vertices) comes back unchanged with that warning, as
/// does a result whose topology changed.
/// @throws InvalidOptions when target_vertices is 0.
SimplifyResult simplify(const TriangleMesh& mesh, const SimplifyOptions& options);

/// Smallest interior angle over all non-degenerate triangles, in degrees (0 for no triangle).
double min_angle_deg(const TriangleMesh& mesh);

}  // namespace envcrust::remesh
