// Projection of the sheet's vertices onto the sampled surface and its boundary curves.
#pragma once

#include "sheet_mesh.h"

namespace envcrust::extract {

struct ProjectionStats {
  std::size_t moved = 0;
  std::size_t refused = 0;
};

/// Interior (non-border) vertices move onto a weighted least-squares quadric fitted to the
/// positions and normals of their `neighbors` nearest samples when the move is below
/// `max_move`; a move that would fold an incident face over in the tangent plane (or collapse
/// it) is halved, then refused, and refused or halved moves are retried up to `retry_rounds`
/// times after the other vertices have moved.
ProjectionStats project_onto_samples(TaggedMesh& tagged, const envelope::SurfaceSamples& surface,
                                     const NearestIndex& samples, double max_move, unsigned neighbors,
                                     unsigned retry_rounds);

/// Cut away what lies beyond the boundary curves: the level (x - b) . c, b the nearest point of
/// a boundary curve (within `reach`) and c its outward conormal, is trimmed at zero. The
/// sheet overshoots the boundary by up to ~0.6 rho into the rim tube (docs/method.md §8.5).
/// Returns the number of faces removed (net).
std::size_t trim_beyond_boundary(TaggedMesh& tagged, const envelope::SurfaceSamples& surface,
                                 double reach);

/// Border vertices move onto the nearest point of the boundary curves, checked as above (in
/// the tangent plane of the surface at the curve point, with retries); a vertex whose snap
/// still folds a face moves along the surface normal only.
ProjectionStats snap_border(TaggedMesh& tagged, const envelope::SurfaceSamples& surface,
                            double max_move, unsigned retry_rounds);

/// Close the notches that a cut opened in the sheet's rim: along a border loop that mostly
/// lies on a boundary curve (within `on_curve`), each run of vertices off it that reaches
/// `min_depth` in, between two vertices on one curve at most `max_width` apart along it, is
/// filled with a smooth disc (fill_with_patch) bounded by the run and the stretch of curve
/// between its ends, which becomes the border there. The disc is glued along an arc of the
/// border, so the topology is unchanged. Returns the number of notches closed.
std::size_t close_border_notches(TaggedMesh& tagged, const envelope::SurfaceSamples& surface, double on_curve,
                                 double min_depth, double max_width);

}  // namespace envcrust::extract
