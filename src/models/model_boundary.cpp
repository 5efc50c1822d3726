// The boundary of a model of several patches: the pieces of the patches' exact boundary curves
// that lie on the joined tessellation's border loops, in the loops' order, with their frames.
#include "model_boundary.h"

#include "envcrust/topology.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <algorithm>
#include <cmath>

namespace envcrust::models {
namespace {

using Segment = Kernel::Segment_3;
using Primitive = CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// Conormals of two patches meeting on the boundary that differ by more than this make a
// corner (as a loop turning by it does for mesh_boundary_curves).
constexpr double kCornerCos = 0.8660254037844386;  // cos 30 degrees

// A vertex of a patch's exact boundary curve placed on a border loop of the joined mesh.
struct Placed {
  double s = 0;  // arc length along the loop
  std::size_t patch = 0;
  BoundaryVertex vertex;
};

// The vertex turned to run the other way along its curve.
BoundaryVertex reversed(BoundaryVertex v) {
  v.tangent = -v.tangent;
  if (v.is_corner) std::swap(v.conormal, v.conormal_next);
  return v;
}

}  // namespace

std::vector<BoundaryCurve> model_boundary_curves(const TriangleMesh& truth,
                                                 const std::vector<std::vector<BoundaryCurve>>& patch_curves,
                                                 double tolerance) {
  // The loops alone (the truth is welded already: no full analysis needed).
  const auto loops = topology::boundary_loops(truth);
  if (loops.empty()) return {};
  // The loops' segments, with the loop and arc length where each starts.
  std::vector<Segment> segments;
  std::vector<std::pair<std::size_t, double>> segment_start;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto polyline = loops[l].polyline(truth.vertices);
    double s = 0;
    for (std::size_t k = 0; k < polyline.size(); ++k) {
      const Point3& a = polyline[k];
      const Point3& b = polyline[(k + 1) % polyline.size()];
      segments.emplace_back(a, b);
      segment_start.emplace_back(l, s);
      s += std::sqrt(CGAL::squared_distance(a, b));
    }
  }
  SegmentTree tree(segments.cbegin(), segments.cend());
  tree.accelerate_distance_queries();

  std::vector<std::vector<Placed>> placed(loops.size());
  for (std::size_t p = 0; p < patch_curves.size(); ++p) {
    for (const auto& curve : patch_curves[p]) {
      for (const auto& v : curve.vertices) {
        const auto [point, id] = tree.closest_point_and_primitive(v.position);
        if (CGAL::squared_distance(point, v.position) > tolerance * tolerance) continue;  // on a joined edge
        const auto k = static_cast<std::size_t>(id - segments.cbegin());
        const auto [loop, start] = segment_start[k];
        const double s = start + std::sqrt(CGAL::squared_distance(segments[k].source(), point));
        // Tangents run along the loop.
        const Vector3 along = segments[k].to_vector();
        placed[loop].push_back({s, p, v.tangent * along < 0 ? reversed(v) : v});
      }
    }
  }

  std::vector<BoundaryCurve> curves;
  const double tol2 = tolerance * tolerance;
  for (auto& list : placed) {
    if (list.empty()) continue;
    std::stable_sort(list.begin(), list.end(), [](const Placed& a, const Placed& b) { return a.s < b.s; });
    // Vertices at one point (within the tolerance) are one vertex of the loop: where two
    // patches meet, the one the loop arrives from (the patch of the vertex before) gives the
    // position, tangent and arriving conormal, the other the leaving conormal; a corner when
    // the two differ. A patch's own corner on a joined edge is no corner of the loop.
    BoundaryCurve curve;
    std::size_t previous_patch = list.back().patch;
    for (std::size_t a = 0; a < list.size();) {
      std::size_t b = a + 1;
      while (b < list.size() && CGAL::squared_distance(list[a].vertex.position, list[b].vertex.position) <= tol2) ++b;
      std::size_t arriving = a, leaving = a;
      for (std::size_t k = a; k < b; ++k) {
        if (list[k].patch == previous_patch) arriving = k;
        else leaving = k;
      }
      if (b - a == 1 || arriving == leaving) {
        curve.vertices.push_back(list[arriving].vertex);
      } else {
        BoundaryVertex v = list[arriving].vertex;
        const BoundaryVertex& next = list[leaving].vertex;
        const Vector3 leaving_conormal = next.is_corner ? next.conormal_next : next.conormal;
        v.is_corner = v.conormal * leaving_conormal < kCornerCos;
        v.conormal_next = v.is_corner ? leaving_conormal : Vector3(0, 0, 0);
        curve.vertices.push_back(v);
      }
      previous_patch = list[leaving].patch;
      a = b;
    }
    // The same point at both ends (the loop's start lies where it closes): once.
    if (curve.vertices.size() > 1 &&
        CGAL::squared_distance(curve.vertices.back().position, curve.vertices.front().position) <= tol2)
      curve.vertices.pop_back();
    for (std::size_t k = 1; k < curve.vertices.size(); ++k)  // normal lines: keep the sign going
      if (curve.vertices[k].normal * curve.vertices[k - 1].normal < 0) curve.vertices[k].normal = -curve.vertices[k].normal;
    if (curve.vertices.size() >= 3) curves.push_back(std::move(curve));
  }
  return curves;
}

}  // namespace envcrust::models
