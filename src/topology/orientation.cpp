// Orientability by breadth-first propagation of face signs across two-face edges.
#include "envcrust/mesh_graph.h"

#include <queue>

namespace envcrust::topology {
Orientation orient_components(const MeshGraph& g, const std::vector<std::uint32_t>& component,
                              std::size_t num_components, const std::vector<std::uint32_t>& first_faces) {
  Orientation out;
  out.face_sign.assign(g.faces.size(), 0);
  out.is_orientable.assign(num_components, true);
  std::queue<std::uint32_t> queue;
  auto grow = [&](std::uint32_t seed) {
    if (out.face_sign[seed] != 0) return;
    out.face_sign[seed] = 1;
    queue.push(seed);
    while (!queue.empty()) {
      const std::uint32_t f = queue.front();
      queue.pop();
      for (std::uint32_t e : g.face_edges[f]) {
        // Only two-face edges carry an orientation constraint; at a non-manifold edge the
        // mesh is not a surface there and orientability is judged on the rest.
        if (g.face_count_of_edge(e) != 2) continue;
        const std::uint32_t begin = g.edge_face_begin[e];
        const std::uint32_t other =
            g.edge_faces[begin] == f ? g.edge_faces[begin + 1] : g.edge_faces[begin];
        const auto [a, b] = g.edges[e];
        const int here = out.face_sign[f] * direction_along(g.faces[f], a, b);
        const int wanted = -here;  // neighbours must run the shared edge the other way
        const int there = direction_along(g.faces[other], a, b);
        if (out.face_sign[other] == 0) {
          out.face_sign[other] = static_cast<signed char>(wanted * there);
          queue.push(other);
        } else if (out.face_sign[other] * there != wanted) {
          out.is_orientable[component[f]] = false;
        }
      }
    }
  };
  for (const std::uint32_t f : first_faces)
    if (f < g.faces.size()) grow(f);
  for (std::uint32_t f = 0; f < g.faces.size(); ++f) grow(f);
  return out;
}

}  // namespace envcrust::topology
