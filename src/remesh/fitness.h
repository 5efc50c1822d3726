// What remesh and simplify check before and after they run: whether a mesh fits a halfedge
// mesh, and the topology numbers neither stage may change.
#pragma once

#include "envcrust/topology.h"

#include <string>

namespace envcrust::remesh {

/// The numbers a stage must not change, as "chi 0, 1 component(s), 2 boundary loop(s),
/// orientable" (", non-manifold" appended for a non-manifold mesh).
std::string describe(const topology::MeshTopology& t);

/// Why the mesh cannot be remeshed or simplified (no triangles; not a manifold, with its
/// counts; degenerate or duplicate faces or repeated vertices), or "" when it can.
std::string unfit_reason(const topology::MeshTopology& t);

/// How a stage changed what it must keep ("it changed the mesh from chi 0, ... to chi 2, ...",
/// with the count of degenerate faces it made, if any), or "" when it did not.
std::string topology_change(const topology::MeshTopology& before, const topology::MeshTopology& after);

}  // namespace envcrust::remesh
