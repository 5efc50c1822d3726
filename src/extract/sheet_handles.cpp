// Cut out the places where the sheet is not a disc at a given scale (SheetOptions::cut_handles_rel_rho).
#include "sheet_geodesic.h"
#include "sheet_mesh.h"

#include "envcrust/mesh_graph.h"
#include "envcrust/union_find.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace envcrust::extract {
namespace {

// Seeds: one vertex per occupied cell of a grid of side `cell`, so every vertex lies within
// sqrt(3) cell (in space, hence about as far along the sheet) of a seed.
std::vector<Index> grid_seeds(const TriangleMesh& mesh, double cell) {
  std::unordered_map<std::uint64_t, Index> first;
  auto coord = [&](double x) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(x / cell)) & 0x1fffff); };
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (const Index v : t) used[v] = 1;
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    if (!used[v]) continue;
    const Point3& p = mesh.vertices[v];
    first.emplace(coord(p.x()) << 42 | coord(p.y()) << 21 | coord(p.z()), v);
  }
  std::vector<Index> seeds;
  seeds.reserve(first.size());
  for (const auto& [key, v] : first) seeds.push_back(v);
  std::sort(seeds.begin(), seeds.end());
  return seeds;
}

struct BallScratch {
  explicit BallScratch(std::size_t vertices) : ball(vertices) {}
  GeodesicBall ball;
  std::vector<std::uint32_t> faces;
  std::vector<std::pair<Index, Index>> edges;
};

// Whether the faces of the ball (all three corners inside) fail to be discs: their Euler
// characteristic, with each hole of the sheet that lies wholly inside counted as capped, is
// below their number of components. A disc or half-disc (at the sheet's border) passes; a
// handle, a cross-cap or a tube narrower than the ball fails.
bool ball_is_not_a_disc(const TriangleMesh& mesh, const topology::MeshGraph& g, const MeshAdjacency& a,
                        const std::vector<char>& on_border, BallScratch& s) {
  s.faces.clear();
  for (const Index v : s.ball.reached())
    for (std::size_t k = a.face_begin[v]; k < a.face_begin[v + 1]; ++k) {
      const std::uint32_t f = a.faces[k];
      const auto& t = mesh.triangles[f];
      // Each face once: from its inside corner of smallest index.
      Index first = std::numeric_limits<Index>::max();
      bool inside = true;
      for (const Index c : t) {
        inside = inside && s.ball.contains(c);
        first = std::min(first, c);
      }
      if (inside && first == v) s.faces.push_back(f);
    }
  if (s.faces.empty()) return false;
  s.edges.clear();
  for (const std::uint32_t f : s.faces)
    for (int k = 0; k < 3; ++k) {
      const Index u = mesh.triangles[f][k], w = mesh.triangles[f][(k + 1) % 3];
      s.edges.emplace_back(std::min(u, w), std::max(u, w));
    }
  std::sort(s.edges.begin(), s.edges.end());
  const auto edge_count = static_cast<long>(std::unique(s.edges.begin(), s.edges.end()) - s.edges.begin());
  s.edges.resize(static_cast<std::size_t>(edge_count));
  // Vertices used by the faces, components of the faces (through shared vertices, which is
  // what a fan of faces around a vertex joins), and the sheet's border edges among them.
  std::unordered_map<Index, Index> local;
  for (const std::uint32_t f : s.faces)
    for (const Index c : mesh.triangles[f]) local.emplace(c, static_cast<Index>(local.size()));
  topology::UnionFind components(local.size());
  for (const std::uint32_t f : s.faces) {
    const auto& t = mesh.triangles[f];
    components.unite(local[t[0]], local[t[1]]);
    components.unite(local[t[0]], local[t[2]]);
  }
  std::size_t component_count = 0;
  for (const auto& [v, i] : local) component_count += components.find(i) == i;
  // Holes of the sheet wholly inside: cycles of border edges among the ball's edges. Each
  // connected set of border edges whose vertices all have two border edges in the ball is a
  // closed loop.
  topology::UnionFind holes(local.size());
  std::unordered_map<Index, int> border_degree;
  for (const auto& [u, w] : s.edges) {
    if (!(on_border[u] && on_border[w])) continue;
    // A border edge of the sheet: one face in the whole mesh.
    const auto it = std::lower_bound(g.edges.begin(), g.edges.end(), std::make_pair(u, w));
    if (it == g.edges.end() || *it != std::make_pair(u, w)) continue;
    if (g.face_count_of_edge(static_cast<std::size_t>(it - g.edges.begin())) != 1) continue;
    holes.unite(local[u], local[w]);
    ++border_degree[u], ++border_degree[w];
  }
  std::unordered_map<Index, bool> closed;  // hole root -> every vertex has two border edges
  for (const auto& [v, degree] : border_degree) {
    const Index root = holes.find(local[v]);
    auto [it, fresh] = closed.emplace(root, true);
    it->second = it->second && degree == 2;
  }
  long capped = 0;
  for (const auto& [root, is_closed] : closed) capped += is_closed;
  const long chi = static_cast<long>(local.size()) - edge_count + static_cast<long>(s.faces.size()) + capped;
  return chi < static_cast<long>(component_count);
}

}  // namespace

HandleCutStats cut_local_handles(TaggedMesh& tagged, double radius) {
  HandleCutStats stats;
  TriangleMesh& mesh = tagged.mesh;
  if (mesh.triangles.empty()) return stats;
  const topology::MeshGraph g = topology::build_mesh_graph(mesh.triangles, mesh.vertices.size());
  const MeshAdjacency a = mesh_adjacency(mesh, g);
  std::vector<char> on_border(mesh.vertices.size(), 0);
  for (std::size_t e = 0; e < g.edges.size(); ++e)
    if (g.face_count_of_edge(e) == 1) on_border[g.edges[e].first] = on_border[g.edges[e].second] = 1;
  // Seeds half a radius apart: a defect smaller than about half the radius lies wholly
  // inside the ball of some seed.
  const std::vector<Index> seeds = grid_seeds(mesh, 0.5 * radius / std::sqrt(3.0));
  std::vector<char> flagged(seeds.size(), 0);
  tbb::enumerable_thread_specific<BallScratch> scratch([&] { return BallScratch(mesh.vertices.size()); });
  // A ball that is not a disc is confirmed on the ball three times as large: around a finger
  // thinner than the ball (a toe), the ball is an annulus but the larger one takes in the
  // fingertip and is a disc again; a handle or a cross-cap stays in any larger ball.
  tbb::parallel_for(std::size_t{0}, seeds.size(), [&](std::size_t i) {
    BallScratch& s = scratch.local();
    s.ball.grow(a, std::span(&seeds[i], 1), radius);
    if (!ball_is_not_a_disc(mesh, g, a, on_border, s)) return;
    s.ball.grow(a, std::span(&seeds[i], 1), 3 * radius);
    flagged[i] = ball_is_not_a_disc(mesh, g, a, on_border, s);
  });
  // Each flagged ball shrinks to the smallest radius at which it is still not a disc (the
  // defect then lies on its rim), found by bisection; the faces of that ball are removed.
  std::vector<double> smallest(seeds.size(), 0.0);
  tbb::parallel_for(std::size_t{0}, seeds.size(), [&](std::size_t i) {
    if (!flagged[i]) return;
    BallScratch& s = scratch.local();
    double lo = 0, hi = radius;
    for (int step = 0; step < 6; ++step) {
      const double mid = 0.5 * (lo + hi);
      s.ball.grow(a, std::span(&seeds[i], 1), mid);
      (ball_is_not_a_disc(mesh, g, a, on_border, s) ? hi : lo) = mid;
    }
    smallest[i] = hi;
  });
  std::vector<char> remove(mesh.triangles.size(), 0);
  GeodesicBall ball(mesh.vertices.size());
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (!flagged[i]) continue;
    ++stats.balls;
    ball.grow(a, std::span(&seeds[i], 1), smallest[i]);
    for (const Index v : ball.reached())
      for (std::size_t k = a.face_begin[v]; k < a.face_begin[v + 1]; ++k) remove[a.faces[k]] = 1;
  }
  if (stats.balls == 0) return stats;
  stats.faces_removed = remove_faces(tagged, remove);
  make_manifold(tagged);
  return stats;
}

}  // namespace envcrust::extract
