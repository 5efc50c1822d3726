// min_angle_deg: the smallest triangle angle, the quality number remeshing is judged by.
#include "envcrust/remesh.h"

#include <algorithm>
#include <cmath>

namespace envcrust::remesh {

double min_angle_deg(const TriangleMesh& mesh) {
  double min_cos_angle = 2.0;  // the largest cosine is the smallest angle
  bool any = false;
  for (const auto& t : mesh.triangles) {
    const Point3& a = mesh.vertices[t[0]];
    const Point3& b = mesh.vertices[t[1]];
    const Point3& c = mesh.vertices[t[2]];
    if (a == b || b == c || c == a) continue;
    const Point3* p[3] = {&a, &b, &c};
    for (int i = 0; i < 3; ++i) {
      const Vector3 u = *p[(i + 1) % 3] - *p[i];
      const Vector3 v = *p[(i + 2) % 3] - *p[i];
      const double cos_angle = (u * v) / std::sqrt(u.squared_length() * v.squared_length());
      min_cos_angle = any ? std::max(min_cos_angle, cos_angle) : cos_angle;
      any = true;
    }
  }
  if (!any) return 0.0;
  return std::acos(std::clamp(min_cos_angle, -1.0, 1.0)) * 180.0 / 3.141592653589793;
}

}  // namespace envcrust::remesh
