// Delaunay triangulation of the envelope samples and selection of the shell-crossing edges.
#include "voronoi_sheet.h"

#include "envcrust/errors.h"
#include "envcrust/nearest_index.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/Hilbert_sort_3.h>
#include <CGAL/Hilbert_policy_tags.h>
#include <CGAL/property_map.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>
#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <numbers>
#include <optional>

namespace envcrust::extract {
namespace {

using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<Index, Kernel,
                                                     CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

constexpr Index kUnused = std::numeric_limits<Index>::max();
// |u . w| below this: a sample's offset direction u is square to the crease's bisector w, on
// neither side (a right-angled crease's samples read 0.71).
constexpr double kUndecidedSide = 0.1;

// The creases whose wedge is open at the scale of rho: a ball of radius 0.9 rho centred
// 2 rho along the wedge's bisector is clear of M (faces meeting at 54 degrees or more, with
// nothing else of M in between). The folded rim of a plate thinner than rho (an ear) is not
// such a crease: pairs across it join the plate's two sides, not the crease's.
std::vector<CreaseSegment> open_creases(const std::vector<CreaseSegment>& creases,
                                        const std::vector<envelope::EnvelopeSample>& samples,
                                        const NearestIndex& generators) {
  std::vector<char> keep(creases.size(), 0);
  tbb::parallel_for(std::size_t{0}, creases.size(), [&](std::size_t i) {
    const Point3 middle = CGAL::midpoint(creases[i].a, creases[i].b);
    const auto& nearest = samples[generators.nearest(middle).first];
    const double rho = std::sqrt(CGAL::squared_distance(nearest.position, nearest.generator));
    keep[i] = !generators.any_within(middle + 2.0 * rho * creases[i].wedge, 0.9 * rho);
  });
  std::vector<CreaseSegment> out;
  for (std::size_t i = 0; i < creases.size(); ++i)
    if (keep[i]) out.push_back(creases[i]);
  return out;
}

}  // namespace

RawSheet voronoi_sheet(const envelope::EnvelopeSamples& envelope, double min_angle_deg, const FoldPairs& folds) {
  const auto& samples = envelope.samples;
  if (samples.size() < 5) throw DegenerateInput("envelope has fewer than 5 samples");
  // Insert along a Hilbert curve, each point located from the previous one (what the range
  // constructor does, without its shuffle by CGAL's process-wide random generator).
  std::vector<Index> order(samples.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::vector<Point3> positions;
  positions.reserve(samples.size());
  for (const auto& s : samples) positions.push_back(s.position);
  using SortTraits = CGAL::Spatial_sort_traits_adapter_3<
      Kernel, CGAL::Pointer_property_map<Point3>::type>;
  const CGAL::Hilbert_sort_3<SortTraits, CGAL::Hilbert_sort_median_policy> hilbert(
      SortTraits(CGAL::make_property_map(positions)));
  hilbert(order.begin(), order.end());
  Delaunay dt;
  Delaunay::Vertex_handle hint;
  for (Index i : order) {
    hint = dt.insert(positions[i], hint == Delaunay::Vertex_handle() ? Delaunay::Cell_handle() : hint->cell());
    hint->info() = i;
  }
  if (dt.dimension() < 3) throw DegenerateInput("envelope samples are coplanar");

  // Everything below runs in an order fixed by the sample indices: CGAL's point location
  // walks at random, so the storage order of cells (and of edges) differs between calls.
  using CellKey = std::array<Index, 4>;
  auto key_of = [](Delaunay::Cell_handle c) {
    CellKey k{c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()};
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<CellKey> cell_keys;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) cell_keys.push_back(key_of(c));
  std::sort(cell_keys.begin(), cell_keys.end());
  const Index next_cell = static_cast<Index>(cell_keys.size());
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    c->info() = static_cast<Index>(std::lower_bound(cell_keys.begin(), cell_keys.end(), key_of(c)) - cell_keys.begin());
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c)
    if (dt.is_infinite(c)) c->info() = kUnused;

  const double max_dot = std::cos(min_angle_deg * std::numbers::pi / 180.0);
  // Fold pairs: a segment that passes through M where its two halves meet at a sharp angle
  // (points along it checked against the generators, which sample M). Per sample, the
  // largest u_p . u_q its fold pairs may have (-2: none).
  auto fold_dot = [](double angle_deg) { return angle_deg > 0 ? std::cos(angle_deg * std::numbers::pi / 180.0) : -2.0; };
  const double global_fold_dot = fold_dot(folds.min_angle_deg);
  const bool has_creases = folds.creases && !folds.creases->empty() && folds.crease_min_angle_deg > 0;
  std::vector<Point3> generators;
  if (global_fold_dot > -2.0 || has_creases) {
    generators.reserve(samples.size());
    for (const auto& s : samples) generators.push_back(s.generator);
  }
  const std::optional<NearestIndex> generator_index =
      generators.empty() ? std::nullopt : std::optional<NearestIndex>(std::in_place, generators);
  const envelope::CreaseDistance creases(has_creases ? open_creases(*folds.creases, samples, *generator_index)
                                                     : std::vector<CreaseSegment>{});
  std::vector<double> max_fold_dot(samples.size(), global_fold_dot);
  // Near a crease, the side of M each sample lies on: +1 in the wedge (its offset direction
  // into the wedge of the crease nearest its generator), -1 outside, 0 undecided (square to
  // the bisector). The nearest crease of a face's generator is one of that face's own, also
  // at a corner where three creases meet.
  std::vector<signed char> crease_side(samples.size(), 0);
  if (!creases.empty()) {
    const double crease_dot = fold_dot(folds.crease_min_angle_deg);
    tbb::parallel_for(std::size_t{0}, samples.size(), [&](std::size_t i) {
      const double rho = std::sqrt(CGAL::squared_distance(samples[i].position, samples[i].generator));
      if (!(creases(samples[i].generator) <= folds.crease_reach_rel_rho * rho)) return;
      max_fold_dot[i] = std::max(max_fold_dot[i], crease_dot);
      const double into = samples[i].direction * creases.nearest_wedge(samples[i].generator);
      crease_side[i] = into > kUndecidedSide ? 1 : into < -kUndecidedSide ? -1 : 0;
    });
  }
  const bool use_folds = std::any_of(max_fold_dot.begin(), max_fold_dot.end(), [](double d) { return d > -2.0; });
  auto is_fold_pair = [&](Index p, Index q, double dot) {
    if (!use_folds || dot > std::max(max_fold_dot[p], max_fold_dot[q])) return false;
    const double rho = std::sqrt(std::min(CGAL::squared_distance(samples[p].position, samples[p].generator),
                                          CGAL::squared_distance(samples[q].position, samples[q].generator)));
    const Point3& a = samples[p].position;
    const Point3& b = samples[q].position;
    constexpr int kSteps = 16;
    if (dot <= global_fold_dot) {
      for (int k = 1; k < kSteps; ++k) {
        const double t = static_cast<double>(k) / kSteps;
        if (generator_index->any_within(a + t * (b - a), folds.clearance_rel_rho * rho)) return true;
      }
      return false;
    }
    // A pair only a crease lets in must cross M by the crease: one end in the wedge, the
    // other outside, and its midpoint within crease_reach_rel_rho rho of the crease (in a
    // groove narrower than rho, pairs between the walls' sheets also cross M, but away from
    // the crease line). The fin of the envelope's inner medial axis joins two samples in the
    // wedge, and a pair round the convex side two outside (its segment passes through the
    // wedge, in through one face and out through the other). Unlike a test of the segment's
    // distance to the generators, this one needs no generators closer together than rho.
    if (crease_side[p] * crease_side[q] >= 0) return false;
    return creases(CGAL::midpoint(a, b)) <= folds.crease_reach_rel_rho * rho;
  };
  RawSheet sheet;
  struct CrossingEdge {
    std::pair<Index, Index> key;  // sample indices, smaller first
    std::vector<Index> cells;     // around the edge, turning positively about key.first -> key.second
    double dot = 0.0;
  };
  std::vector<CrossingEdge> crossing;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    ++sheet.delaunay_edges;
    const auto cell = e->first;
    const Index p = cell->vertex(e->second)->info();
    const Index q = cell->vertex(e->third)->info();
    const double dot = samples[p].direction * samples[q].direction;
    if (dot > max_dot && !is_fold_pair(p, q, dot)) continue;
    ++sheet.crossing_edges;
    CrossingEdge edge{std::minmax(p, q), {}, dot};
    bool bounded = true;
    auto circulator = dt.incident_cells(*e);
    const auto start = circulator;
    do {
      if (circulator->info() == kUnused) {
        bounded = false;
        break;
      }
      edge.cells.push_back(circulator->info());
    } while (++circulator != start);
    if (!bounded || edge.cells.size() < 3) continue;
    // The circulator turns about the edge as stored (p -> q): make it p < q, and start at the
    // smallest cell.
    if (p > q) std::reverse(edge.cells.begin(), edge.cells.end());
    std::rotate(edge.cells.begin(), std::min_element(edge.cells.begin(), edge.cells.end()), edge.cells.end());
    crossing.push_back(std::move(edge));
  }
  std::sort(crossing.begin(), crossing.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
  std::vector<Vector3> midpoint_sum(next_cell, Vector3(0, 0, 0));
  std::vector<std::uint32_t> midpoint_count(next_cell, 0);
  for (auto& edge : crossing) {
    const Vector3 mid = 0.5 * ((samples[edge.key.first].position - CGAL::ORIGIN) +
                               (samples[edge.key.second].position - CGAL::ORIGIN));
    for (Index c : edge.cells) {
      midpoint_sum[c] = midpoint_sum[c] + mid;
      ++midpoint_count[c];
    }
    sheet.polygons.push_back(std::move(edge.cells));
    sheet.polygon_dot.push_back(edge.dot);
  }
  // Compact: only cells on some polygon become vertices. Adjacent cells with the same
  // selected edges get the same position; they become one vertex (their Voronoi edge has
  // length zero), so that no face of the sheet has a zero-length side.
  std::vector<Index> vertex_of(next_cell, kUnused);
  std::map<Point3, Index> vertex_at;
  for (Index c = 0; c < next_cell; ++c) {
    if (midpoint_count[c] == 0) continue;
    const Point3 at = CGAL::ORIGIN + midpoint_sum[c] / static_cast<double>(midpoint_count[c]);
    const auto [it, is_new] = vertex_at.try_emplace(at, static_cast<Index>(sheet.vertices.size()));
    if (is_new) sheet.vertices.push_back(at);
    vertex_of[c] = it->second;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < sheet.polygons.size(); ++i) {
    auto& polygon = sheet.polygons[i];
    std::vector<Index> distinct;
    for (Index c : polygon)
      if (distinct.empty() || distinct.back() != vertex_of[c]) distinct.push_back(vertex_of[c]);
    while (distinct.size() > 1 && distinct.back() == distinct.front()) distinct.pop_back();
    if (distinct.size() < 3) continue;  // collapsed to an edge
    sheet.polygons[kept] = std::move(distinct);
    sheet.polygon_dot[kept] = sheet.polygon_dot[i];
    ++kept;
  }
  sheet.polygons.resize(kept);
  sheet.polygon_dot.resize(kept);
  return sheet;
}

}  // namespace envcrust::extract
