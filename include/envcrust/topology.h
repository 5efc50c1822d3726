// Topology of an indexed triangle mesh: manifoldness, components, Euler characteristic,
// orientability, genus and boundary loops (docs/method.md §9.1-9.2).
#pragma once

#include "envcrust/types.h"

#include <optional>
#include <vector>

namespace envcrust::topology {

/// One boundary loop: vertex indices (of the welded mesh) in walking order, not repeated.
struct BoundaryLoop {
  std::vector<Index> vertices;
  double length = 0.0;       ///< sum of its edge lengths
  int component = -1;        ///< connected component the loop belongs to
  bool is_oriented = false;  ///< order follows the induced orientation of an orientable component
  [[nodiscard]] Polyline polyline(const std::vector<Point3>& points) const;
};

/// Topology of one connected component (faces connected through shared edges).
struct ComponentTopology {
  std::size_t vertices = 0, edges = 0, faces = 0;
  long euler_characteristic = 0;  ///< V - E + F; a triangle alone has chi = 1
  int boundary_loops = 0;
  bool is_orientable = true;
  bool is_manifold = true;        ///< no non-manifold edge or vertex in the component
  /// Orientable: genus g from chi = 2 - 2g - b. Non-orientable: number of cross-caps k from
  /// chi = 2 - k - b. Unset when the component is not a manifold.
  std::optional<long> genus;
};

/// Topology of a whole mesh. Vertices with identical coordinates are welded first.
struct MeshTopology {
  std::size_t input_vertices = 0;    ///< as given
  std::size_t vertices = 0;          ///< used by a counted face, after welding
  std::size_t welded_vertices = 0;   ///< vertices merged into an identical one
  std::size_t unused_vertices = 0;   ///< referenced by no face
  std::size_t faces = 0;             ///< faces with three distinct vertices (zero-area ones too)
  std::size_t edges = 0;
  /// Faces with a repeated vertex (left out of `faces`) or of zero area (counted in it).
  std::size_t degenerate_faces = 0;
  std::size_t duplicate_faces = 0;   ///< same vertex set as an earlier face
  std::size_t boundary_edges = 0;    ///< edges with exactly one face
  std::size_t non_manifold_edges = 0;     ///< edges with three or more faces
  std::size_t non_manifold_vertices = 0;  ///< vertices whose faces form several fans
  /// Two-face edges that both faces run in the same direction: the faces are not consistently
  /// oriented as given (possible for an orientable mesh with flipped faces).
  std::size_t misoriented_edges = 0;
  long euler_characteristic = 0;
  bool is_orientable = true;              ///< every component orientable
  std::vector<ComponentTopology> components;
  std::vector<BoundaryLoop> boundary_loops;
  std::vector<Point3> points;             ///< welded vertex positions (loops index these)

  [[nodiscard]] bool is_manifold() const {
    return non_manifold_edges == 0 && non_manifold_vertices == 0;
  }
  [[nodiscard]] bool is_closed() const { return boundary_edges == 0; }
};

/// Handles and cross-caps of the whole mesh: the components' genus summed; unset when a
/// component is not a manifold.
std::optional<long> total_genus(const MeshTopology& topology);

/// Options of analyze_topology.
struct TopologyOptions {
  /// Merge vertices with identical coordinates first (files often repeat them, e.g. STL and
  /// soups). Off: indices are taken as given, and loops index the input's vertices.
  bool weld_identical_vertices = true;
};

/// Analyze the topology of a triangle mesh. Faces with a repeated vertex are ignored (and
/// counted as degenerate); zero-area faces with three distinct vertices are counted as
/// degenerate but kept, so the numbers describe the mesh as a simplicial complex.
/// @throws InvalidInput if a face index is out of range ("face 12 has vertex index 40, but
/// the mesh has 30 vertices").
MeshTopology analyze_topology(const TriangleMesh& mesh, const TopologyOptions& options = {});

/// The boundary loops alone, as analyze_topology(mesh, {.weld_identical_vertices = false})
/// traces them (the same loops in the same order, with the same lengths; each loop's vertices
/// may be walked the other way round) but not oriented: is_oriented is false and component -1. For the cleaning steps of large meshes that only need each loop's
/// vertices and length (it skips the duplicate, component, fan and orientation counts).
/// @throws InvalidInput as analyze_topology does for a face index out of range.
std::vector<BoundaryLoop> boundary_loops(const TriangleMesh& mesh);

/// Flip triangles so that faces sharing an edge run it in opposite directions: every
/// orientable piece (faces joined through two-face edges) comes out consistently wound, a
/// closed one facing outward (positive signed volume), an open one facing out of the volume
/// it encloses once cones over its borders close it (a hemisphere's dome, a range scan's
/// front; a flat piece faces where its vector area's largest component is positive); a
/// non-orientable piece is wound consistently except across one seam of edges. Faces with a
/// repeated vertex are left alone.
/// Vertices are not welded: call it on a mesh whose shared vertices share indices.
/// @returns the number of faces flipped.
std::size_t orient_faces(TriangleMesh& mesh);

/// Turn each piece of `mesh` (faces joined through edges) over, every face's winding
/// reversed, when its area vectors, summed against the normal of the sample nearest to each
/// face's centre, point against `normals`: a reconstruction then faces like the oriented
/// normals it was made from (and renders show their front colour on that side). Windings
/// within a piece keep their relation. @returns the number of pieces turned; 0 without samples.
std::size_t orient_along_normals(TriangleMesh& mesh, const std::vector<Point3>& points,
                                 const std::vector<Vector3>& normals);

}  // namespace envcrust::topology
