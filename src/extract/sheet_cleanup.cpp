// Cleaning the raw sheet into a 2-manifold: non-manifold edges, pinched vertices, outer
// pieces and crumbs, holes below the envelope's resolution (docs/method.md §8.4).
#include "sheet_mesh.h"

#include "envcrust/median.h"
#include "envcrust/mesh_graph.h"
#include "envcrust/nearest_index.h"
#include "envcrust/topology.h"
#include "envcrust/union_find.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <unordered_map>

namespace envcrust::extract {

std::size_t remove_faces(TaggedMesh& t, const std::vector<char>& remove) {
  std::size_t kept = 0;
  for (std::size_t f = 0; f < t.mesh.triangles.size(); ++f) {
    if (remove[f]) continue;
    t.mesh.triangles[kept] = t.mesh.triangles[f];
    t.face_dot[kept] = t.face_dot[f];
    ++kept;
  }
  const std::size_t removed = t.mesh.triangles.size() - kept;
  t.mesh.triangles.resize(kept);
  t.face_dot.resize(kept);
  return removed;
}

namespace {

// fill_short_loops: a piece smaller than this times the area of a flat disc of the loop's
// perimeter is an island, not a sheet with a hole (a hemisphere spans 2).
constexpr double kMinPieceAreaOverSpan = 1.5;

// Per face, a face id standing for its connected component (faces joined across edges).
std::vector<std::uint32_t> component_roots(const TriangleMesh& m) {
  const auto g = topology::build_mesh_graph(m.triangles, m.vertices.size());
  topology::UnionFind uf(g.faces.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e)
    for (std::uint32_t i = g.edge_face_begin[e] + 1; i < g.edge_face_begin[e + 1]; ++i)
      uf.unite(g.edge_faces[g.edge_face_begin[e]], g.edge_faces[i]);
  std::vector<std::uint32_t> root(g.faces.size());
  for (std::uint32_t f = 0; f < root.size(); ++f) root[f] = uf.find(f);
  return root;
}

double face_area(const TriangleMesh& m, const std::array<Index, 3>& f) {
  return std::sqrt(Kernel::Triangle_3(m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]).squared_area());
}

// filter_components: a piece under the area fraction that lies on at least this many samples
// no kept piece comes near is an island of the input (a speck of a scan apart from the
// rest), not a crumb of the sheet.
constexpr std::size_t kMinIslandSamples = 20;

// Mark kept (in `keep`) the `small` pieces that are islands: at least kMinIslandSamples
// samples lie within their allowed distance of a vertex of the piece (the vertex's nearest
// sample) and no vertex of a kept piece lies that close to the vertex.
void keep_islands(const TriangleMesh& m, const std::vector<std::vector<Index>>& component_vertices,
                  const NearestIndex& samples, const std::vector<double>& max_distance,
                  const std::vector<char>& small, std::vector<char>& keep) {
  if (std::find(small.begin(), small.end(), 1) == small.end()) return;
  std::vector<Point3> kept_vertices;
  for (std::size_t c = 0; c < component_vertices.size(); ++c)
    if (keep[c])
      for (const Index v : component_vertices[c]) kept_vertices.push_back(m.vertices[v]);
  const NearestIndex kept(kept_vertices);
  for (std::size_t c = 0; c < component_vertices.size(); ++c) {
    if (!small[c]) continue;
    std::vector<std::size_t> own;
    for (const Index v : component_vertices[c]) {
      const auto [j, distance] = samples.nearest(m.vertices[v]);
      if (distance > max_distance[j]) continue;
      if (!kept.empty() && kept.any_within(m.vertices[v], max_distance[j])) continue;
      own.push_back(j);
    }
    std::sort(own.begin(), own.end());
    own.erase(std::unique(own.begin(), own.end()), own.end());
    if (own.size() >= kMinIslandSamples) keep[c] = 1;
  }
}

}  // namespace

std::size_t resolve_non_manifold_edges(TaggedMesh& t) {
  std::vector<char> remove(t.mesh.triangles.size(), 0);
  {  // duplicate faces (same vertex set): keep the first
    std::vector<std::pair<std::array<Index, 3>, std::size_t>> keys;
    keys.reserve(t.mesh.triangles.size());
    for (std::size_t f = 0; f < t.mesh.triangles.size(); ++f) {
      auto k = t.mesh.triangles[f];
      std::sort(k.begin(), k.end());
      keys.emplace_back(k, f);
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i)
      if (keys[i].first == keys[i - 1].first) remove[keys[i].second] = 1;
  }
  const auto graph = topology::build_mesh_graph(t.mesh.triangles, t.mesh.vertices.size());
  for (std::size_t e = 0; e < graph.edges.size(); ++e) {
    const std::uint32_t begin = graph.edge_face_begin[e];
    const std::uint32_t end = graph.edge_face_begin[e + 1];
    std::vector<std::uint32_t> faces;
    for (std::uint32_t i = begin; i < end; ++i)
      if (!remove[graph.edge_faces[i]]) faces.push_back(graph.edge_faces[i]);
    if (faces.size() < 3) continue;
    std::sort(faces.begin(), faces.end(), [&](std::uint32_t a, std::uint32_t b) {
      return t.face_dot[a] != t.face_dot[b] ? t.face_dot[a] < t.face_dot[b] : a < b;
    });
    for (std::size_t i = 2; i < faces.size(); ++i) remove[faces[i]] = 1;
  }
  const auto removed = static_cast<std::size_t>(std::count(remove.begin(), remove.end(), 1));
  remove_faces(t, remove);
  return removed;
}

std::size_t split_pinched_vertices(TaggedMesh& t) {
  std::size_t copies = 0;
  for (int round = 0; round < 4; ++round) {
    const auto g = topology::build_mesh_graph(t.mesh.triangles, t.mesh.vertices.size());
    const auto fan = topology::corner_fans(g);
    // Pinched vertices (corners in two or more fans) first: almost every vertex has one fan,
    // and per-vertex containers for all of them cost more than the rest of the step.
    constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> first_fan(g.num_vertices, kNone);
    std::vector<char> is_pinched(g.num_vertices, 0);
    for (std::uint32_t c = 0; c < 3 * g.faces.size(); ++c) {
      const Index v = g.faces[c / 3][c % 3];
      if (first_fan[v] == kNone) first_fan[v] = fan[c];
      else if (first_fan[v] != fan[c]) is_pinched[v] = 1;
    }
    // (vertex, fan, face) of the pinched vertices' corners, in that order.
    std::vector<std::array<std::uint32_t, 3>> corners;
    for (std::uint32_t c = 0; c < 3 * g.faces.size(); ++c) {
      const Index v = g.faces[c / 3][c % 3];
      if (is_pinched[v]) corners.push_back({v, fan[c], c / 3});
    }
    std::sort(corners.begin(), corners.end());
    std::vector<char> remove(g.faces.size(), 0);
    const bool changed = !corners.empty();
    for (std::size_t begin = 0; begin < corners.size();) {
      const Index v = corners[begin][0];
      std::vector<std::vector<std::uint32_t>> list;
      std::size_t end = begin;
      for (; end < corners.size() && corners[end][0] == v; ++end) {
        if (end == begin || corners[end][1] != corners[end - 1][1]) list.emplace_back();
        list.back().push_back(corners[end][2]);
      }
      begin = end;
      std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) {
        return a.size() != b.size() ? a.size() > b.size() : a.front() < b.front();
      });
      for (std::size_t k = 0; k < list.size(); ++k) {
        if (list[k].size() < 3) {
          for (auto f : list[k]) remove[f] = 1;
          continue;
        }
        if (k == 0) continue;  // the largest fan keeps the vertex
        // The copy moves 1% of the mean edge towards the fan's centroid.
        Vector3 centroid(0, 0, 0);
        double edge_sum = 0.0;
        std::size_t count = 0;
        for (auto f : list[k]) {
          for (Index w : t.mesh.triangles[f]) {
            if (w == v) continue;
            centroid = centroid + (t.mesh.vertices[w] - CGAL::ORIGIN);
            edge_sum += std::sqrt(CGAL::squared_distance(t.mesh.vertices[w], t.mesh.vertices[v]));
            ++count;
          }
        }
        const Point3 c = CGAL::ORIGIN + centroid / static_cast<double>(count);
        const Vector3 towards = c - t.mesh.vertices[v];
        const double len = std::sqrt(towards.squared_length());
        const double step = 0.01 * edge_sum / static_cast<double>(count);
        const auto copy = static_cast<Index>(t.mesh.vertices.size());
        t.mesh.vertices.push_back(len > 0 ? t.mesh.vertices[v] + (step / len) * towards : t.mesh.vertices[v]);
        for (auto f : list[k])
          for (Index& w : t.mesh.triangles[f])
            if (w == v) w = copy;
        ++copies;
      }
    }
    remove_faces(t, remove);
    if (!changed) break;
  }
  return copies;
}

std::size_t filter_components(TaggedMesh& t, const NearestIndex& nearest,
                              const std::vector<double>& max_distance, double min_area_fraction) {
  if (t.mesh.triangles.empty()) return 0;
  const std::vector<std::uint32_t> face_root = component_roots(t.mesh);
  std::map<std::uint32_t, std::vector<std::uint32_t>> components;
  for (std::uint32_t f = 0; f < face_root.size(); ++f) components[face_root[f]].push_back(f);
  double total_area = 0.0;
  std::vector<double> areas;
  std::vector<double> medians;
  std::vector<std::vector<Index>> component_vertices;
  for (const auto& [root, faces] : components) {
    double area = 0.0;
    std::vector<Index> vertices;
    for (auto f : faces) {
      area += face_area(t.mesh, t.mesh.triangles[f]);
      for (Index v : t.mesh.triangles[f]) vertices.push_back(v);
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::vector<double> d;
    const std::size_t stride = std::max<std::size_t>(1, vertices.size() / 200);
    for (std::size_t i = 0; i < vertices.size(); i += stride) {
      const auto [j, distance] = nearest.nearest(t.mesh.vertices[vertices[i]]);
      d.push_back(distance / max_distance[j]);
    }
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    medians.push_back(d[d.size() / 2]);
    areas.push_back(area);
    total_area += area;
    component_vertices.push_back(std::move(vertices));
  }
  std::vector<char> keep(components.size(), 0), small(components.size(), 0);
  for (std::size_t c = 0; c < components.size(); ++c) {
    if (!(medians[c] < 1.0)) continue;
    (areas[c] >= min_area_fraction * total_area ? keep : small)[c] = 1;
  }
  keep_islands(t.mesh, component_vertices, nearest, max_distance, small, keep);
  std::vector<char> remove(face_root.size(), 0);
  std::size_t dropped = 0;
  std::size_t index = 0;
  for (const auto& [root, faces] : components) {
    if (!keep[index]) {
      ++dropped;
      for (auto f : faces) remove[f] = 1;
    }
    ++index;
  }
  remove_faces(t, remove);
  return dropped;
}

std::size_t drop_far_faces(TaggedMesh& t, const NearestIndex& nearest, const std::vector<double>& max_distance) {
  if (t.mesh.triangles.empty() || nearest.empty()) return 0;
  std::vector<char> remove(t.mesh.triangles.size(), 0);
  // A face with no sample within the largest allowed distance is far whatever its nearest
  // sample; the range test settles it without the nearest-point search.
  const double farthest_allowed = *std::max_element(max_distance.begin(), max_distance.end());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, t.mesh.triangles.size(), 1024), [&](const auto& range) {
    for (std::size_t f = range.begin(); f != range.end(); ++f) {
      const auto& tri = t.mesh.triangles[f];
      const Point3 centre = CGAL::centroid(t.mesh.vertices[tri[0]], t.mesh.vertices[tri[1]], t.mesh.vertices[tri[2]]);
      if (!nearest.any_within(centre, farthest_allowed)) {
        remove[f] = 1;
        continue;
      }
      const auto [j, distance] = nearest.nearest(centre);
      remove[f] = distance > max_distance[j] ? 1 : 0;
    }
  });
  const auto dropped = static_cast<std::size_t>(std::count(remove.begin(), remove.end(), 1));
  remove_faces(t, remove);
  return dropped;
}

namespace {

// Triangles from the loop's edges to its centroid (a new vertex).
void fill_with_fan(TaggedMesh& t, const std::vector<Index>& loop) {
  Vector3 sum(0, 0, 0);
  for (Index v : loop) sum = sum + (t.mesh.vertices[v] - CGAL::ORIGIN);
  const auto centre = static_cast<Index>(t.mesh.vertices.size());
  t.mesh.vertices.push_back(CGAL::ORIGIN + sum / static_cast<double>(loop.size()));
  for (std::size_t i = 0; i < loop.size(); ++i) {
    t.mesh.triangles.push_back({loop[i], loop[(i + 1) % loop.size()], centre});
    t.face_dot.push_back(-1.0);
  }
}

// The simple cycles of a loop that passes through a vertex more than once (a pinch: the
// border touches itself), split there: v a b v c d -> (v a b), (v c d). Each keeps its
// vertices' order; cycles of fewer than 3 vertices (an edge walked there and back) drop out.
std::vector<std::vector<Index>> simple_cycles(const std::vector<Index>& loop) {
  std::vector<std::vector<Index>> cycles;
  std::vector<Index> stack;
  std::unordered_map<Index, std::size_t> at;  // vertex -> its position on the stack
  for (Index v : loop) {
    const auto it = at.find(v);
    if (it != at.end()) {
      std::vector<Index> cycle(stack.begin() + static_cast<std::ptrdiff_t>(it->second), stack.end());
      for (std::size_t k = 1; k < cycle.size(); ++k) at.erase(cycle[k]);
      stack.resize(it->second + 1);
      if (cycle.size() >= 3) cycles.push_back(std::move(cycle));
      continue;
    }
    at[v] = stack.size();
    stack.push_back(v);
  }
  if (stack.size() >= 3) cycles.push_back(std::move(stack));
  return cycles;
}

}  // namespace

void fill_hole(TaggedMesh& t, const std::vector<Index>& loop, const std::unordered_set<std::uint64_t>& sheet_edges) {
  if (fill_with_patch(t, loop, sheet_edges)) return;
  const auto cycles = simple_cycles(loop);
  if (cycles.size() < 2) {
    fill_with_fan(t, loop);
    return;
  }
  for (const auto& cycle : cycles)
    if (!fill_with_patch(t, cycle, sheet_edges)) fill_with_fan(t, cycle);
}

namespace {

std::vector<std::vector<Index>> vertices_of(const std::vector<topology::BoundaryLoop>& loops) {
  std::vector<std::vector<Index>> out;
  out.reserve(loops.size());
  for (const auto& loop : loops) out.push_back(loop.vertices);
  return out;
}

}  // namespace

std::size_t fill_short_loops(TaggedMesh& t, double max_length, const std::function<double(const Point3&)>& unit) {
  const auto loops = topology::boundary_loops(t.mesh);
  std::vector<double> bound(loops.size(), max_length);
  if (unit) {
    std::vector<double> along;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      if (loops[l].vertices.empty()) continue;
      along.clear();
      for (const Index v : loops[l].vertices) along.push_back(unit(t.mesh.vertices[v]));
      bound[l] = max_length * upper_median_in_place(along);
    }
  }
  bool any = false;
  for (std::size_t l = 0; l < loops.size(); ++l)
    any = any || (loops[l].length < bound[l] && loops[l].vertices.size() >= 3);
  if (!any) return 0;
  // A loop is a hole of its piece only if the piece is larger than a disc spanning the loop:
  // the rim of a small island (a flat disc of perimeter L has area L^2 / 4 pi, the most any
  // flat piece has) would make the piece a closed, doubled shell when filled. A cup spans
  // twice that, a pinhole in a closed sheet far more.
  const std::vector<std::uint32_t> root = component_roots(t.mesh);
  std::vector<double> area(root.size(), 0.0);
  std::vector<std::uint32_t> face_of_vertex(t.mesh.vertices.size(), 0);
  for (std::uint32_t f = 0; f < root.size(); ++f) {
    area[root[f]] += face_area(t.mesh, t.mesh.triangles[f]);
    for (const Index v : t.mesh.triangles[f]) face_of_vertex[v] = f;
  }
  std::size_t filled = 0;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    if (loop.length >= bound[l] || loop.vertices.size() < 3) continue;
    const double spanned = loop.length * loop.length / (4.0 * std::numbers::pi);
    if (area[root[face_of_vertex[loop.vertices.front()]]] < kMinPieceAreaOverSpan * spanned) continue;
    fill_with_fan(t, loop.vertices);
    ++filled;
  }
  return filled;
}

namespace {

// Whether at least half the loop's vertices lie within max_distance of a boundary point.
bool runs_along_boundary(const TriangleMesh& m, const std::vector<Index>& loop, const NearestIndex& boundary,
                         double max_distance) {
  if (boundary.empty()) return false;
  std::size_t near = 0;
  for (Index v : loop) near += boundary.nearest(m.vertices[v]).second <= max_distance;
  return 2 * near >= loop.size();
}

}  // namespace

std::size_t fill_loops_away_from_boundary(TaggedMesh& t, const std::vector<Point3>& boundary_points,
                                          double max_distance, HoleFill fill) {
  const NearestIndex nearest(boundary_points);
  const auto loops = topology::boundary_loops(t.mesh);
  const auto sheet_edges =
      fill == HoleFill::Patch ? edges_among(t.mesh, vertices_of(loops)) : std::unordered_set<std::uint64_t>{};
  std::size_t filled = 0;
  for (const auto& loop : loops) {
    if (loop.vertices.size() < 3 || runs_along_boundary(t.mesh, loop.vertices, nearest, max_distance)) continue;
    if (fill == HoleFill::Fan) fill_with_fan(t, loop.vertices);
    else fill_hole(t, loop.vertices, sheet_edges);
    ++filled;
  }
  return filled;
}

std::size_t drop_pieces_away_from_boundary(TaggedMesh& t, const std::vector<Point3>& boundary_points,
                                           double max_distance) {
  if (boundary_points.empty() || t.mesh.triangles.empty()) return 0;
  const std::vector<std::uint32_t> root = component_roots(t.mesh);
  std::vector<std::uint32_t> component_of_vertex(t.mesh.vertices.size(), 0);
  for (std::uint32_t f = 0; f < t.mesh.triangles.size(); ++f)
    for (Index v : t.mesh.triangles[f]) component_of_vertex[v] = root[f];
  // Per component root: 1 it has a border loop, 3 one of them runs along a boundary curve.
  std::vector<char> status(t.mesh.triangles.size(), 0);
  const NearestIndex nearest(boundary_points);
  for (const auto& loop : topology::boundary_loops(t.mesh))
    status[component_of_vertex[loop.vertices.front()]] |=
        runs_along_boundary(t.mesh, loop.vertices, nearest, max_distance) ? 3 : 1;
  // A piece is cut off only when the sheet that follows the curves is larger: a detected curve
  // may be false (a flagged crumple or thin tube on a closed shape), and then the whole sheet
  // away from it, which every sample supports, would go (the femur's 30k samples: 99.9% of the
  // sheet dropped, a piece of 0.1% around the false curve kept).
  std::vector<double> area(t.mesh.triangles.size(), 0.0);
  for (std::uint32_t f = 0; f < t.mesh.triangles.size(); ++f) area[root[f]] += face_area(t.mesh, t.mesh.triangles[f]);
  double along = 0.0;
  for (std::size_t r = 0; r < status.size(); ++r)
    if (status[r] == 3) along = std::max(along, area[r]);
  std::size_t dropped = 0;
  for (std::size_t r = 0; r < status.size(); ++r) {
    if (status[r] == 1 && !(area[r] < along)) status[r] = 0;
    dropped += status[r] == 1;
  }
  if (dropped == 0) return 0;
  std::vector<char> remove(t.mesh.triangles.size(), 0);
  for (std::uint32_t f = 0; f < remove.size(); ++f) remove[f] = status[root[f]] == 1;
  remove_faces(t, remove);
  return dropped;
}

void compact_vertices(TaggedMesh& t) {
  std::vector<Index> index(t.mesh.vertices.size(), std::numeric_limits<Index>::max());
  std::vector<Point3> vertices;
  for (auto& f : t.mesh.triangles) {
    for (Index& v : f) {
      if (index[v] == std::numeric_limits<Index>::max()) {
        index[v] = static_cast<Index>(vertices.size());
        vertices.push_back(t.mesh.vertices[v]);
      }
      v = index[v];
    }
  }
  t.mesh.vertices = std::move(vertices);
}

}  // namespace envcrust::extract
