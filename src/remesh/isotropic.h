// The CGAL side of remesh: soup -> Surface_mesh -> isotropic_remeshing -> soup.
#pragma once

#include "envcrust/remesh.h"
#include "envcrust/types.h"

namespace envcrust::remesh {

/// Orient the faces consistently, build a CGAL Surface_mesh, remesh it towards
/// `target_edge_length` and return it as an indexed mesh without unused vertices.
/// The mesh must be a manifold and orientable (checked by the caller).
/// @throws NumericalFailure when the faces cannot be oriented into a halfedge mesh.
TriangleMesh isotropic_remesh(const TriangleMesh& mesh, double target_edge_length, int iterations,
                              BoundaryMode boundary);

/// Median length of the mesh's edges, each counted once (0 for no triangle).
double median_edge_length(const TriangleMesh& mesh);

}  // namespace envcrust::remesh
