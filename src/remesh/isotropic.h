// The CGAL side of remesh: soup -> cut -> Surface_mesh -> isotropic_remeshing -> weld -> soup.
#pragma once

#include "envcrust/remesh.h"
#include "envcrust/types.h"

namespace envcrust::remesh {

/// Cut the mesh open along its orientation seam (seam.h; empty for an orientable mesh), build
/// a CGAL Surface_mesh with the seam vertices constrained, remesh it towards
/// `target_edge_length`, weld the seam back and return it as an indexed mesh without unused
/// vertices. The mesh must be a manifold without degenerate faces (checked by the caller).
/// @throws NumericalFailure when the faces cannot be built into a halfedge mesh or the two
/// sides of the seam moved apart.
TriangleMesh isotropic_remesh(const TriangleMesh& mesh, double target_edge_length, int iterations,
                              BoundaryMode boundary);

/// Median length of the mesh's edges, each counted once (0 for no triangle).
double median_edge_length(const TriangleMesh& mesh);

}  // namespace envcrust::remesh
