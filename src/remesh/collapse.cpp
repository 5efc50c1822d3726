// collapse_edges: CGAL's edge collapse with length or quadric cost, the placement kept on the
// border and off fixed vertices, and a bound on the normal change; pieces of the mesh in
// parallel, merged at the vertices they share.
#include "collapse.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/mesh_graph.h"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_filter.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_ratio_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <boost/optional.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>

namespace envcrust::remesh {
namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using FixedMap = SurfaceMesh::Property_map<SurfaceMesh::Vertex_index, bool>;

// The border neighbours of border vertex v (the vertices before and after it along its
// border loop).
std::array<SurfaceMesh::Vertex_index, 2> border_neighbours(const SurfaceMesh& mesh, SurfaceMesh::Vertex_index v) {
  for (const auto h : CGAL::halfedges_around_target(v, mesh))
    if (mesh.is_border(h)) return {mesh.source(h), mesh.target(mesh.next(h))};
  return {v, v};
}

// How sharply the border turns at border vertex v: 1 - cos of the angle between its two
// border edges (0 straight on, 2 folded back).
double border_turn(const SurfaceMesh& mesh, SurfaceMesh::Vertex_index v) {
  const auto [before, after] = border_neighbours(mesh, v);
  const Vector3 in = mesh.point(v) - mesh.point(before), out = mesh.point(after) - mesh.point(v);
  const double norms = std::sqrt(in.squared_length() * out.squared_length());
  return norms > 0 ? 1.0 - in * out / norms : 0.0;
}

// The midpoint of an edge: where a shortest-first collapse puts it.
struct MidpointOf {
  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const {
    return CGAL::midpoint(profile.p0(), profile.p1());
  }
};

// Where an edge collapses to: the inner placement's point, inside; onto an endpoint at the border, so that
// every border vertex left stays where it was (on the border polyline): a border edge onto
// the endpoint where the border turns more, unless the border edge that replaces it would be
// longer than max_border_edge (remeshing splits border edges at their midpoints, which are
// not projected: a long chord would cut a curved border short); an edge with one border
// endpoint onto that one. Nowhere if an endpoint is fixed, or if both are on the border and
// the edge is not (collapsing that chord would pinch the surface), or (Frozen) if either is
// on the border.
template <typename InnerPlacement>
class BorderAwarePlacement {
 public:
  BorderAwarePlacement(InnerPlacement inner, FixedMap fixed, BorderCollapse border, double max_border_edge)
      : inner_(std::move(inner)), fixed_(fixed), border_(border), max_border_edge2_(max_border_edge * max_border_edge) {}

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const {
    const SurfaceMesh& mesh = profile.surface_mesh();
    const auto v0 = profile.v0(), v1 = profile.v1();
    if (fixed_[v0] || fixed_[v1]) return boost::none;
    const bool b0 = mesh.is_border(v0), b1 = mesh.is_border(v1);
    if (border_ == BorderCollapse::Frozen && (b0 || b1)) return boost::none;
    if (b0 && b1) {
      if (!(profile.is_v0_v1_a_border() || profile.is_v1_v0_a_border())) return boost::none;
      const bool keep0 = border_turn(mesh, v0) >= border_turn(mesh, v1);
      const auto kept = keep0 ? v0 : v1, gone = keep0 ? v1 : v0;
      const auto [before, after] = border_neighbours(mesh, gone);
      const auto far_side = before == kept ? after : before;
      if (CGAL::squared_distance(mesh.point(kept), mesh.point(far_side)) > max_border_edge2_) return boost::none;
      return mesh.point(kept);
    }
    if (b0) return profile.p0();
    if (b1) return profile.p1();
    return inner_(profile);
  }

 private:
  InnerPlacement inner_;
  FixedMap fixed_;
  BorderCollapse border_;
  double max_border_edge2_;
};

// Collapse one Surface_mesh in place (see collapse.h).
void collapse_in_place(SurfaceMesh& mesh, FixedMap fixed, const CollapseOptions& options) {
  // The normal check is a filter, run once per collapse; as a placement it would also run
  // each time a neighbour's cost is updated (measured: 37 s for the bunny's 1.8M faces).
  // Edges at fixed vertices are also marked constrained: CGAL collapses edges of length zero
  // without asking the placement, unless they are constrained.
  auto at_fixed = mesh.add_property_map<SurfaceMesh::Edge_index, bool>("e:envcrust_at_fixed", false).first;
  for (const auto e : mesh.edges()) at_fixed[e] = fixed[mesh.vertex(e, 0)] || fixed[mesh.vertex(e, 1)];
  if (options.order == CollapseOrder::ShortestFirst) {
    SMS::edge_collapse(mesh, SMS::Edge_length_stop_predicate<double>(options.max_length),
                       CGAL::parameters::get_cost(SMS::Edge_length_cost<SurfaceMesh>())
                           .get_placement(BorderAwarePlacement(MidpointOf{}, fixed, options.border,
                                                               options.max_border_edge))
                           .filter(SMS::Bounded_normal_change_filter<>())
                           .edge_is_constrained_map(at_fixed));
  } else {
    // The policies hold the vertices' quadrics; the cost evaluates them at whatever point the
    // placement chose, so a border endpoint is charged for the error it leaves.
    SMS::GarlandHeckbert_plane_policies<SurfaceMesh, Kernel> quadrics(mesh);
    SMS::edge_collapse(mesh, SMS::Count_ratio_stop_predicate<SurfaceMesh>(options.keep_edge_fraction),
                       CGAL::parameters::get_cost(quadrics.get_cost())
                           .get_placement(BorderAwarePlacement(quadrics.get_placement(), fixed, options.border,
                                                               options.max_border_edge))
                           .filter(SMS::Bounded_normal_change_filter<>())
                           .edge_is_constrained_map(at_fixed));
  }
  mesh.remove_property_map(at_fixed);
  mesh.collect_garbage();
}

// One piece of the mesh: its faces' vertices renumbered, and per local vertex the input one.
struct Piece {
  TriangleMesh mesh;
  std::vector<Index> input_vertex;
  std::vector<char> fixed;
};

// A vertex whose faces in the piece form several fans (the rest of its faces lie in other
// pieces: it is shared, hence fixed; common, e.g. ~50 per piece of a 28,800-face grid cut in
// 9) gets a copy per further fan, with the same input vertex, so that the piece is the
// manifold CGAL's edge collapse expects; the copies merge back with the other pieces'.
void split_fans(Piece& piece) {
  const auto graph = topology::build_mesh_graph(piece.mesh.triangles, piece.mesh.vertices.size());
  const auto fan = topology::corner_fans(graph);
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> first_fan(piece.mesh.vertices.size(), none);
  std::unordered_map<std::uint32_t, Index> copy_of_fan;
  for (std::uint32_t c = 0; c < fan.size(); ++c) {
    Index& v = piece.mesh.triangles[c / 3][c % 3];
    if (first_fan[v] == none) first_fan[v] = fan[c];
    if (first_fan[v] == fan[c]) continue;
    auto [it, is_new] = copy_of_fan.emplace(fan[c], static_cast<Index>(piece.mesh.vertices.size()));
    if (is_new) {
      piece.mesh.vertices.push_back(piece.mesh.vertices[v]);
      piece.input_vertex.push_back(piece.input_vertex[v]);
      piece.fixed.push_back(piece.fixed[v]);
    }
    v = it->second;
  }
}

}  // namespace

SurfaceMesh to_halfedge_mesh(const TriangleMesh& mesh) {
  SurfaceMesh sm;
  sm.reserve(mesh.vertices.size(), 3 * mesh.triangles.size() / 2, mesh.triangles.size());
  for (const auto& p : mesh.vertices) sm.add_vertex(p);
  for (const auto& t : mesh.triangles) {
    const auto f = sm.add_face(SurfaceMesh::Vertex_index(t[0]), SurfaceMesh::Vertex_index(t[1]),
                               SurfaceMesh::Vertex_index(t[2]));
    if (f == SurfaceMesh::null_face())
      throw NumericalFailure("remeshing: the faces cannot be oriented into a halfedge mesh");
  }
  // add_face refuses an edge used twice the same way; every vertex's circulator must also
  // reach all of its faces. That does not catch every pinched vertex (Surface_mesh links the
  // fans of one through their border halfedges, and they pass: seen on pieces before
  // split_fans), so callers hand in manifolds: remesh checks its input, pieces split their
  // fans. (CGAL's is_polygon_soup_a_polygon_mesh, which refuses pinched vertices, took 4.7 s
  // of the bunny's 1.8M faces; building the mesh with this check takes 0.33 s.)
  std::size_t corners = 0;
  for (const auto v : sm.vertices())
    if (sm.halfedge(v) != SurfaceMesh::null_halfedge())
      for (const auto f : CGAL::faces_around_target(sm.halfedge(v), sm))
        if (f != SurfaceMesh::null_face()) ++corners;
  if (corners != 3 * sm.number_of_faces())
    throw NumericalFailure("remeshing: the faces cannot be oriented into a halfedge mesh");
  return sm;
}

Collapsed collapse_edges(const TriangleMesh& mesh, const std::vector<char>& fixed, const CollapseOptions& options) {
  const mesh::SpatiallyOrdered ordered = mesh::order_spatially(mesh);
  const std::size_t face_count = ordered.mesh.triangles.size();
  const std::size_t piece_count =
      std::clamp<std::size_t>(face_count / std::max<std::size_t>(options.faces_per_piece, 1), 1, 64);
  // Faces in Hilbert order, cut into runs: piece k has faces [first_face(k), first_face(k + 1)).
  auto first_face = [&](std::size_t k) { return k * face_count / piece_count; };
  constexpr Index unset = std::numeric_limits<Index>::max();
  std::vector<Index> first_piece(ordered.mesh.vertices.size(), unset);
  std::vector<char> shared(ordered.mesh.vertices.size(), 0);
  for (std::size_t k = 0; k < piece_count; ++k)
    for (std::size_t f = first_face(k); f < first_face(k + 1); ++f)
      for (const Index v : ordered.mesh.triangles[f]) {
        if (first_piece[v] == unset) first_piece[v] = static_cast<Index>(k);
        else if (first_piece[v] != k) shared[v] = 1;
      }

  std::vector<Piece> pieces(piece_count);
  tbb::parallel_for(std::size_t{0}, piece_count, [&](std::size_t k) {
    Piece& piece = pieces[k];
    std::unordered_map<Index, Index> local;
    for (std::size_t f = first_face(k); f < first_face(k + 1); ++f) {
      std::array<Index, 3> tri{};
      for (int i = 0; i < 3; ++i) {
        const Index v = ordered.mesh.triangles[f][i];
        auto [it, is_new] = local.emplace(v, static_cast<Index>(piece.input_vertex.size()));
        if (is_new) {
          piece.input_vertex.push_back(v);
          piece.mesh.vertices.push_back(ordered.mesh.vertices[v]);
          piece.fixed.push_back(shared[v] || fixed[ordered.old_vertex[v]]);
        }
        tri[i] = it->second;
      }
      piece.mesh.triangles.push_back(tri);
    }
    split_fans(piece);
    SurfaceMesh sm = to_halfedge_mesh(piece.mesh);
    auto is_fixed = sm.add_property_map<SurfaceMesh::Vertex_index, bool>("v:envcrust_fixed", false).first;
    auto origin = sm.add_property_map<SurfaceMesh::Vertex_index, Index>("v:envcrust_origin", unset).first;
    for (const auto v : sm.vertices()) {
      is_fixed[v] = piece.fixed[v] != 0;
      if (piece.fixed[v]) origin[v] = piece.input_vertex[v];  // fixed vertices neither move nor go
    }
    collapse_in_place(sm, is_fixed, options);
    piece.mesh = {};
    piece.input_vertex.clear();
    for (const auto v : sm.vertices()) {
      piece.mesh.vertices.push_back(sm.point(v));
      piece.input_vertex.push_back(origin[v]);
    }
    for (const auto f : sm.faces()) {
      std::array<Index, 3> tri{};
      std::size_t i = 0;
      for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) tri[i++ % 3] = static_cast<Index>(v);
      piece.mesh.triangles.push_back(tri);
    }
  });

  // Merge: the shared (fixed) vertices once, in piece order; everything else as it is.
  Collapsed out;
  std::vector<Index> merged(ordered.mesh.vertices.size(), unset);
  for (const Piece& piece : pieces) {
    std::vector<Index> index(piece.mesh.vertices.size());
    for (std::size_t v = 0; v < index.size(); ++v) {
      const Index ordered_id = piece.input_vertex[v];
      if (ordered_id != unset && merged[ordered_id] != unset) {
        index[v] = merged[ordered_id];
        continue;
      }
      index[v] = static_cast<Index>(out.mesh.vertices.size());
      out.mesh.vertices.push_back(piece.mesh.vertices[v]);
      out.input_vertex.push_back(ordered_id == unset ? unset : ordered.old_vertex[ordered_id]);
      if (ordered_id != unset) merged[ordered_id] = index[v];
    }
    for (const auto& t : piece.mesh.triangles) out.mesh.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  }
  return out;
}

void collapse_cut_mesh(CutMesh& cut, const CollapseOptions& options, const std::vector<char>& held) {
  std::vector<char> fixed(cut.on_seam.begin(), cut.on_seam.end());
  for (std::size_t v = 0; v < std::min(held.size(), fixed.size()); ++v) fixed[v] = fixed[v] || held[v];
  Collapsed collapsed = collapse_edges(cut.mesh, fixed, options);
  std::vector<bool> on_seam(collapsed.mesh.vertices.size(), false);
  std::vector<Index> weld_key(collapsed.mesh.vertices.size(), kNoWeldKey);
  for (std::size_t v = 0; v < on_seam.size(); ++v) {
    const Index input = collapsed.input_vertex[v];
    if (input != std::numeric_limits<Index>::max() && cut.on_seam[input]) {
      on_seam[v] = true;
      weld_key[v] = cut.weld_key[input];
    }
  }
  cut.mesh = std::move(collapsed.mesh);
  cut.on_seam = std::move(on_seam);
  cut.weld_key = std::move(weld_key);
}

}  // namespace envcrust::remesh
