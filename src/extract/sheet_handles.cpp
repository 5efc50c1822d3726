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

namespace envcrust::extract {
namespace {

// Seeds such that every vertex lies within `spacing` of one along the sheet: a greedy cover,
// each vertex not yet covered becomes a seed and covers its geodesic ball. On the bunny's
// sheet 4.6 times fewer seeds than one per occupied cell of a grid with the same guarantee in
// space (cells of side spacing / sqrt(3)), and the guarantee holds along the sheet.
std::vector<Index> covering_seeds(const TriangleMesh& mesh, const MeshAdjacency& a, double spacing) {
  std::vector<char> covered(mesh.vertices.size(), 1);
  for (const auto& t : mesh.triangles)
    for (const Index v : t) covered[v] = 0;
  GeodesicBall ball(mesh.vertices.size());
  std::vector<Index> seeds;
  for (Index v = 0; v < mesh.vertices.size(); ++v) {
    if (covered[v]) continue;
    seeds.push_back(v);
    ball.grow(a, std::span(&v, 1), spacing);
    for (const Index w : ball.reached()) covered[w] = 1;
  }
  return seeds;
}

// Per-thread working memory of the ball test, reused from ball to ball: per-vertex and
// per-edge slots are valid only where their stamp is the current ball's.
struct BallScratch {
  BallScratch(std::size_t vertices, std::size_t edges)
      : ball(vertices), vertex_stamp(vertices, 0), vertex_local(vertices, 0), edge_stamp(edges, 0) {}
  GeodesicBall ball;
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> faces;
  std::vector<std::uint32_t> vertex_stamp;
  std::vector<Index> vertex_local;   ///< local id of a vertex of the ball's faces
  std::vector<std::uint32_t> edge_stamp;
  topology::UnionFind component{0}, hole{0};  ///< over local ids
  std::vector<int> border_degree;     ///< per local id: border edges of the sheet at it
  std::vector<int> hole_state;
};

// Whether the faces of the ball (all three corners inside) fail to be discs: their Euler
// characteristic, with each hole of the sheet that lies wholly inside counted as capped, is
// below their number of components. A disc or half-disc (at the sheet's border) passes; a
// handle, a cross-cap or a tube narrower than the ball fails.
bool ball_is_not_a_disc(const TriangleMesh& mesh, const topology::MeshGraph& g, const MeshAdjacency& a,
                        BallScratch& s) {
  s.faces.clear();
  for (const Index v : s.ball.reached())
    for (std::size_t k = a.face_begin[v]; k < a.face_begin[v + 1]; ++k) {
      const std::uint32_t f = a.faces[k];
      const auto& t = mesh.triangles[f];
      // Each face once: from its inside corner of smallest index.
      if (s.ball.contains(t[0]) && s.ball.contains(t[1]) && s.ball.contains(t[2]) &&
          std::min({t[0], t[1], t[2]}) == v)
        s.faces.push_back(f);
    }
  if (s.faces.empty()) return false;
  if (++s.stamp == 0) {  // wrapped: clear the stamps
    std::fill(s.vertex_stamp.begin(), s.vertex_stamp.end(), 0);
    std::fill(s.edge_stamp.begin(), s.edge_stamp.end(), 0);
    s.stamp = 1;
  }
  // Local ids of the faces' vertices, and their distinct edges.
  Index vertices = 0;
  long edges = 0;
  for (const std::uint32_t f : s.faces) {
    for (const Index c : mesh.triangles[f])
      if (s.vertex_stamp[c] != s.stamp) s.vertex_stamp[c] = s.stamp, s.vertex_local[c] = vertices++;
    for (const std::uint32_t e : g.face_edges[f])
      if (s.edge_stamp[e] != s.stamp) s.edge_stamp[e] = s.stamp, ++edges;
  }
  // Components of the faces (through shared vertices, which is what a fan of faces around a
  // vertex joins), and the sheet's holes among them: connected border edges (one face in the
  // whole sheet) whose every vertex has two of them in the ball form a closed loop.
  s.component.reset(vertices);
  s.hole.reset(vertices);
  s.border_degree.assign(vertices, 0);
  for (const std::uint32_t f : s.faces) {
    const auto& t = mesh.triangles[f];
    s.component.unite(s.vertex_local[t[0]], s.vertex_local[t[1]]);
    s.component.unite(s.vertex_local[t[0]], s.vertex_local[t[2]]);
    for (const std::uint32_t e : g.face_edges[f]) {
      if (g.face_count_of_edge(e) != 1) continue;  // a border edge belongs to this face only
      const Index u = s.vertex_local[g.edges[e].first], w = s.vertex_local[g.edges[e].second];
      s.hole.unite(u, w);
      ++s.border_degree[u], ++s.border_degree[w];
    }
  }
  long components = 0, capped = 0;
  s.hole_state.assign(vertices, 0);  // per hole root: 1 closed so far, 2 open
  for (Index i = 0; i < vertices; ++i) {
    components += s.component.find(i) == i;
    if (s.border_degree[i] == 0) continue;
    int& state = s.hole_state[s.hole.find(i)];
    state = (state == 2 || s.border_degree[i] != 2) ? 2 : 1;
  }
  for (const int state : s.hole_state) capped += state == 1;
  const long chi = static_cast<long>(vertices) - edges + static_cast<long>(s.faces.size()) + capped;
  return chi < components;
}

}  // namespace

HandleCutStats cut_local_handles(TaggedMesh& tagged, double radius) {
  HandleCutStats stats;
  TriangleMesh& mesh = tagged.mesh;
  if (mesh.triangles.empty()) return stats;
  const topology::MeshGraph g = topology::build_mesh_graph(mesh.triangles, mesh.vertices.size());
  const MeshAdjacency a = mesh_adjacency(mesh, g);
  // Every vertex within half a radius of a seed: a defect smaller than about half the radius
  // lies wholly inside the ball of some seed.
  const std::vector<Index> seeds = covering_seeds(mesh, a, 0.5 * radius);
  std::vector<char> flagged(seeds.size(), 0);
  tbb::enumerable_thread_specific<BallScratch> scratch([&] { return BallScratch(mesh.vertices.size(), g.edges.size()); });
  // A ball that is not a disc is confirmed on the ball three times as large: around a finger
  // thinner than the ball (a toe), the ball is an annulus but the larger one takes in the
  // fingertip and is a disc again; a handle or a cross-cap stays in any larger ball.
  tbb::parallel_for(std::size_t{0}, seeds.size(), [&](std::size_t i) {
    BallScratch& s = scratch.local();
    s.ball.grow(a, std::span(&seeds[i], 1), radius);
    if (!ball_is_not_a_disc(mesh, g, a, s)) return;
    s.ball.grow(a, std::span(&seeds[i], 1), 3 * radius);
    flagged[i] = ball_is_not_a_disc(mesh, g, a, s);
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
      (ball_is_not_a_disc(mesh, g, a, s) ? hi : lo) = mid;
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
