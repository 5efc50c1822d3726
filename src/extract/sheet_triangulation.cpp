// Polygons of the raw sheet to triangles.
#include "sheet_mesh.h"

namespace envcrust::extract {

TaggedMesh triangulate_sheet(const RawSheet& sheet) {
  TaggedMesh out;
  out.mesh.vertices = sheet.vertices;
  auto& v = out.mesh.vertices;
  for (std::size_t i = 0; i < sheet.polygons.size(); ++i) {
    const auto& p = sheet.polygons[i];
    const double dot = sheet.polygon_dot[i];
    auto add = [&](Index a, Index b, Index c) {
      out.mesh.triangles.push_back({a, b, c});
      out.face_dot.push_back(dot);
    };
    if (p.size() == 3) {
      add(p[0], p[1], p[2]);
    } else if (p.size() == 4) {
      if (CGAL::squared_distance(v[p[0]], v[p[2]]) <= CGAL::squared_distance(v[p[1]], v[p[3]])) {
        add(p[0], p[1], p[2]);
        add(p[0], p[2], p[3]);
      } else {
        add(p[1], p[2], p[3]);
        add(p[1], p[3], p[0]);
      }
    } else {
      Vector3 sum(0, 0, 0);
      for (Index k : p) sum = sum + (v[k] - CGAL::ORIGIN);
      const auto centre = static_cast<Index>(v.size());
      v.push_back(CGAL::ORIGIN + sum / static_cast<double>(p.size()));
      for (std::size_t k = 0; k < p.size(); ++k) add(p[k], p[(k + 1) % p.size()], centre);
    }
  }
  return out;
}

}  // namespace envcrust::extract
