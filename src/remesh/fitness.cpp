// describe, unfit_reason and topology_change (fitness.h).
#include "fitness.h"

#include <sstream>

namespace envcrust::remesh {

std::string describe(const topology::MeshTopology& t) {
  std::ostringstream s;
  s << "chi " << t.euler_characteristic << ", " << t.components.size() << " component(s), "
    << t.boundary_loops.size() << " boundary loop(s), " << (t.is_orientable ? "orientable" : "non-orientable")
    << (t.is_manifold() ? "" : ", non-manifold");
  return s.str();
}

std::string unfit_reason(const topology::MeshTopology& t) {
  if (t.faces == 0) return "the mesh has no triangles";
  if (!t.is_manifold())
    return "the mesh is not a manifold (" + std::to_string(t.non_manifold_edges) + " non-manifold edges, " +
           std::to_string(t.non_manifold_vertices) + " non-manifold vertices)";
  if (t.degenerate_faces + t.duplicate_faces + t.welded_vertices > 0)
    return "the mesh has degenerate or duplicate faces or repeated vertices";
  return "";
}

std::string topology_change(const topology::MeshTopology& before, const topology::MeshTopology& after) {
  if (describe(after) == describe(before) && after.degenerate_faces == 0) return "";
  return "it changed the mesh from " + describe(before) + " to " + describe(after) +
         (after.degenerate_faces > 0 ? " with " + std::to_string(after.degenerate_faces) + " degenerate faces" : "");
}

}  // namespace envcrust::remesh
