// Edge collapse in pieces on all cores (CGAL's Surface_mesh_simplification): the short edges
// before isotropic remeshing, so that remeshing starts from a mesh near its target size, or
// the edges of least quadric error, to simplify a mesh to a vertex count.
#pragma once

#include "envcrust/types.h"
#include "seam.h"

#include <CGAL/Surface_mesh.h>

#include <cstddef>
#include <vector>

namespace envcrust::remesh {

using SurfaceMesh = CGAL::Surface_mesh<Point3>;

/// What the collapse may do at the true border.
enum class BorderCollapse {
  AlongBorder,  ///< border vertices may go, none moves: the border stays on its polyline
  Frozen        ///< no edge at a border vertex collapses
};

/// Which edges collapse first, where to, and when to stop.
enum class CollapseOrder {
  /// Shortest first, to the midpoint, until every edge is at least max_length.
  ShortestFirst,
  /// Least quadric error first (Garland-Heckbert: the sum of squared distances to the planes
  /// of the faces merged into a vertex so far), to the point that minimises it, until
  /// keep_edge_fraction of the edges is left. The error grows where the surface bends, so the
  /// vertices stay at tips and creases and go on flat parts.
  LeastQuadricError
};

/// Options of collapse_edges.
struct CollapseOptions {
  CollapseOrder order = CollapseOrder::ShortestFirst;
  double max_length = 0.0;       ///< ShortestFirst: edges shorter than this collapse
  /// LeastQuadricError: each piece stops when this share of its edges is left, in (0, 1].
  double keep_edge_fraction = 1.0;
  double max_border_edge = 0.0;  ///< no collapse leaves a border edge longer than this
  BorderCollapse border = BorderCollapse::AlongBorder;
  /// The mesh is collapsed in pieces of about this many faces (runs of its faces in Hilbert
  /// order), in parallel; the vertices two pieces share stay fixed. The count depends on the
  /// mesh only, so the result does not depend on the number of threads.
  std::size_t faces_per_piece = 200000;
};

/// The collapsed mesh, and per vertex the input vertex it is, for vertices that kept their
/// place (every fixed vertex), or Index max.
struct Collapsed {
  TriangleMesh mesh;
  std::vector<Index> input_vertex;
};

/// Collapse the edges of `mesh` (an oriented manifold) in the options' order, with CGAL's link
/// condition (so the topology stays) and no face normal turning by more than 90 degrees.
/// Inside, an edge collapses to its midpoint (ShortestFirst) or to its least-error point
/// (LeastQuadricError). No border vertex moves: a
/// border edge collapses onto the endpoint where the border turns more, unless the border
/// edge left in its place would be longer than `max_border_edge`; an edge with one border
/// endpoint collapses onto it; edges between two border vertices that are no border edge,
/// and edges at a vertex with `fixed[v]`, do not collapse (Frozen: no edge at a border vertex
/// does).
/// @throws NumericalFailure when the faces do not form a halfedge mesh.
Collapsed collapse_edges(const TriangleMesh& mesh, const std::vector<char>& fixed, const CollapseOptions& options);

/// collapse_edges on a mesh cut open along its seam, the seam's vertices fixed, and the
/// vertices v < held.size() with held[v] (cut vertex v < the input's vertex count is input
/// vertex v); the seam marks and weld keys follow the vertices that stay (vertices that moved
/// have none).
void collapse_cut_mesh(CutMesh& cut, const CollapseOptions& options, const std::vector<char>& held = {});

/// The mesh (an oriented manifold: pinched vertices are not all caught) as a CGAL
/// Surface_mesh, vertex i being vertex i.
/// @throws NumericalFailure when the faces do not fit a halfedge mesh.
SurfaceMesh to_halfedge_mesh(const TriangleMesh& mesh);

}  // namespace envcrust::remesh
