// Edge table of a triangle mesh: unique undirected edges, the faces around each, per-face edges.
#pragma once

#include "envcrust/types.h"

#include <array>
#include <utility>
#include <vector>

namespace envcrust::topology {

struct MeshGraph {
  std::size_t num_vertices = 0;
  std::vector<std::array<Index, 3>> faces;
  std::vector<std::pair<Index, Index>> edges;  ///< (a, b) with a < b, sorted
  std::vector<std::uint32_t> edge_face_begin;  ///< faces of edge e: edge_faces[begin[e], begin[e+1])
  std::vector<std::uint32_t> edge_faces;
  std::vector<std::array<std::uint32_t, 3>> face_edges;  ///< edge k joins corners k and k+1

  [[nodiscard]] std::size_t face_count_of_edge(std::size_t e) const {
    return edge_face_begin[e + 1] - edge_face_begin[e];
  }
};

/// +1 if the face runs the edge from a to b, -1 if from b to a, 0 if the edge is not its own.
int direction_along(const std::array<Index, 3>& face, Index a, Index b);

/// Build the edge table. Faces must have three distinct, in-range vertices.
MeshGraph build_mesh_graph(std::vector<std::array<Index, 3>> faces, std::size_t num_vertices);

/// Components of the faces joined through any shared edge: label[f] in [0, count), numbered
/// in order of their first face. @returns count.
std::uint32_t face_components(const MeshGraph& graph, std::vector<std::uint32_t>& label);

/// Number of fans of faces around each vertex (faces joined through edges at that vertex).
/// A manifold vertex has exactly one fan.
std::vector<std::uint32_t> count_vertex_fans(const MeshGraph& graph);

/// Fan id of every corner 3 * face + slot: two corners of one vertex share an id exactly when
/// their faces are joined through edges at that vertex.
std::vector<std::uint32_t> corner_fans(const MeshGraph& graph);

/// Per face, +1 or -1 so that faces sharing a two-face edge traverse it in opposite
/// directions; `is_orientable[c]` for each component c (components given per face). The signs
/// spread breadth-first from each of `first_faces` not reached yet (out-of-range ids are
/// ignored), then from the first face of every piece left; on a non-orientable piece the
/// edges where the fronts meet wrongly form a seam that starts from where the search began.
struct Orientation {
  std::vector<signed char> face_sign;
  std::vector<bool> is_orientable;
};
Orientation orient_components(const MeshGraph& graph, const std::vector<std::uint32_t>& component,
                              std::size_t num_components, const std::vector<std::uint32_t>& first_faces = {});

}  // namespace envcrust::topology
