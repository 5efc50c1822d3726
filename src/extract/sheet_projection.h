// Projection of the sheet's vertices onto the sampled surface and its boundary curves.
#pragma once

#include "sheet_mesh.h"

namespace envcrust::extract {

struct ProjectionStats {
  std::size_t moved = 0;
  std::size_t refused = 0;
};

/// Interior (non-border) vertices move onto the weighted tangent planes of their `neighbors`
/// nearest samples when the move is below `max_move`; a move that would flip or collapse an
/// incident face is halved, then refused.
ProjectionStats project_onto_samples(TaggedMesh& tagged, const envelope::SurfaceSamples& surface,
                                     double max_move, unsigned neighbors);

/// Cut away what lies beyond the boundary curves: the level (x - b) . c, b the nearest point of
/// a boundary curve (within `reach`) and c its outward conormal, is trimmed at zero. The
/// sheet overshoots the boundary by up to ~0.6 rho into the rim tube (METHOD.md §5 c1).
/// Returns the number of faces removed (net).
std::size_t trim_beyond_boundary(TaggedMesh& tagged, const envelope::SurfaceSamples& surface,
                                 double reach);

/// Border vertices move onto the nearest point of the boundary curves, checked as above.
ProjectionStats snap_border(TaggedMesh& tagged, const envelope::SurfaceSamples& surface,
                            double max_move);

}  // namespace envcrust::extract
