// Core value types shared by every stage: the one kernel, point sets, indexed meshes, polylines.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cstdint>
#include <vector>

namespace envcrust {

/// The one geometry kernel of the project: exact predicates, double constructions.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Vector3 = Kernel::Vector_3;

/// Index of a vertex or face in an indexed mesh (32 bits: meshes up to 4e9 elements).
using Index = std::uint32_t;

/// A set of points with optional per-point normals (normals empty, or one per point).
/// Normals are *lines* unless a stage says otherwise: their sign carries no meaning.
struct PointSet {
  std::vector<Point3> points;
  std::vector<Vector3> normals;  ///< empty or points.size() unit vectors
  [[nodiscard]] bool has_normals() const { return !normals.empty(); }
  [[nodiscard]] std::size_t size() const { return points.size(); }
};

/// An indexed mesh of polygons (as read from files). Faces list vertex indices in order.
struct PolygonMesh {
  std::vector<Point3> vertices;
  std::vector<std::vector<Index>> faces;
};

/// An indexed triangle mesh. May be non-manifold or non-orientable: it is a soup with shared
/// vertices, which is what the analyzer and the extraction stages need (a halfedge structure
/// cannot hold a Moebius band's faces consistently).
struct TriangleMesh {
  std::vector<Point3> vertices;
  std::vector<std::array<Index, 3>> triangles;
};

/// An ordered sequence of points; closed curves do not repeat the first point at the end.
using Polyline = std::vector<Point3>;

/// One vertex of a sampled boundary curve: position, unit tangent t (along the loop), unit
/// normal line n, and outward conormal c (tangent to the surface, perpendicular to t,
/// pointing away from the surface). At a corner of the domain (square), `is_corner` is set,
/// `tangent` and `conormal` are those of the edge arriving at the corner and `conormal_next`
/// holds the conormal of the following edge.
struct BoundaryVertex {
  Point3 position;
  Vector3 tangent, normal, conormal;
  bool is_corner = false;
  Vector3 conormal_next = Vector3(0, 0, 0);
};

/// A closed boundary loop, in order (the first vertex is not repeated at the end).
struct BoundaryCurve {
  std::vector<BoundaryVertex> vertices;
  [[nodiscard]] Polyline polyline() const;  ///< the positions, in order
};

/// A sharp crease of a surface: an edge where two faces meet at an angle, with the unit
/// direction that bisects the wedge between the faces (the side where they make less than
/// 180 degrees).
struct CreaseSegment {
  Point3 a, b;
  Vector3 wedge;
};

}  // namespace envcrust
