// isotropic_remesh: CGAL's isotropic remeshing on a Surface_mesh built from the mesh cut
// open along its seam (so a non-orientable mesh fits), welded back after.
#include "isotropic.h"

#include "collapse.h"
#include "seam.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace envcrust::remesh {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;

// The cut mesh as a Surface_mesh, its vertices and faces in spatial order (mesh.h; the
// remeshing walks neighbourhoods, and a round after the collapse gets the pieces' vertices
// concatenated). Seam vertices are marked and carry their weld key (other vertices, new ones
// included, have none).
struct Built {
  SurfaceMesh sm;
  SurfaceMesh::Property_map<SurfaceMesh::Vertex_index, bool> on_seam;
  SurfaceMesh::Property_map<SurfaceMesh::Vertex_index, Index> weld_key;
};

Built to_surface_mesh(const CutMesh& cut) {
  const mesh::SpatiallyOrdered ordered = mesh::order_spatially(cut.mesh);
  Built b{to_halfedge_mesh(ordered.mesh), {}, {}};
  b.on_seam = b.sm.add_property_map<SurfaceMesh::Vertex_index, bool>("v:envcrust_on_seam", false).first;
  b.weld_key = b.sm.add_property_map<SurfaceMesh::Vertex_index, Index>("v:envcrust_weld_key", kNoWeldKey).first;
  for (std::size_t v = 0; v < ordered.mesh.vertices.size(); ++v) {
    const Index old = ordered.old_vertex[v];
    if (cut.on_seam[old]) {
      const SurfaceMesh::Vertex_index vd(static_cast<SurfaceMesh::size_type>(v));
      b.on_seam[vd] = true;
      b.weld_key[vd] = cut.weld_key[old];
    }
  }
  return b;
}

// What one remeshing round does to the true border: as the BoundaryMode says, or nothing.
enum class Border { Resample, Keep, Fixed };

// The cut mesh with its edges shorter than 0.8 of the target collapsed (collapse.h), the
// border kept on its polyline or frozen as the mode says.
void collapse_short_edges(CutMesh& cut, double target_edge_length, Border border_mode) {
  CollapseOptions options;
  options.max_length = 0.8 * target_edge_length;
  options.max_border_edge = 4.0 / 3.0 * target_edge_length;
  options.border = border_mode == Border::Resample ? BorderCollapse::AlongBorder : BorderCollapse::Frozen;
  collapse_cut_mesh(cut, options);
}

// A remeshed mesh, welded, and its faces at the seam it was cut along (none for an empty
// seam).
struct Remeshed {
  TriangleMesh mesh;
  std::vector<std::uint32_t> seam_faces;
};

// Back to an indexed mesh without unused vertices, the two sides of the seam welded.
Remeshed to_triangle_mesh(const Built& b) {
  const SurfaceMesh& sm = b.sm;
  TriangleMesh out;
  std::vector<std::uint32_t> seam_faces;
  std::vector<Index> key;
  constexpr Index unused = std::numeric_limits<Index>::max();
  std::vector<Index> index(sm.num_vertices() + sm.number_of_removed_vertices(), unused);
  for (const auto f : sm.faces()) {
    std::array<Index, 3> tri{};
    std::size_t k = 0;
    for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (index[v] == unused) {
        index[v] = static_cast<Index>(out.vertices.size());
        out.vertices.push_back(sm.point(v));
        key.push_back(b.weld_key[v]);
      }
      if (b.on_seam[v] && (seam_faces.empty() || seam_faces.back() != out.triangles.size()))
        seam_faces.push_back(static_cast<std::uint32_t>(out.triangles.size()));
      if (k < 3) tri[k] = index[v];
      ++k;
    }
    if (k != 3) throw NumericalFailure("remeshing: CGAL returned a face with " + std::to_string(k) + " vertices");
    out.triangles.push_back(tri);
  }
  return {weld(out, key), std::move(seam_faces)};  // welding keeps the faces and their order
}

// Closest points on a triangle soup (the input mesh, which every round projects onto instead
// of onto its own input).
class SoupProjection {
 public:
  explicit SoupProjection(const TriangleMesh& mesh) {
    triangles_.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
      triangles_.emplace_back(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    tree_.insert(triangles_.begin(), triangles_.end());
    tree_.accelerate_distance_queries();
  }
  [[nodiscard]] Point3 closest_point(const Point3& p) const { return tree_.closest_point(p); }

 private:
  using Triangle = Kernel::Triangle_3;
  using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
  std::vector<Triangle> triangles_;
  CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>> tree_;
};

// One remeshing of the mesh cut open along the seam of a greedy orientation from first_faces.
// The seam stays as it is (only split to the target, the same on both sides): its vertices
// are constrained, so they neither move nor go, and its edges, no longer than the target and
// between fixed vertices, are neither split nor collapsed in either mode. Border::Fixed
// constrains the true border's vertices likewise (its edges, no longer than 4/3 of the target
// after a first round, stay as they are). The other modes first collapse the short edges
// (collapse.h), keeping the seam and the border as the mode says.
Remeshed remesh_cut_open(const TriangleMesh& mesh, const std::vector<std::uint32_t>& first_faces,
                         double target_edge_length,
                         unsigned int iterations, Border border_mode, const SoupProjection& projection) {
  CutMesh cut = cut_along_seam(mesh, first_faces);
  split_long_seam_edges(cut, target_edge_length);
  // Start near the target size: the sheet's median edge is about a third of the target, and
  // CGAL's remeshing rounds are slower at collapsing than its edge collapse (bunny sheet,
  // 1.8M faces: 24 s of collapsing in one piece + 8 s of remeshing, where remeshing alone
  // took 38 s; in 8 pieces on 2 cores the whole stage takes 20 s).
  // Remeshing then projects onto the input, not onto the collapsed mesh. (A later round,
  // Border::Fixed, starts from a remeshed mesh.)
  if (border_mode != Border::Fixed) collapse_short_edges(cut, target_edge_length, border_mode);
  Built b = to_surface_mesh(cut);
  SurfaceMesh& sm = b.sm;
  auto constrained = sm.add_property_map<SurfaceMesh::Vertex_index, bool>("v:envcrust_constrained", false).first;
  for (const auto v : sm.vertices()) constrained[v] = b.on_seam[v] || (border_mode == Border::Fixed && sm.is_border(v));
  const auto params = CGAL::parameters::number_of_iterations(iterations).vertex_is_constrained_map(constrained);
  auto project = [&](SurfaceMesh::Vertex_index v) { return projection.closest_point(sm.point(v)); };
  if (border_mode == Border::Keep) {
    // Protected edges must not exceed 4/3 of the target (CGAL's precondition). The seam's
    // sides are border edges of the cut mesh too, already short enough.
    const std::set<std::array<Index, 2>> seam(cut.seam_edges.begin(), cut.seam_edges.end());
    auto is_seam = [&](SurfaceMesh::Edge_index e) {
      const Index a = b.weld_key[sm.vertex(e, 0)], c = b.weld_key[sm.vertex(e, 1)];
      return a != kNoWeldKey && c != kNoWeldKey && seam.count({std::min(a, c), std::max(a, c)}) > 0;
    };
    std::vector<SurfaceMesh::Edge_index> border;
    for (const auto e : sm.edges())
      if (sm.is_border(e) && !is_seam(e)) border.push_back(e);
    PMP::split_long_edges(border, 4.0 / 3.0 * target_edge_length, sm);
    PMP::isotropic_remeshing(faces(sm), target_edge_length, sm,
                             params.protect_constraints(true).projection_functor(project));
  } else {
    // Border edges are constrained by default: split and collapsed along the border only, and
    // their vertices do not move (relax_constraints would cut the border's corners).
    PMP::isotropic_remeshing(faces(sm), target_edge_length, sm, params.projection_functor(project));
  }
  return to_triangle_mesh(b);
}

}  // namespace

double median_edge_length(const TriangleMesh& mesh) {
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i) edges.emplace_back(std::minmax(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<double> lengths;
  lengths.reserve(edges.size());
  for (const auto& [a, b] : edges)
    if (a != b) lengths.push_back(std::sqrt(CGAL::squared_distance(mesh.vertices[a], mesh.vertices[b])));
  if (lengths.empty()) return 0.0;
  auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

TriangleMesh isotropic_remesh(const TriangleMesh& mesh, double target_edge_length, int iterations,
                              BoundaryMode boundary) {
  const auto nb_iter = static_cast<unsigned int>(iterations);
  const SoupProjection onto_input(mesh);
  Remeshed first = remesh_cut_open(mesh, {}, target_edge_length, nb_iter,
                                   boundary == BoundaryMode::Keep ? Border::Keep : Border::Resample, onto_input);
  if (first.seam_faces.empty()) return std::move(first.mesh);
  // The seam kept the input's dense vertices, leaving thin triangles along it. A second
  // round, its search started at the first seam (in every piece that had one), cuts along a
  // seam half way round from it, through remeshed triangles, and
  // so remeshes the first seam's neighbourhood freely; the border, done, stays fixed, and
  // vertices are projected onto the input as in the first round.
  return remesh_cut_open(first.mesh, first.seam_faces, target_edge_length, nb_iter, Border::Fixed, onto_input)
      .mesh;
}

}  // namespace envcrust::remesh
