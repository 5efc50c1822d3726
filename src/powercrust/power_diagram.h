// The power diagram of the poles as a parallel regular triangulation, and its pole graph.
#pragma once

#include "envcrust/power_crust.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <memory>
#include <vector>

namespace envcrust::powercrust {

using RtVertexBase = CGAL::Triangulation_vertex_base_with_info_3<
    Index, Kernel, CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
// Discard_hidden_points: the default keeps a list of hidden points per cell, which costs
// memory we never use (hidden poles are found by their missing vertex).
using RtCellBase = CGAL::Regular_triangulation_cell_base_3<
    Kernel, CGAL::Triangulation_cell_base_3<Kernel>, CGAL::Discard_hidden_points>;
using RtTds = CGAL::Triangulation_data_structure_3<RtVertexBase, RtCellBase, CGAL::Parallel_tag>;
/// Vertex info: pole id.
using Regular = CGAL::Regular_triangulation_3<Kernel, RtTds>;
using RtVertex = Regular::Vertex_handle;

/// The regular triangulation of the weighted poles (centre, radius^2) and, per pole, its
/// vertex (null for a hidden pole).
struct PowerDiagram {
  std::unique_ptr<Regular> rt;
  std::vector<RtVertex> vertex_of_pole;
  double joggle = 0.0;  ///< the sites' offset bound relative to the radius (PowerCrustOptions)
};

/// The weighted point pole `id` is inserted as: its centre moved by a pseudo-random offset of
/// up to `joggle` x radius per coordinate (a hash of the id: the same bits every time), weight radius^2.
/// The poles themselves keep their exact centres.
Kernel::Weighted_point_3 power_site(const Pole& pole, Index id, double joggle);

/// Build the power diagram (parallel insertion when `parallel`, with a lock grid over
/// `lock_box`: the samples' box, where most poles are; far outer poles share border cells)
/// of the sites power_site(pole, id, joggle), and set Pole::is_hidden.
PowerDiagram build_power_diagram(std::vector<Pole>& poles, const CGAL::Bbox_3& lock_box, bool parallel,
                                 double joggle);

/// Adjacency of the poles through finite regular-triangulation edges (compressed rows). The
/// edge weight w_pq (intersection_weight) is computed when needed, not stored: at 1M samples
/// the stored doubles took 8 bytes x ~15 neighbours x 1M poles, next to the live regular
/// triangulation. Row order is arbitrary; every consumer combines rows with max, so it does
/// not matter.
struct PoleGraph {
  std::vector<std::size_t> offsets;  ///< poles + 1 entries
  std::vector<Index> neighbours;
};

/// The pole graph of the power diagram (parallel per pole).
PoleGraph build_pole_graph(const PowerDiagram& diagram, const std::vector<Pole>& poles);

/// w_pq = (r_p^2 + r_q^2 - |p-q|^2) / (2 r_p r_q), the cosine of the balls' intersection
/// angle, computed in a symmetric way (same bits for (p,q) and (q,p)).
double intersection_weight(const Pole& p, const Pole& q);

}  // namespace envcrust::powercrust
