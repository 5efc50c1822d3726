// simplify: check the mesh, cut it open along its seam, collapse by quadric error in pieces
// and then whole, weld back, undo on a topology change.
#include "envcrust/errors.h"
#include "envcrust/remesh.h"
#include "envcrust/topology.h"
#include "collapse.h"
#include "fitness.h"
#include "seam.h"

#include <CGAL/exceptions.h>

#include <algorithm>
#include <chrono>
#include <limits>

namespace envcrust::remesh {
namespace {

// The share of the cut mesh's edges to keep so that about `target` vertices are left (on a
// triangle mesh the edges are about three times the vertices, whatever their number).
double keep_fraction(const CutMesh& cut, std::size_t target) {
  return std::min(1.0, static_cast<double>(target) / static_cast<double>(std::max<std::size_t>(cut.mesh.vertices.size(), 1)));
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

  TriangleMesh simplified;
  try {
    CutMesh cut = cut_along_seam(mesh);
    CollapseOptions o;
    o.order = CollapseOrder::LeastQuadricError;
    o.max_border_edge = std::numeric_limits<double>::infinity();  // the quadrics guard the border's shape
    o.keep_edge_fraction = keep_fraction(cut, options.target_vertices);
    // In one piece, on one core. In pieces (their shared vertices held, then the whole once
    // more from fresh quadrics) fandisk's sheet, 1.25M vertices to 30,000, crossed itself at
    // 42 pairs of faces where one piece crosses at none.
    o.faces_per_piece = std::numeric_limits<std::size_t>::max();
    collapse_cut_mesh(cut, o);
    simplified = weld(cut.mesh, cut.weld_key);
  } catch (const NumericalFailure& e) {
    return finish(std::string("simplification skipped: ") + e.what());
  } catch (const CGAL::Failure_exception& e) {
    return finish("simplification skipped: CGAL failed (" + e.message() + ")");
  }
  if (const std::string change = topology_change(before, topology::analyze_topology(simplified)); !change.empty())
    return finish("simplification undone: " + change);
  out.mesh = std::move(simplified);
  out.stats.is_simplified = true;
  out.stats.vertices_after = out.mesh.vertices.size();
  return finish("");
}

}  // namespace envcrust::remesh
