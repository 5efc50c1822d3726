// Collapsing the short edges of a mesh before isotropic remeshing (CGAL's
// Surface_mesh_simplification, in pieces on all cores), so that remeshing starts from a mesh
// near its target size.
#pragma once

#include "envcrust/types.h"

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

/// Options of collapse_short_edges.
struct CollapseOptions {
  double max_length = 0.0;       ///< edges shorter than this collapse
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

/// Collapse the edges of `mesh` (an oriented manifold) shorter than `max_length`, shortest
/// first, with CGAL's link condition (so the topology stays) and no face normal turning by
/// more than 90 degrees. Inside, an edge collapses to its midpoint. No border vertex moves: a
/// border edge collapses onto the endpoint where the border turns more, unless the border
/// edge left in its place would be longer than `max_border_edge`; an edge with one border
/// endpoint collapses onto it; edges between two border vertices that are no border edge,
/// and edges at a vertex with `fixed[v]`, do not collapse (Frozen: no edge at a border vertex
/// does).
/// @throws NumericalFailure when the faces do not form a halfedge mesh.
Collapsed collapse_short_edges(const TriangleMesh& mesh, const std::vector<char>& fixed,
                               const CollapseOptions& options);

/// The mesh (an oriented manifold: pinched vertices are not all caught) as a CGAL
/// Surface_mesh, vertex i being vertex i.
/// @throws NumericalFailure when the faces do not fit a halfedge mesh.
SurfaceMesh to_halfedge_mesh(const TriangleMesh& mesh);

}  // namespace envcrust::remesh
