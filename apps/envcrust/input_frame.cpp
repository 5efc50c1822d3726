// The input's coordinates and the samples' frame, for outputs and references.
#include "input_frame.h"

#include "envcrust/input.h"

#include <utility>

namespace envcrust::cli {

TriangleMesh in_input_frame(TriangleMesh mesh, const Vector3& origin) {
  input::restore_origin(mesh.vertices, origin);
  return mesh;
}

PointSet in_input_frame(PointSet points, const Vector3& origin) {
  input::restore_origin(points.points, origin);
  return points;
}

std::vector<BoundaryCurve> in_input_frame(std::vector<BoundaryCurve> curves, const Vector3& origin) {
  if (origin == CGAL::NULL_VECTOR) return curves;
  for (auto& curve : curves)
    for (auto& v : curve.vertices) v.position = v.position + origin;
  return curves;
}

analysis::Reference in_samples_frame(analysis::Reference reference, const Vector3& origin) {
  if (origin == CGAL::NULL_VECTOR) return reference;
  const Vector3 back = -origin;
  if (reference.mesh) input::restore_origin(reference.mesh->vertices, back);
  input::restore_origin(reference.points, back);
  for (auto& loop : reference.boundary) input::restore_origin(loop, back);
  return reference;
}

}  // namespace envcrust::cli
