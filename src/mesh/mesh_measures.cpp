// Bounding boxes, areas and polygon triangulation of indexed meshes.
#include "envcrust/mesh.h"

#include <CGAL/bounding_box.h>

#include <cmath>

namespace envcrust {

Polyline BoundaryCurve::polyline() const {
  Polyline points;
  points.reserve(vertices.size());
  for (const BoundaryVertex& vertex : vertices) points.push_back(vertex.position);
  return points;
}

}  // namespace envcrust

namespace envcrust::mesh {

double bbox_diagonal(const std::vector<Point3>& points) {
  if (points.size() < 2) return 0.0;
  const auto box = CGAL::bbox_3(points.begin(), points.end());
  const double dx = box.xmax() - box.xmin();
  const double dy = box.ymax() - box.ymin();
  const double dz = box.zmax() - box.zmin();
  return std::hypot(dx, dy, dz);  // no underflow of tiny extents (1e-200 squared is 0)
}

double total_area(const TriangleMesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    area += std::sqrt(Kernel::Triangle_3(mesh.vertices[t[0]], mesh.vertices[t[1]],
                                         mesh.vertices[t[2]])
                          .squared_area());
  }
  return area;
}

double closed_length(const Polyline& curve) {
  double length = 0.0;
  for (std::size_t i = 0; i < curve.size(); ++i)
    length += std::sqrt(CGAL::squared_distance(curve[i], curve[(i + 1) % curve.size()]));
  return length;
}

TriangleMesh triangulate_polygons(const PolygonMesh& mesh) {
  TriangleMesh out;
  out.vertices = mesh.vertices;
  for (const auto& face : mesh.faces) {
    for (std::size_t i = 1; i + 1 < face.size(); ++i) {
      out.triangles.push_back({face[0], face[i], face[i + 1]});
    }
  }
  return out;
}

}  // namespace envcrust::mesh
