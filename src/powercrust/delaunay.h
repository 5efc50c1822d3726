// The Delaunay triangulation of the samples plus 8 bounding points, parallel, with ids as info.
#pragma once

#include "envcrust/types.h"

#include "compact_cell.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <array>
#include <memory>
#include <vector>

namespace envcrust::powercrust {

using DtVertexBase = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
using DtCellBase =
    CGAL::Delaunay_triangulation_cell_base_3<Kernel, CGAL::Triangulation_cell_base_3<Kernel, CompactCell<>>>;
using DtTds = CGAL::Triangulation_data_structure_3<DtVertexBase, DtCellBase, CGAL::Parallel_tag>;
/// Vertex info: sample id, or samples.size() + k for bounding corner k. Cells are CompactCell
/// (64 bytes, no info): a 1M-sample torus has 20M of them.
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, DtTds>;

/// The 8 corners of the cube centred at the samples' bbox midpoint with half-width
/// `scale` times the largest extent (docs/method.md §7.2).
std::array<Point3, 8> bounding_points(const std::vector<Point3>& samples, double scale);

/// Delaunay triangulation of samples and corners (range insertion, parallel when `parallel`).
/// The result holds no lock structure any more: it is meant to be read, from many threads.
std::unique_ptr<Delaunay> build_delaunay(const std::vector<Point3>& samples,
                                         const std::array<Point3, 8>& corners, bool parallel);

}  // namespace envcrust::powercrust
