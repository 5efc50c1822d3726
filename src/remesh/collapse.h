// Collapsing the short edges of a Surface_mesh before isotropic remeshing (CGAL's
// Surface_mesh_simplification), so that remeshing starts from a mesh near its target size.
#pragma once

#include "envcrust/types.h"

#include <CGAL/Surface_mesh.h>

#include <cstddef>

namespace envcrust::remesh {

using SurfaceMesh = CGAL::Surface_mesh<Point3>;

/// What the collapse may do at the true border.
enum class BorderCollapse {
  AlongBorder,  ///< border vertices may go, none moves: the border stays on its polyline
  Frozen        ///< no edge at a border vertex collapses
};

/// Collapse the edges of `mesh` shorter than `max_length`, shortest first, with CGAL's link
/// condition (so the topology stays) and no face normal turning by more than 90 degrees.
/// Inside, an edge collapses to its midpoint. No border vertex moves: a border edge collapses
/// onto the endpoint where the border turns more, unless the border edge left in its place
/// would be longer than `max_border_edge`; an edge with one border endpoint collapses onto
/// it; edges between two border vertices that are no border edge, and edges at a vertex in
/// `fixed`, do not collapse (Frozen: no edge at a border vertex does). Collapsed vertices are
/// removed from `mesh` (garbage collected), property maps follow. Returns the number of
/// collapses.
std::size_t collapse_short_edges(SurfaceMesh& mesh, SurfaceMesh::Property_map<SurfaceMesh::Vertex_index, bool> fixed,
                                 double max_length, double max_border_edge, BorderCollapse border);

}  // namespace envcrust::remesh
