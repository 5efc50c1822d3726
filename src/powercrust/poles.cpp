// Voronoi vertices and poles of the samples, with welding and opposite-pole weights (docs/method.md §7.4).
#include "incident_cells.h"
#include "robust_centres.h"
#include "stages.h"

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>

namespace envcrust::powercrust {
namespace {

using Cell = Delaunay::Cell_handle;
constexpr std::size_t kGrain = 1024;
// Poles whose centres and radii agree to this fraction of the bbox diagonal are one ball.
constexpr double kWeldTolerance = 1e-11;

template <class F>
void parallel_indices(std::size_t n, F&& f) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
                    });
}

// Vertices by ascending id, so that the circumcentre's rounding does not depend on the
// order in which the (parallel) insertion left them in the cell.
std::array<Delaunay::Vertex_handle, 4> sorted_vertices(Cell c) {
  std::array<Delaunay::Vertex_handle, 4> v{c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
  std::sort(v.begin(), v.end(), [](auto a, auto b) { return a->info() < b->info(); });
  return v;
}

// The cell's circumcentre from its vertices in id order (the same bits whichever thread or
// vertex asks). Unweighted power vertex = circumcentre, with the exact fallback: a nearly
// flat cell of cospherical samples (grid rings) gives doubles a centre off by the sphere's
// radius.
Point3 circumcentre(Cell c) {
  const auto v = sorted_vertices(c);
  using Weighted = Kernel::Weighted_point_3;
  return power_vertex(Weighted(v[0]->point()), Weighted(v[1]->point()), Weighted(v[2]->point()),
                      Weighted(v[3]->point()));
}

// A cell's address as a key: it tells the cells apart after the triangulation is freed.
std::uintptr_t cell_address(Cell c) { return reinterpret_cast<std::uintptr_t>(c.operator->()); }

// The cells of p+ and p- of one sample (their addresses), with their circumcentres.
struct PoleChoice {
  std::array<std::uintptr_t, 2> cells;  ///< outer, inner
  std::array<Point3, 2> centres;
};

// Calls f(cell) for every finite cell, in parallel: a serial walk of the cell container hands
// out chunks to the threads (the container has no random access, and a vector of handles
// would take 128 MB for the 16M cells of a 1M-sample torus).
template <class F>
void parallel_for_each_finite_cell(const Delaunay& dt, F&& f) {
  constexpr std::size_t kChunk = 4096;
  using Chunk = std::vector<Cell>;
  auto it = dt.finite_cells_begin();
  const auto end = dt.finite_cells_end();
  tbb::parallel_pipeline(
      static_cast<std::size_t>(4 * tbb::this_task_arena::max_concurrency()),
      tbb::make_filter<void, std::shared_ptr<Chunk>>(tbb::filter_mode::serial_in_order,
                                                     [&](tbb::flow_control& control) -> std::shared_ptr<Chunk> {
                                                       if (it == end) {
                                                         control.stop();
                                                         return nullptr;
                                                       }
                                                       auto chunk = std::make_shared<Chunk>();
                                                       chunk->reserve(kChunk);
                                                       for (; it != end && chunk->size() < kChunk; ++it)
                                                         chunk->push_back(it);
                                                       return chunk;
                                                     }) &
          tbb::make_filter<std::shared_ptr<Chunk>, void>(tbb::filter_mode::parallel,
                                                         [&](const std::shared_ptr<Chunk>& chunk) {
                                                           for (Cell c : *chunk) f(c);
                                                         }));
}

// Sorted vertex ids: the last tie-break between cells, independent of memory addresses.
std::array<Index, 4> cell_key(Cell c) {
  const auto v = sorted_vertices(c);
  return {v[0]->info(), v[1]->info(), v[2]->info(), v[3]->info()};
}

// The best candidate cell of one sample so far and the value it is ranked by.
struct Candidate {
  double value = 0;
  Cell cell;
};

// Larger value wins; ties (cospherical inputs) go to the lexicographically smaller centre,
// then to the smaller vertex ids: the choice does not depend on the order cells are visited.
bool ranks_above(double value, const Point3& centre, Cell cell, const Candidate& best) {
  if (best.cell == Cell()) return true;
  if (value != best.value) return value > best.value;
  const Point3 best_centre = circumcentre(best.cell);  // exact ties only: rare
  if (centre != best_centre) return centre < best_centre;
  return cell_key(cell) < cell_key(best.cell);
}

// One spin lock per sample: two cells sharing a sample may be visited at once.
class SampleLocks {
 public:
  explicit SampleLocks(std::size_t n) : flags_(n) {}
  template <class F>
  void with(std::size_t i, F&& f) {
    while (flags_[i].exchange(true, std::memory_order_acquire)) {
    }
    f();
    flags_[i].store(false, std::memory_order_release);
  }

 private:
  std::vector<std::atomic<bool>> flags_;
};

// p+ and p- of every sample (docs/method.md §7.4), indexed by sample id, in two passes over the cells:
// p+ is the cell of largest circumradius among a sample's cells, p- the largest on the far
// side of p+. Each circumcentre is computed once per pass: storing them (24 bytes x 20 cells
// per sample on an exact torus) was the stage's peak memory, and collecting each sample's
// cells cost a hash-set walk per sample.
// With `nearest`, also each sample's distance to its nearest other sample (a Delaunay
// neighbour) in the same pass; with `lfs_lower` (and r < 1), each sample's lower bound on the
// local feature size from the Voronoi vertices near its tangent plane, in the second pass
// (PowerCrustOptions::sampling_estimate).
std::vector<PoleChoice> choose_poles(const Delaunay& dt, std::size_t n, std::vector<double>* nearest,
                                     double r = 1.0, std::vector<double>* lfs_lower = nullptr) {
  SampleLocks locks(n);
  std::vector<Candidate> outer(n);
  if (nearest) nearest->assign(n, std::numeric_limits<double>::infinity());
  parallel_for_each_finite_cell(dt, [&](Cell c) {
    const Point3 centre = circumcentre(c);
    for (int j = 0; j < 4; ++j) {
      const auto v = c->vertex(j);
      if (v->info() >= n) continue;  // a bounding corner
      const double d = CGAL::squared_distance(centre, v->point());
      double edge = std::numeric_limits<double>::infinity();
      if (nearest)
        for (int k = 0; k < 4; ++k)
          if (k != j && c->vertex(k)->info() < n)
            edge = std::min(edge, CGAL::squared_distance(v->point(), c->vertex(k)->point()));
      locks.with(v->info(), [&] {
        if (ranks_above(d, centre, c, outer[v->info()])) outer[v->info()] = {d, c};
        if (nearest) (*nearest)[v->info()] = std::min((*nearest)[v->info()], edge);
      });
    }
  });
  if (nearest)
    for (double& d : *nearest) d = std::sqrt(d);
  std::vector<PoleChoice> chosen(n);
  parallel_indices(n, [&](std::size_t i) {
    chosen[i].cells[0] = cell_address(outer[i].cell);
    chosen[i].centres[0] = circumcentre(outer[i].cell);
  });
  outer = {};
  std::vector<Candidate> inner(n), fallback(n);
  const bool bound_lfs = lfs_lower != nullptr && r < 1.0;
  if (bound_lfs) lfs_lower->assign(n, 0.0);
  const double cos_2r = std::cos(2.0 * r);
  parallel_for_each_finite_cell(dt, [&](Cell c) {
    const Point3 centre = circumcentre(c);
    for (int j = 0; j < 4; ++j) {
      const auto v = c->vertex(j);
      if (v->info() >= n) continue;
      const Point3& s = v->point();
      const Vector3 to_outer = chosen[v->info()].centres[0] - s;
      const double dot = (centre - s) * to_outer;
      const double d = CGAL::squared_distance(centre, s);
      // A Voronoi vertex near the tangent plane lies about lfs away at most: its distance and
      // angle bound lfs(s) from below for an r-sample.
      double bound = 0.0;
      if (bound_lfs && d > 0) {
        const double cosine = dot / std::sqrt(d * to_outer.squared_length());
        if (std::abs(cosine) < cos_2r) bound = std::sqrt(d) / r * (std::sqrt(1.0 - cosine * cosine) - r);
      }
      locks.with(v->info(), [&] {
        if (dot <= 0 && ranks_above(d, centre, c, inner[v->info()])) inner[v->info()] = {d, c};
        if (ranks_above(-dot, centre, c, fallback[v->info()])) fallback[v->info()] = {-dot, c};
        if (bound_lfs) (*lfs_lower)[v->info()] = std::max((*lfs_lower)[v->info()], bound);
      });
    }
  });
  parallel_indices(n, [&](std::size_t i) {
    // A bounded Voronoi cell always has a vertex on the far side of s; the fallback (the
    // most opposite one) only guards against rounding in the dot product.
    const Cell c = inner[i].cell != Cell() ? inner[i].cell : fallback[i].cell;
    chosen[i].cells[1] = cell_address(c);
    chosen[i].centres[1] = circumcentre(c);
  });
  return chosen;
}

// For each choice k = 2 j + side, the choice of sample order[j], the first choice of the same
// cell: poles are then numbered in that order (p+ before p-) whatever the cells' addresses.
std::vector<std::size_t> first_choice_of_cell(const std::vector<PoleChoice>& chosen,
                                              const std::vector<std::size_t>& order) {
  std::vector<std::pair<std::uintptr_t, std::size_t>> by_cell(2 * chosen.size());
  tbb::parallel_for(std::size_t{0}, chosen.size(), [&](std::size_t j) {
    for (int side = 0; side < 2; ++side) by_cell[2 * j + side] = {chosen[order[j]].cells[side], 2 * j + side};
  });
  tbb::parallel_sort(by_cell.begin(), by_cell.end());
  std::vector<std::size_t> first(by_cell.size());
  for (std::size_t k = 0; k < by_cell.size(); ++k)
    first[by_cell[k].second] = k > 0 && by_cell[k].first == by_cell[k - 1].first ? first[by_cell[k - 1].second]
                                                                                 : by_cell[k].second;
  return first;
}

double opposite_weight(const Point3& s, const Point3& outer, const Point3& inner) {
  const Vector3 a = outer - s, b = inner - s;
  const double den = std::sqrt(a.squared_length() * b.squared_length());
  if (den == 0) return 0.0;
  return std::clamp(-(a * b) / den, 0.0, 1.0);
}

// Merge poles whose balls agree within `tolerance` (centre and radius) into the one of
// lowest id; returns the old->new map. Cospherical samples give many cells with one centre,
// and a sphere's inner poles agree to rounding: as separate weighted points they would only
// feed the regular triangulation near-degenerate (exact, slow) predicates.
std::vector<Index> weld_poles(std::vector<Pole>& poles, double tolerance) {
  const std::size_t n = poles.size();
  // Cells of the tolerance grid, centred on 0 (where a sphere's inner poles gather); a cluster
  // of rounding-level differences straddles a cell border only by bad luck (~1e-4).
  using Key = std::array<long long, 4>;
  auto key = [&](const Pole& p) {
    return Key{std::llround(p.center.x() / tolerance), std::llround(p.center.y() / tolerance),
               std::llround(p.center.z() / tolerance), std::llround(p.radius / tolerance)};
  };
  std::vector<std::pair<Key, Index>> order(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { order[i] = {key(poles[i]), static_cast<Index>(i)}; });
  tbb::parallel_sort(order.begin(), order.end());
  std::vector<Index> root(n);
  for (std::size_t i = 0; i < n; ++i)
    root[order[i].second] = i > 0 && order[i].first == order[i - 1].first ? root[order[i - 1].second] : order[i].second;
  auto find = [&](Index v) { return root[v]; };
  std::vector<Index> remap(n);
  std::vector<Pole> kept;
  kept.reserve(n);
  for (std::size_t p = 0; p < n; ++p) {
    const Index first = find(static_cast<Index>(p));
    if (first == p) {
      remap[p] = static_cast<Index>(kept.size());
      kept.push_back(poles[p]);
    } else {
      remap[p] = remap[first];  // first < p: already placed
    }
  }
  poles = std::move(kept);
  return remap;
}

// Sample ids along a Hilbert curve (CGAL's spatial sort: deterministic for given points).
std::vector<std::size_t> spatial_order(const std::vector<Point3>& samples) {
  std::vector<std::size_t> order(samples.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using Map = CGAL::Pointer_property_map<Point3>::const_type;
  CGAL::spatial_sort(order.begin(), order.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, Map>(CGAL::make_property_map(samples)));
  return order;
}

// Every finite cell with its circumcentre and the pole it became (choice_pole as in
// compute_poles), for PowerCrustOptions::keep_delaunay_cells.
std::vector<DelaunayCell> delaunay_cells(const Delaunay& dt, const std::vector<PoleChoice>& chosen,
                                         const std::vector<std::size_t>& order,
                                         const std::vector<Index>& choice_pole) {
  std::vector<std::pair<std::uintptr_t, Index>> cell_pole(choice_pole.size());
  for (std::size_t k = 0; k < choice_pole.size(); ++k)
    cell_pole[k] = {chosen[order[k / 2]].cells[k % 2], choice_pole[k]};
  std::sort(cell_pole.begin(), cell_pole.end());
  std::vector<Cell> cells;
  cells.reserve(dt.number_of_finite_cells());
  for (Cell c : dt.finite_cell_handles()) cells.push_back(c);
  std::vector<DelaunayCell> out(cells.size());
  parallel_indices(cells.size(), [&](std::size_t k) {
    const auto v = sorted_vertices(cells[k]);
    DelaunayCell& c = out[k];
    for (int j = 0; j < 4; ++j) c.vertices[j] = v[j]->info();
    c.center = circumcentre(cells[k]);
    c.radius = std::sqrt(CGAL::squared_distance(c.center, v[0]->point()));
    const auto it = std::lower_bound(cell_pole.begin(), cell_pole.end(),
                                     std::pair<std::uintptr_t, Index>{cell_address(cells[k]), 0});
    c.pole = it != cell_pole.end() && it->first == cell_address(cells[k]) ? it->second : kNoPole;
  });
  return out;
}

// Per sample, the median of `nearest` over the sample and its Delaunay neighbours: a local
// spacing that one close pair (noise) or one lonely sample does not set alone.
std::vector<double> median_neighbour_spacing(const Delaunay& dt, const std::vector<double>& nearest) {
  const std::size_t n = nearest.size();
  std::vector<double> out(n, 0.0);
  std::vector<Delaunay::Vertex_handle> vertices;
  vertices.reserve(n);
  for (auto v : dt.finite_vertex_handles())
    if (v->info() < n) vertices.push_back(v);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      IncidentCells<Delaunay> incident;
                      std::vector<Index> ids;
                      std::vector<double> values;
                      for (std::size_t k = r.begin(); k != r.end(); ++k) {
                        const auto v = vertices[k];
                        ids.clear();
                        for (Cell c : incident(v))
                          for (int j = 0; j < 4; ++j)
                            if (!dt.is_infinite(c->vertex(j)) && c->vertex(j)->info() < n) ids.push_back(c->vertex(j)->info());
                        std::sort(ids.begin(), ids.end());
                        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());  // v itself included
                        values.clear();
                        for (Index id : ids) values.push_back(nearest[id]);
                        const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
                        std::nth_element(values.begin(), middle, values.end());
                        out[v->info()] = *middle;
                      }
                    });
  return out;
}

}  // namespace

PoleStage compute_poles(std::unique_ptr<Delaunay> dt, const std::vector<Point3>& samples, bool keep_cells,
                        bool local_spacing, double sampling_estimate) {
  const std::size_t n = samples.size();
  PoleStage out;
  out.finite_cells = dt->number_of_finite_cells();
  std::vector<double> nearest, lfs_lower;
  std::vector<PoleChoice> chosen =
      choose_poles(*dt, n, local_spacing ? &nearest : nullptr, sampling_estimate, &lfs_lower);
  std::vector<char> bad_inner;  // per sample: its second pole is nearer than the lfs bound
  if (!lfs_lower.empty()) {
    bad_inner.resize(n);
    parallel_indices(n, [&](std::size_t i) {
      bad_inner[i] = CGAL::squared_distance(chosen[i].centres[1], samples[i]) < CGAL::square(lfs_lower[i]);
    });
  }
  if (local_spacing) out.local_spacing = median_neighbour_spacing(*dt, nearest);
  // The triangulation is the largest object of the run: free it as soon as the poles are
  // chosen (the power diagram comes next, and the two are never held together, docs/method.md §7.10).
  // What follows needs the centres and the cells' addresses only.
  if (!keep_cells) dt.reset();
  const std::vector<std::size_t> order = spatial_order(samples);

  // One pole per chosen cell, numbered in the samples' spatial order (p+ before p-): poles
  // close in space get close ids, and the passes over the power diagram, which go by pole
  // id, then walk memory in order. choice_pole[2 j + side]: the pole of sample order[j].
  std::vector<Index> choice_pole(2 * n);
  std::size_t pole_count = 0;
  {
    const std::vector<std::size_t> first = first_choice_of_cell(chosen, order);
    for (std::size_t k = 0; k < 2 * n; ++k)
      choice_pole[k] = first[k] == k ? static_cast<Index>(pole_count++) : choice_pole[first[k]];  // first[k] < k
  }
  if (keep_cells) {
    out.cells = delaunay_cells(*dt, chosen, order, choice_pole);
    dt.reset();
  }

  out.poles.reserve(pole_count);
  out.sample_poles.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t i = order[j];
    for (int side = 0; side < 2; ++side) {
      if (choice_pole[2 * j + side] != out.poles.size()) continue;  // not its first choice
      Pole p;
      p.center = chosen[i].centres[side];
      p.radius = std::sqrt(CGAL::squared_distance(p.center, samples[i]));
      out.poles.push_back(p);
    }
    out.sample_poles[i] = {choice_pole[2 * j], choice_pole[2 * j + 1],
                           opposite_weight(samples[i], chosen[i].centres[0], chosen[i].centres[1])};
    if (!bad_inner.empty() && bad_inner[i]) out.sample_poles[i].is_paired = false;
  }
  chosen = {};
  const CGAL::Bbox_3 box = CGAL::bbox_3(samples.begin(), samples.end());
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const std::vector<Index> remap = weld_poles(out.poles, kWeldTolerance * diagonal);
  out.welded_poles = pole_count - out.poles.size();
  for (auto& sp : out.sample_poles) sp.outer = remap[sp.outer], sp.inner = remap[sp.inner];
  if (keep_cells) {
    for (auto& c : out.cells)
      if (c.pole != kNoPole) c.pole = remap[c.pole];
    tbb::parallel_sort(out.cells.begin(), out.cells.end(),
                       [](const DelaunayCell& a, const DelaunayCell& b) { return a.vertices < b.vertices; });
  }
  return out;
}

}  // namespace envcrust::powercrust
