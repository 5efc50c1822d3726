// Cutting a manifold mesh open along a seam so that its faces orient consistently (a
// non-orientable mesh then fits in a halfedge mesh), and welding the copies back.
#pragma once

#include "envcrust/types.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace envcrust::remesh {

/// Key of a vertex that is welded to no other.
inline constexpr Index kNoWeldKey = std::numeric_limits<Index>::max();

/// A mesh cut open along its seam.
struct CutMesh {
  /// The input's faces, each as given or reversed so that faces sharing an edge run it in
  /// opposite directions, on vertices split along the seam: each side of a seam edge has its
  /// own copies of the edge's vertices. Vertex i < input size is (a copy of) input vertex i;
  /// further copies and seam split points follow. Orientable.
  TriangleMesh mesh;
  /// Per vertex of `mesh`: vertices with the same key are copies of one point and are welded
  /// back. The input's vertices have their own index as key; seam split points get keys from
  /// the input's vertex count up.
  std::vector<Index> weld_key;
  /// The seam edges as key pairs (smaller key first), each once; both sides carry each one.
  std::vector<std::array<Index, 2>> seam_edges;
  /// Per vertex of `mesh`: it has another copy (it lies on the seam).
  std::vector<bool> on_seam;
  /// Faces reversed to orient the mesh consistently.
  std::size_t reversed_faces = 0;
};

/// Orient the faces greedily (breadth-first across two-face edges from each of
/// `first_faces` not reached yet, which keeps its orientation, then likewise from the first
/// face of each component left) and cut along the seam: the two-face edges whose faces then
/// run them in the same direction. For an orientable mesh the seam is empty and only faces
/// are reversed; for a Möbius strip it is a path of edges across the strip, about where the
/// two fronts of the search meet, half way round from where it started; the cut mesh is a
/// disc. The mesh must be a manifold without degenerate faces (checked by the caller).
CutMesh cut_along_seam(const TriangleMesh& mesh, const std::vector<std::uint32_t>& first_faces = {});

/// Split every seam edge longer than `max_length` into equal pieces no longer than it, the
/// same points on both sides (each side's face becomes a fan), so that the seam can be kept
/// fixed while the rest is remeshed at that length.
void split_long_seam_edges(CutMesh& cut, double max_length);

/// Merge the vertices of `mesh` that share a key (`key[v] == kNoWeldKey`: v stays alone).
/// Vertices keep the order of their first copy, so welding a fresh cut with its weld_key
/// gives back the input's vertices and faces (some reversed).
/// @throws NumericalFailure when copies to be merged lie at different positions.
TriangleMesh weld(const TriangleMesh& mesh, const std::vector<Index>& key);

}  // namespace envcrust::remesh
