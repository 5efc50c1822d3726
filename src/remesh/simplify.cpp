// simplify: check the mesh, cut it open along its seam, collapse by quadric error, weld back;
// again with the input held where the result passes through itself; undo on a topology change.
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"
#include "envcrust/remesh.h"
#include "envcrust/topology.h"
#include "collapse.h"
#include "fitness.h"
#include "seam.h"

#include <CGAL/exceptions.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

namespace envcrust::remesh {
namespace {

// The share of the cut mesh's edges to keep so that about `target` vertices are left (on a
// triangle mesh the edges are about three times the vertices, whatever their number).
double keep_fraction(const CutMesh& cut, std::size_t target) {
  return std::min(1.0, static_cast<double>(target) / static_cast<double>(std::max<std::size_t>(cut.mesh.vertices.size(), 1)));
}

// One simplification of the whole mesh, the vertices with held[v] kept in place.
TriangleMesh simplify_once(const TriangleMesh& mesh, std::size_t target, const std::vector<char>& held) {
  CutMesh cut = cut_along_seam(mesh);
  CollapseOptions o;
  o.order = CollapseOrder::LeastQuadricError;
  o.max_border_edge = std::numeric_limits<double>::infinity();  // the quadrics guard the border's shape
  o.keep_edge_fraction = keep_fraction(cut, target);
  // In one piece, on one core. In pieces (their shared vertices held, then the whole once
  // more from fresh quadrics) fandisk's sheet, 1.25M vertices to 30,000, crossed itself at
  // 42 pairs of faces where one piece crosses at none.
  o.faces_per_piece = std::numeric_limits<std::size_t>::max();
  collapse_cut_mesh(cut, o, held);
  return weld(cut.mesh, cut.weld_key);
}

// Holds the input's vertices within twice its longest edge of each face of `crossing` (faces
// of `simplified`). Returns how many were newly held.
std::size_t hold_around(const TriangleMesh& simplified, const std::vector<Index>& crossing,
                        const NearestIndex& input_vertices, std::vector<char>& held) {
  std::size_t added = 0;
  for (const Index f : crossing) {
    const auto& t = simplified.triangles[f];
    const Point3 &a = simplified.vertices[t[0]], &b = simplified.vertices[t[1]], &c = simplified.vertices[t[2]];
    const double longest = std::sqrt(std::max({CGAL::squared_distance(a, b), CGAL::squared_distance(b, c),
                                               CGAL::squared_distance(c, a)}));
    for (const std::size_t v : input_vertices.within(CGAL::centroid(a, b, c), 2.0 * longest))
      if (!held[v]) {
        held[v] = 1;
        ++added;
      }
  }
  return added;
}

}  // namespace

SimplifyResult simplify(const TriangleMesh& mesh, const SimplifyOptions& options) {
  if (options.target_vertices == 0) throw InvalidOptions("SimplifyOptions::target_vertices must be positive (got 0)");
  const auto t0 = std::chrono::steady_clock::now();
  SimplifyResult out;
  out.mesh = mesh;
  out.stats.vertices_before = out.stats.vertices_after = mesh.vertices.size();
  auto finish = [&](std::string warning) {
    if (!warning.empty()) out.warnings.push_back(std::move(warning));
    out.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  };
  if (mesh.vertices.size() <= options.target_vertices) return finish("");
  const auto before = topology::analyze_topology(mesh);
  if (const std::string why = unfit_reason(before); !why.empty()) return finish("simplification skipped: " + why);

  // A collapse can fold a thin part through its other side (the link condition and the
  // normal bound see only the edge's neighbourhood). Where the result passes through itself,
  // the input is held around the crossing faces and the whole simplified again; the input's
  // own crossings are allowed.
  TriangleMesh simplified;
  std::vector<char> held(mesh.vertices.size(), 0);
  std::optional<NearestIndex> input_vertices;
  std::optional<std::size_t> input_crossings;
  mesh::SelfIntersections crossings;
  try {
    for (int round = 0;; ++round) {
      simplified = simplify_once(mesh, options.target_vertices, held);
      crossings = mesh::self_intersections(simplified, 0);
      if (crossings.face_pairs == 0) break;
      if (!input_crossings) input_crossings = mesh::self_intersections(mesh, 0).face_pairs;
      if (crossings.face_pairs <= *input_crossings || round == kSimplifyRounds - 1) break;
      if (!input_vertices) input_vertices.emplace(mesh.vertices);
      if (hold_around(simplified, crossings.face_list, *input_vertices, held) == 0) break;
    }
  } catch (const NumericalFailure& e) {
    return finish(std::string("simplification skipped: ") + e.what());
  } catch (const CGAL::Failure_exception& e) {
    return finish("simplification skipped: CGAL failed (" + e.message() + ")");
  }
  if (input_crossings && crossings.face_pairs > *input_crossings)
    return finish("simplification undone: the simplified surface passed through itself at " +
                  std::to_string(crossings.face_pairs) + " pairs of faces, the input at " +
                  std::to_string(*input_crossings));
  if (const std::string change = topology_change(before, topology::analyze_topology(simplified)); !change.empty())
    return finish("simplification undone: " + change);
  out.mesh = std::move(simplified);
  out.stats.is_simplified = true;
  out.stats.vertices_after = out.mesh.vertices.size();
  out.stats.vertices_held = static_cast<std::size_t>(std::count(held.begin(), held.end(), char{1}));
  return finish("");
}

}  // namespace envcrust::remesh
