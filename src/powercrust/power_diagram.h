// The power diagram of the poles as a parallel regular triangulation, and its pole graph.
#pragma once

#include "compact_cell.h"

#include "envcrust/power_crust.h"

#include <CGAL/Bbox_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Regular_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <memory>
#include <vector>

namespace envcrust::powercrust {

using RtVertexBase = CGAL::Triangulation_vertex_base_with_info_3<
    Index, Kernel, CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
/// The hidden-point container of a cell that keeps none: with Discard_hidden_points CGAL's
/// cell base only asks it for an (empty) end(), yet its default std::list takes 24 bytes per
/// cell. Hidden poles are found by their missing vertex instead.
struct NoHiddenPoints {
  using iterator = Kernel::Weighted_point_3*;
  using const_iterator = const Kernel::Weighted_point_3*;
  iterator end() { return nullptr; }
  const_iterator end() const { return nullptr; }
};
/// 72 bytes: CompactCell (64) and the empty container (was 96 with CGAL's cell and list).
using RtCellBase = CGAL::Regular_triangulation_cell_base_3<
    Kernel, CGAL::Triangulation_cell_base_3<Kernel, CompactCell<>>, CGAL::Discard_hidden_points, NoHiddenPoints>;
using RtTds = CGAL::Triangulation_data_structure_3<RtVertexBase, RtCellBase, CGAL::Parallel_tag>;
/// Vertex info: pole id.
using Regular = CGAL::Regular_triangulation_3<Kernel, RtTds>;
using RtVertex = Regular::Vertex_handle;

/// The regular triangulation of the weighted poles and, per pole, its vertex (null for a
/// hidden pole).
struct PowerDiagram {
  std::unique_ptr<Regular> rt;
  std::vector<RtVertex> vertex_of_pole;
  /// Per pole, the bound of its site's offset (empty: no joggle).
  std::vector<float> offset;

  /// The weighted point pole `id` is inserted as: its centre moved by a pseudo-random offset
  /// of up to offset[id] per coordinate (a hash of the id: the same bits every time), weight
  /// radius^2. The poles themselves keep their exact centres.
  [[nodiscard]] Kernel::Weighted_point_3 site(const std::vector<Pole>& poles, Index id) const;
};

/// Build the power diagram (parallel insertion when `parallel`, with a lock grid over
/// `lock_box`: the samples' box, where most poles are; far outer poles share border cells)
/// and set Pole::is_hidden. With joggle > 0 each site moves by up to joggle times the smaller
/// of its radius and the box diagonal per coordinate (the radius alone would move the far
/// outer poles of a convex surface, and the crust with them, by a fraction of the box).
/// Poles marked in `skip` (empty: none) are not inserted and come out hidden.
PowerDiagram build_power_diagram(std::vector<Pole>& poles, const CGAL::Bbox_3& lock_box, bool parallel,
                                 double joggle, const std::vector<bool>& skip = {});

/// For each hidden pole, the visible pole whose power cell holds its (moved) centre: the ball
/// that hides it, whose label it shares. kNoPole for visible poles.
std::vector<Index> covering_poles(const PowerDiagram& diagram, const std::vector<Pole>& poles);

/// Adjacency of the poles through finite regular-triangulation edges, and between each hidden
/// pole and the pole that hides it (covering_poles: its ball lies deep in that pole's, so the
/// labeling reaches it and passes its evidence on), in compressed rows. The
/// edge weight w_pq (intersection_weight) is computed when needed, not stored: at 1M samples
/// the stored doubles took 8 bytes x ~15 neighbours x 1M poles, next to the live regular
/// triangulation. Row order is arbitrary; every consumer combines rows with max, so it does
/// not matter.
struct PoleGraph {
  std::vector<std::size_t> offsets;  ///< poles + 1 entries
  std::vector<Index> neighbours;
};

/// The pole graph of the power diagram (parallel per pole, after locating the hidden poles).
PoleGraph build_pole_graph(const PowerDiagram& diagram, const std::vector<Pole>& poles);

/// w_pq = (r_p^2 + r_q^2 - |p-q|^2) / (2 r_p r_q), the cosine of the balls' intersection
/// angle, computed in a symmetric way (same bits for (p,q) and (q,p)).
double intersection_weight(const Pole& p, const Pole& q);

}  // namespace envcrust::powercrust
