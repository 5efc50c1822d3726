// CGAL's advancing front with a priority that refuses the candidates off the sheet, and the
// long ones. The front
// asks for a facet's priority many times over (about 30 calls per output face), so each
// facet's verdict is kept.
#include "interpolate_detail.h"

#include "envcrust/mesh.h"

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_data_structure_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>

namespace envcrust::interpolate::detail {
namespace {

// A Delaunay cell that keeps the guide's verdict on each of its four facets (-1: not asked
// yet), so that the front's repeated questions cost an array read. A hash map keyed by the
// facets' vertices did the same and took 8.6% of a head run's CPU (30k samples).
template <typename GT, typename Cb = CGAL::Delaunay_triangulation_cell_base_3<GT>>
class VerdictCellBase : public Cb {
 public:
  template <typename TDS2>
  struct Rebind_TDS {
    using Other = VerdictCellBase<GT, typename Cb::template Rebind_TDS<TDS2>::Other>;
  };
  using Cb::Cb;
  std::array<std::int8_t, 4> verdict{{-1, -1, -1, -1}};
};

// The priority functor: CGAL's own (the smallest Delaunay sphere through the facet) for the
// facets the guide allows, infinity (never added) for the others.
class GuidedPriority {
 public:
  GuidedPriority(const std::vector<double>& spacing, const SheetGuide& guide, const InterpolateOptions& options,
                 std::size_t& refused)
      : spacing_(&spacing), guide_(&guide), options_(options), refused_(&refused) {}

  template <typename AdvancingFront, typename CellHandle>
  double operator()(const AdvancingFront& front, CellHandle& cell, const int& index) const {
    if (cell->verdict[index] < 0) {
      std::array<Point3, 3> points;
      double scale = 0;
      for (int i = 0; i < 3; ++i) {
        const auto v = cell->vertex((index + 1 + i) & 3);
        points[i] = v->point();
        scale = std::max(scale, spacing_at(v));
      }
      const double longest = std::sqrt(std::max({CGAL::squared_distance(points[0], points[1]),
                                                 CGAL::squared_distance(points[1], points[2]),
                                                 CGAL::squared_distance(points[2], points[0])}));
      const bool allowed = longest <= kMaxEdgeRelSpacing * scale &&
                           guide_->allows(points[0], points[1], points[2],
                                          options_.max_sheet_distance_rel_spacing * scale, options_.min_normal_cosine);
      if (!allowed) ++*refused_;
      // The same facet seen from the neighbouring cell.
      const auto other = cell->neighbor(index);
      cell->verdict[index] = other->verdict[other->index(cell)] = allowed ? 1 : 0;
    }
    if (cell->verdict[index] == 0) return std::numeric_limits<double>::infinity();
    return front.smallest_radius_delaunay_sphere(cell, index);
  }

 private:
  // The vertex's sample: CGAL's function numbers the points in input order (Vertex::id()).
  template <typename VertexHandle>
  double spacing_at(const VertexHandle& v) const {
    const auto id = static_cast<std::size_t>(v->id());
    return id < spacing_->size() ? (*spacing_)[id] : 0.0;
  }

  const std::vector<double>* spacing_;
  const SheetGuide* guide_;
  InterpolateOptions options_;
  std::size_t* refused_;
};

}  // namespace

std::vector<std::array<Index, 3>> guided_front(const std::vector<Point3>& samples,
                                               const std::vector<double>& spacing, const SheetGuide& guide,
                                               const InterpolateOptions& options, std::size_t& refused) {
  using Vb = CGAL::Advancing_front_surface_reconstruction_vertex_base_3<Kernel>;
  using Cb = CGAL::Advancing_front_surface_reconstruction_cell_base_3<Kernel, VerdictCellBase<Kernel>>;
  using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vb, Cb>>;
  // Inserted along a Hilbert curve, each point located from the previous one: CGAL's range
  // insertion shuffles first with its process-wide generator, seeded by the clock, and on
  // cospherical samples (a grid) the triangulation, so the output, changed from run to run.
  Delaunay dt;
  Delaunay::Vertex_handle hint;
  for (const std::size_t i : mesh::hilbert_order(samples)) {
    const std::size_t before = dt.number_of_vertices();
    hint = dt.insert(samples[i], hint == Delaunay::Vertex_handle() ? Delaunay::Cell_handle() : hint->cell());
    if (dt.number_of_vertices() > before) hint->id() = i;  // a repeated point keeps its first index
  }
  CGAL::Advancing_front_surface_reconstruction<Delaunay, GuidedPriority> front(
      dt, GuidedPriority(spacing, guide, options, refused));
  front.run();
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::write_triple_indices(std::back_inserter(facets), front);
  std::vector<std::array<Index, 3>> faces;
  faces.reserve(facets.size());
  for (const auto& f : facets)
    faces.push_back({static_cast<Index>(f[0]), static_cast<Index>(f[1]), static_cast<Index>(f[2])});
  return faces;
}

}  // namespace envcrust::interpolate::detail
