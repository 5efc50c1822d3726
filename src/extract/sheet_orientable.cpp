// Cut a non-orientable sheet open around its orientation seams (SheetOptions::cut_to_orientable).
#include "sheet_mesh.h"

#include "envcrust/mesh_graph.h"
#include "envcrust/topology.h"
#include "envcrust/union_find.h"

#include <CGAL/centroid.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <queue>

namespace envcrust::extract {
namespace {

// Two-face edges that both faces run in the same direction, after orient_faces: the seams
// across which no consistent orientation exists.
std::vector<std::size_t> seam_edges(const TriangleMesh& mesh, const topology::MeshGraph& g) {
  auto runs_forward = [&](std::uint32_t f, Index a, Index b) {
    const auto& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k)
      if (t[k] == a && t[(k + 1) % 3] == b) return true;
    return false;
  };
  std::vector<std::size_t> seams;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (g.face_count_of_edge(e) != 2) continue;
    const auto [a, b] = g.edges[e];
    const std::uint32_t f0 = g.edge_faces[g.edge_face_begin[e]], f1 = g.edge_faces[g.edge_face_begin[e] + 1];
    if (runs_forward(f0, a, b) == runs_forward(f1, a, b)) seams.push_back(e);
  }
  return seams;
}

// The seam edges grouped into connected seams (joined through shared vertices).
std::vector<std::vector<std::size_t>> group_seams(const topology::MeshGraph& g, const std::vector<std::size_t>& seams,
                                                  std::size_t vertices) {
  topology::UnionFind uf(vertices);
  for (const std::size_t e : seams) uf.unite(g.edges[e].first, g.edges[e].second);
  std::vector<Index> group_of(vertices, Index(-1));
  std::vector<std::vector<std::size_t>> groups;
  for (const std::size_t e : seams) {
    Index& id = group_of[uf.find(g.edges[e].first)];
    if (id == Index(-1)) id = static_cast<Index>(groups.size()), groups.emplace_back();
    groups[id].push_back(e);
  }
  return groups;
}

// Shortest orientation-reversing loops through given faces, measured between face centroids
// on the orientation double cover of the dual graph: node 2f + s is face f on side s, and
// crossing a seam edge changes the side, so a path from (f, 0) to (f, 1) is a loop through f
// along which the orientation comes back reversed.
class ReversingLoops {
 public:
  ReversingLoops(const TriangleMesh& mesh, const topology::MeshGraph& g, const std::vector<std::size_t>& seams)
      : g_(g), centroid_(mesh.triangles.size()), is_seam_(g.edges.size(), 0),
        distance_(2 * mesh.triangles.size(), std::numeric_limits<double>::infinity()) {
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
      const auto& t = mesh.triangles[f];
      centroid_[f] = CGAL::centroid(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    }
    for (const std::size_t e : seams) is_seam_[e] = 1;
  }

  /// Length of the shortest reversing loop through face `start`; infinity when longer than
  /// `bound` (the search stops there).
  double through(std::uint32_t start, double bound) {
    for (const std::size_t node : touched_) distance_[node] = std::numeric_limits<double>::infinity();
    touched_.clear();
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    auto relax = [&](std::size_t node, double d) {
      if (d >= distance_[node] || d > bound) return;
      if (distance_[node] == std::numeric_limits<double>::infinity()) touched_.push_back(node);
      distance_[node] = d;
      queue.push({d, node});
    };
    relax(2 * std::size_t{start}, 0.0);
    while (!queue.empty()) {
      const auto [d, node] = queue.top();
      queue.pop();
      if (d > distance_[node]) continue;
      const auto f = static_cast<std::uint32_t>(node / 2);
      const std::size_t side = node % 2;
      if (f == start && side == 1) return d;
      for (const std::uint32_t e : g_.face_edges[f]) {
        if (g_.face_count_of_edge(e) != 2) continue;
        const std::uint32_t* faces = &g_.edge_faces[g_.edge_face_begin[e]];
        const std::uint32_t h = faces[0] == f ? faces[1] : faces[0];
        const std::size_t h_side = is_seam_[e] ? 1 - side : side;
        relax(2 * std::size_t{h} + h_side, d + std::sqrt(CGAL::squared_distance(centroid_[f], centroid_[h])));
      }
    }
    return std::numeric_limits<double>::infinity();
  }

 private:
  const topology::MeshGraph& g_;
  std::vector<Point3> centroid_;
  std::vector<char> is_seam_;
  std::vector<double> distance_;
  std::vector<std::size_t> touched_;
};

// Whether an orientation-reversing loop shorter than `bound` crosses the seam: tried from
// the faces of up to 8 of its edges spread along it.
bool has_short_reversing_loop(ReversingLoops& loops, const topology::MeshGraph& g,
                              const std::vector<std::size_t>& seam, double bound) {
  const std::size_t tries = std::min<std::size_t>(8, seam.size());
  for (std::size_t k = 0; k < tries; ++k) {
    const std::size_t e = seam[k * seam.size() / tries];
    if (loops.through(g.edge_faces[g.edge_face_begin[e]], bound) < bound) return true;
  }
  return false;
}

// Per face: whether its piece (faces joined through edges) has a border edge. A closed
// piece cannot be non-orientable and embedded in space, so a seam on it is always a defect.
std::vector<char> piece_has_border(const topology::MeshGraph& g) {
  std::vector<std::uint32_t> piece;
  const std::uint32_t pieces = topology::face_components(g, piece);
  std::vector<char> bordered(pieces, 0);
  for (std::size_t e = 0; e < g.edges.size(); ++e)
    if (g.face_count_of_edge(e) == 1) bordered[piece[g.edge_faces[g.edge_face_begin[e]]]] = 1;
  std::vector<char> has_border(piece.size());
  for (std::size_t f = 0; f < piece.size(); ++f) has_border[f] = bordered[piece[f]];
  return has_border;
}

// The vertices of the seams to cut: every seam, or (with a finite `max_twist_loop`) those
// crossed by a reversing loop shorter than it or lying on a closed piece, defects of the
// sheet; the others are twists of the surface itself (a Moebius strip's). Counts both.
struct SeamChoice {
  std::vector<Index> cut_vertices;
  std::size_t cut = 0, kept = 0;
};

SeamChoice choose_seams(const TriangleMesh& mesh, const topology::MeshGraph& g, double max_twist_loop) {
  SeamChoice choice;
  const std::vector<std::size_t> seams = seam_edges(mesh, g);
  if (seams.empty()) return choice;
  std::optional<ReversingLoops> loops;
  std::vector<char> has_border;
  if (std::isfinite(max_twist_loop)) loops.emplace(mesh, g, seams), has_border = piece_has_border(g);
  for (const std::vector<std::size_t>& seam : group_seams(g, seams, mesh.vertices.size())) {
    const bool on_closed_piece = loops && !has_border[g.edge_faces[g.edge_face_begin[seam.front()]]];
    if (loops && !on_closed_piece && !has_short_reversing_loop(*loops, g, seam, max_twist_loop)) {
      ++choice.kept;
      continue;
    }
    ++choice.cut;
    for (const std::size_t e : seam) choice.cut_vertices.push_back(g.edges[e].first), choice.cut_vertices.push_back(g.edges[e].second);
  }
  return choice;
}

}  // namespace

OrientableCutStats cut_to_orientable(TaggedMesh& tagged, double radius, double max_twist_loop, int max_rounds) {
  OrientableCutStats stats;
  for (int round = 0;; ++round) {
    TriangleMesh& mesh = tagged.mesh;
    topology::orient_faces(mesh);  // flips in place: face order, hence the tags, stay
    const topology::MeshGraph g = topology::build_mesh_graph(mesh.triangles, mesh.vertices.size());
    const SeamChoice choice = choose_seams(mesh, g, max_twist_loop);
    if (round == 0) stats.seams = choice.cut, stats.twists_kept = choice.kept;
    if (choice.cut == 0) break;
    if (round == max_rounds) {
      stats.still_non_orientable = true;
      break;
    }
    stats.faces_removed += remove_faces_near(tagged, g, choice.cut_vertices, radius);
  }
  return stats;
}

}  // namespace envcrust::extract
