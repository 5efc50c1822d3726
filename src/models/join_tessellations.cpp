// Joining the patches' tessellations along the border edges they share: T-junctions split,
// nearby border vertices welded.
#include "envcrust/models.h"

#include "envcrust/mesh.h"
#include "envcrust/union_find.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace envcrust::models {
namespace {

// Border vertices left open within this many tolerances of another patch's border are
// reported (JoinStats::near_misses): a model whose faces meet less closely than the tolerance.
constexpr double kNearMissFactor = 20.0;

using Segment = Kernel::Segment_3;
using Primitive = CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

std::uint64_t edge_key(Index a, Index b) {
  return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

// A border edge (one face) of the concatenated tessellations, from a to b as its face runs it.
struct BorderEdge {
  Index a = 0, b = 0;
  std::size_t face = 0;
};

// A border vertex of another patch lying on a border edge: where the edge is split.
struct Split {
  double t = 0;  // along a -> b
  Index vertex = 0;
};

// The border edges, each with the face that has it, a -> b in the face's winding.
std::vector<BorderEdge> border_edges(const TriangleMesh& mesh) {
  std::unordered_map<std::uint64_t, std::pair<int, BorderEdge>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const Index a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
      auto& [count, edge] = edges[edge_key(a, b)];
      if (++count == 1) edge = {a, b, f};
    }
  }
  std::vector<BorderEdge> out;
  for (const auto& [key, entry] : edges)
    if (entry.first == 1) out.push_back(entry.second);
  // The map's order depends on the hash: sort for a result that is a function of the input.
  std::sort(out.begin(), out.end(), [](const BorderEdge& x, const BorderEdge& y) { return x.face != y.face ? x.face < y.face : x.a < y.a; });
  return out;
}

using Triangle = std::array<Index, 3>;
constexpr Index kUnset = ~Index{0};

// The face's corners with the split points of its border edges in winding order, and the
// position (0..2) in `t` of the first corner of each split edge.
std::pair<std::vector<Index>, std::vector<int>> split_polygon(const Triangle& t, std::size_t face,
                                                              const std::multimap<std::size_t, std::size_t>& edges_of_face,
                                                              const std::vector<BorderEdge>& borders,
                                                              const std::vector<std::vector<Index>>& new_vertices) {
  std::vector<Index> polygon;
  std::vector<int> split_starts;
  const auto [first, last] = edges_of_face.equal_range(face);
  for (int k = 0; k < 3; ++k) {
    const Index a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
    polygon.push_back(a);
    for (auto it = first; it != last; ++it) {
      const BorderEdge& e = borders[it->second];
      if (e.a != a || e.b != b) continue;
      polygon.insert(polygon.end(), new_vertices[it->second].begin(), new_vertices[it->second].end());
      split_starts.push_back(k);
    }
  }
  return {polygon, split_starts};
}

}  // namespace

JoinedMesh join_tessellations(const std::vector<TriangleMesh>& patches, double tolerance) {
  JoinedMesh out;
  out.stats.patches = patches.size();
  out.stats.tolerance = tolerance;
  TriangleMesh& mesh = out.mesh;
  std::vector<std::size_t> patch_of;  // per vertex
  for (std::size_t p = 0; p < patches.size(); ++p) {
    const auto offset = static_cast<Index>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), patches[p].vertices.begin(), patches[p].vertices.end());
    patch_of.resize(mesh.vertices.size(), p);
    for (const auto& t : patches[p].triangles) mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  if (patches.size() < 2) return out;

  const std::vector<BorderEdge> borders = border_edges(mesh);
  std::vector<Segment> segments;
  segments.reserve(borders.size());
  std::vector<char> is_border(mesh.vertices.size(), 0);
  for (const auto& e : borders) {
    segments.emplace_back(mesh.vertices[e.a], mesh.vertices[e.b]);
    is_border[e.a] = is_border[e.b] = 1;
  }
  SegmentTree tree(segments.cbegin(), segments.cend());

  // Each border vertex against the other patches' border edges near it: welded to an end
  // within the tolerance, else splitting the edge where it lies.
  std::vector<std::pair<Index, Index>> welds;
  std::vector<std::vector<Split>> splits(borders.size());
  const double tol2 = tolerance * tolerance;
  std::vector<Primitive::Id> near;
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    if (!is_border[v]) continue;
    const Point3& p = mesh.vertices[v];
    near.clear();
    const double reach = kNearMissFactor * tolerance;  // near misses are looked for too
    const CGAL::Bbox_3 box(p.x() - reach, p.y() - reach, p.z() - reach, p.x() + reach, p.y() + reach, p.z() + reach);
    tree.all_intersected_primitives(box, std::back_inserter(near));
    double gap2 = reach * reach * 2;  // to the nearest border of another patch
    for (const auto id : near) {
      const auto s = static_cast<std::size_t>(id - segments.cbegin());
      const BorderEdge& e = borders[s];
      if (patch_of[e.a] == patch_of[v]) continue;
      const double d2 = CGAL::squared_distance(p, segments[s]);
      gap2 = std::min(gap2, d2);
      if (d2 > tol2) continue;
      const double da = CGAL::squared_distance(p, mesh.vertices[e.a]), db = CGAL::squared_distance(p, mesh.vertices[e.b]);
      if (std::min(da, db) <= tol2) {
        welds.emplace_back(v, da <= db ? e.a : e.b);
        continue;
      }
      const Vector3 ab = mesh.vertices[e.b] - mesh.vertices[e.a];
      splits[s].push_back({((p - mesh.vertices[e.a]) * ab) / ab.squared_length(), v});
    }
    if (gap2 <= tol2) {
      out.stats.largest_gap = std::max(out.stats.largest_gap, std::sqrt(gap2));
    } else if (gap2 <= reach * reach) {
      ++out.stats.near_misses;
      out.stats.nearest_miss = out.stats.nearest_miss > 0 ? std::min(out.stats.nearest_miss, std::sqrt(gap2)) : std::sqrt(gap2);
    }
  }

  // Split points become vertices of their own, welded to the vertex that made them, in order
  // along each edge; the same vertex twice, or two at one place, count once.
  std::vector<std::vector<Index>> new_vertices(borders.size());
  std::multimap<std::size_t, std::size_t> edges_of_face;  // split border edges by face
  for (std::size_t s = 0; s < borders.size(); ++s) {
    auto& list = splits[s];
    if (list.empty()) continue;
    std::sort(list.begin(), list.end(), [](const Split& x, const Split& y) { return x.t < y.t; });
    for (std::size_t k = 0; k < list.size(); ++k) {
      if (k > 0 && (list[k].vertex == list[k - 1].vertex || list[k].t <= list[k - 1].t)) continue;
      const auto added = static_cast<Index>(mesh.vertices.size());
      mesh.vertices.push_back(mesh.vertices[list[k].vertex]);
      new_vertices[s].push_back(added);
      welds.emplace_back(added, list[k].vertex);
    }
    edges_of_face.emplace(borders[s].face, s);
    ++out.stats.split_edges;
  }
  topology::UnionFind all(mesh.vertices.size());
  for (const auto& [a, b] : welds) all.unite(a, b);

  // Faces with split border edges become fans: from the opposite corner when one edge is
  // split, else from a vertex added at the centroid (no fan triangle then lies on a line).
  std::vector<Triangle> triangles;
  std::vector<std::size_t> face_patch;
  triangles.reserve(mesh.triangles.size() + 2 * out.stats.split_edges);
  const std::size_t vertex_count = mesh.vertices.size();
  std::vector<Point3> centroids;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const std::size_t patch = patch_of[t[0]];
    if (!edges_of_face.contains(f)) {
      triangles.push_back(t);
      face_patch.push_back(patch);
      continue;
    }
    const auto [polygon, split_starts] = split_polygon(t, f, edges_of_face, borders, new_vertices);
    const std::size_t n = polygon.size();
    if (split_starts.size() == 1) {
      const Index apex_vertex = t[static_cast<std::size_t>((split_starts.front() + 2) % 3)];
      const auto apex = static_cast<std::size_t>(std::find(polygon.begin(), polygon.end(), apex_vertex) - polygon.begin());
      for (std::size_t i = 1; i + 1 < n; ++i)
        triangles.push_back({polygon[apex], polygon[(apex + i) % n], polygon[(apex + i + 1) % n]});
    } else {
      const auto centre = static_cast<Index>(vertex_count + centroids.size());
      centroids.push_back(CGAL::centroid(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
      for (std::size_t i = 0; i < n; ++i) triangles.push_back({centre, polygon[i], polygon[(i + 1) % n]});
    }
    face_patch.resize(triangles.size(), patch);
  }

  // Weld: each set of vertices becomes its root (its position kept); faces that collapse
  // (a side shorter than the tolerance) or repeat another are dropped.
  std::vector<Index> representative(vertex_count + centroids.size());
  for (Index v = 0; v < vertex_count; ++v) representative[v] = all.find(v);
  for (std::size_t c = 0; c < centroids.size(); ++c) representative[vertex_count + c] = static_cast<Index>(vertex_count + c);
  mesh.vertices.insert(mesh.vertices.end(), centroids.begin(), centroids.end());
  mesh.triangles = std::move(triangles);
  for (Triangle& t : mesh.triangles)
    for (Index& v : t) v = representative[v];
  const std::vector<char> dropped = mesh::repeated_or_degenerate_faces(mesh);
  std::vector<Index> renumber(mesh.vertices.size(), kUnset);
  std::vector<Point3> used;
  std::vector<Triangle> kept;
  std::unordered_map<std::uint64_t, std::size_t> edge_patch;  // the first face's patch per edge
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    if (dropped[f]) continue;
    Triangle t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const auto [it, is_new] = edge_patch.emplace(edge_key(t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]), face_patch[f]);
      if (!is_new && it->second != face_patch[f]) ++out.stats.joined_edges;
    }
    for (Index& v : t) {
      if (renumber[v] == kUnset) renumber[v] = static_cast<Index>(used.size()), used.push_back(mesh.vertices[v]);
      v = renumber[v];
    }
    kept.push_back(t);
  }
  mesh.vertices = std::move(used);
  mesh.triangles = std::move(kept);
  return out;
}

}  // namespace envcrust::models
