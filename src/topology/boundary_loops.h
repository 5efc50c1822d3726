// Tracing boundary loops (chains of one-face edges) of a triangle mesh.
#pragma once

#include "envcrust/topology.h"
#include "envcrust/mesh_graph.h"

namespace envcrust::topology {

/// Walk the one-face edges into closed loops. When the loop's component is orientable
/// (orientation.is_orientable), the walk follows the orientation induced by the face signs.
std::vector<BoundaryLoop> trace_boundary_loops(const MeshGraph& graph,
                                               const std::vector<Point3>& points,
                                               const std::vector<std::uint32_t>& face_component,
                                               const Orientation& orientation);

}  // namespace envcrust::topology
