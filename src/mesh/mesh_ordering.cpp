// hilbert_order of points; order_spatially: Hilbert order of the vertices, faces following
// their first vertex.
#include "envcrust/mesh.h"

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/hilbert_sort.h>

#include <algorithm>
#include <numeric>

namespace envcrust::mesh {

std::vector<std::size_t> hilbert_order(const std::vector<Point3>& points) {
  std::vector<std::size_t> order(points.size());  // the property map's key type
  std::iota(order.begin(), order.end(), std::size_t{0});
  // make_property_map takes &points[0]: undefined on an empty vector (UBSan, scripts/sanitize.sh).
  if (points.empty()) return order;
  using Map = CGAL::Pointer_property_map<Point3>::const_type;
  CGAL::hilbert_sort<CGAL::Parallel_tag>(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, Map>(CGAL::make_property_map(points)));
  return order;
}

SpatiallyOrdered order_spatially(const TriangleMesh& mesh) {
  SpatiallyOrdered out;
  const std::vector<std::size_t> order = hilbert_order(mesh.vertices);
  out.old_vertex.assign(order.begin(), order.end());
  std::vector<Index> new_vertex(mesh.vertices.size());
  out.mesh.vertices.reserve(mesh.vertices.size());
  for (std::size_t i = 0; i < out.old_vertex.size(); ++i) {
    new_vertex[out.old_vertex[i]] = static_cast<Index>(i);
    out.mesh.vertices.push_back(mesh.vertices[out.old_vertex[i]]);
  }
  out.mesh.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) out.mesh.triangles.push_back({new_vertex[t[0]], new_vertex[t[1]], new_vertex[t[2]]});
  auto smallest = [](const std::array<Index, 3>& t) { return std::min({t[0], t[1], t[2]}); };
  std::stable_sort(out.mesh.triangles.begin(), out.mesh.triangles.end(),
                   [&](const auto& a, const auto& b) { return smallest(a) < smallest(b); });
  return out;
}

}  // namespace envcrust::mesh
