// Point-to-mesh (AABB tree) and point-to-points (kd-tree) distances, in parallel with oneTBB,
// queried along a Hilbert curve (consecutive queries visit the same part of the tree).
#include "envcrust/distance.h"
#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace envcrust::distance {
namespace {

using Triangle = Kernel::Triangle_3;
using TrianglePrimitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, TrianglePrimitive>>;
using SearchTraits = CGAL::Search_traits_3<Kernel>;
using NeighborSearch = CGAL::Orthogonal_k_neighbor_search<SearchTraits>;

// Reduce per-point distances into max/mean in a fixed order (thread-count independent).
DirectedDistance summarize(const std::vector<Point3>& points, const std::vector<double>& d) {
  DirectedDistance out;
  out.samples = d.size();
  double sum = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    sum += d[i];
    if (d[i] > out.max || i == 0) {
      out.max = d[i];
      out.worst_point = points[i];
    }
  }
  out.mean = d.empty() ? 0.0 : sum / static_cast<double>(d.size());
  return out;
}

}  // namespace

std::vector<double> distances_to_mesh(const std::vector<Point3>& points, const TriangleMesh& mesh) {
  std::vector<Triangle> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    Triangle tri(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    if (!tri.is_degenerate()) triangles.push_back(tri);
  }
  if (triangles.empty() || points.empty()) return {};
  TriangleTree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();
  std::vector<double> d(points.size());
  const std::vector<std::size_t> order = mesh::hilbert_order(points);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      // Along the Hilbert order each query starts from the previous one's
                      // closest point: the kd-tree of hints is asked once per block.
                      Point3 hint = tree.closest_point(points[order[r.begin()]]);
                      for (std::size_t at = r.begin(); at != r.end(); ++at) {
                        const std::size_t i = order[at];
                        hint = tree.closest_point(points[i], hint);
                        d[i] = std::sqrt(CGAL::squared_distance(points[i], hint));
                      }
                    });
  return d;
}

std::vector<double> distances_to_points(const std::vector<Point3>& points, const std::vector<Point3>& reference) {
  if (points.empty() || reference.empty()) return {};
  NeighborSearch::Tree tree(reference.begin(), reference.end());
  tree.build();
  std::vector<double> d(points.size());
  const std::vector<std::size_t> order = mesh::hilbert_order(points);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 1024),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t at = r.begin(); at != r.end(); ++at) {
                        const std::size_t i = order[at];
                        NeighborSearch search(tree, points[i], 1);
                        d[i] = std::sqrt(search.begin()->second);
                      }
                    });
  return d;
}

DirectedDistance points_to_mesh(const std::vector<Point3>& points, const TriangleMesh& mesh) {
  const std::vector<double> d = distances_to_mesh(points, mesh);
  return d.empty() ? DirectedDistance{} : summarize(points, d);
}

DirectedDistance points_to_points(const std::vector<Point3>& points,
                                  const std::vector<Point3>& reference) {
  const std::vector<double> d = distances_to_points(points, reference);
  return d.empty() ? DirectedDistance{} : summarize(points, d);
}

DirectedDistance curves_to_points(const std::vector<Polyline>& curves, const std::vector<Point3>& points,
                                  double max_step) {
  if (!(max_step > 0)) throw InvalidInput("curves_to_points: max_step must be > 0");
  std::vector<Point3> along;
  for (const Polyline& curve : curves) {
    for (std::size_t i = 0; i < curve.size(); ++i) {
      const Point3& a = curve[i];
      const Point3& b = curve[(i + 1) % curve.size()];
      const auto steps = static_cast<std::size_t>(std::ceil(std::sqrt(CGAL::squared_distance(a, b)) / max_step));
      for (std::size_t k = 0; k < std::max<std::size_t>(steps, 1); ++k)
        along.push_back(a + (static_cast<double>(k) / static_cast<double>(std::max<std::size_t>(steps, 1))) * (b - a));
    }
  }
  return points_to_points(along, points);
}

}  // namespace envcrust::distance
