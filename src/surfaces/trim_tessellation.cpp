// Ground-truth tessellation of a trimmed surface: the parameter grid's nodes inside the kept
// region and the trim loops' points, triangulated with the loops as constraints (CGAL's
// constrained Delaunay triangulation, in grid units so that cells are square), the triangles
// whose centroid is kept mapped onto the surface.
#include "builtin.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <map>
#include <utility>

namespace envcrust::surfaces {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<Index, K>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

/// Grid nodes closer than this (in cells) to a loop point are left out: no slivers there.
constexpr double kNodeClearance = 0.3;

}  // namespace

TriangleMesh tessellate_trimmed(const Surface& surface, int nu, int nv) {
  const ParameterDomain d = surface.domain();
  const double hu = (d.u1 - d.u0) / nu, hv = (d.v1 - d.v0) / nv;
  const auto to_grid = [&](double u, double v) { return K::Point_2((u - d.u0) / hu, (v - d.v0) / hv); };
  TriangleMesh mesh;
  Cdt cdt;
  const auto add = [&](double u, double v) {
    const std::size_t before = cdt.number_of_vertices();
    const auto handle = cdt.insert(to_grid(u, v));
    if (cdt.number_of_vertices() > before) {  // a new point, not one already there
      handle->info() = static_cast<Index>(mesh.vertices.size());
      mesh.vertices.push_back(surface.evaluate(u, v).position);
    }
    return handle;
  };
  // Loop points first, binned by grid cell for the clearance test of the nodes.
  std::map<std::pair<long, long>, std::vector<K::Point_2>> near_loop;
  for (const auto& loop : surface.trim_loops()) {
    std::vector<Cdt::Vertex_handle> handles;
    for (const auto& [u, v] : loop) {
      handles.push_back(add(u, v));
      const K::Point_2 g = to_grid(u, v);
      near_loop[{std::lround(g.x()), std::lround(g.y())}].push_back(g);
    }
    for (std::size_t k = 0; k < handles.size(); ++k) {
      const auto a = handles[k], b = handles[(k + 1) % handles.size()];
      if (a != b) cdt.insert_constraint(a, b);
    }
  }
  for (int i = 0; i <= nu; ++i) {
    for (int j = 0; j <= nv; ++j) {
      const double u = d.u0 + hu * i, v = d.v0 + hv * j;
      if (!surface.contains(u, v)) continue;
      bool is_clear = true;
      for (long di = -1; di <= 1 && is_clear; ++di)
        for (long dj = -1; dj <= 1 && is_clear; ++dj) {
          const auto it = near_loop.find({i + di, j + dj});
          if (it == near_loop.end()) continue;
          for (const auto& p : it->second)
            if (CGAL::squared_distance(p, K::Point_2(i, j)) < kNodeClearance * kNodeClearance) is_clear = false;
        }
      if (is_clear) add(u, v);
    }
  }
  for (auto face = cdt.finite_faces_begin(); face != cdt.finite_faces_end(); ++face) {
    const K::Point_2 c = CGAL::centroid(face->vertex(0)->point(), face->vertex(1)->point(), face->vertex(2)->point());
    if (!surface.contains(d.u0 + c.x() * hu, d.v0 + c.y() * hv)) continue;
    // Counter-clockwise in the grid plane, hence in (u, v): normals follow S_u x S_v.
    mesh.triangles.push_back({face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()});
  }
  return mesh;
}

}  // namespace envcrust::surfaces
