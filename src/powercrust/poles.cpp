// Voronoi vertices and poles of the samples, with welding and opposite-pole weights (METHOD 4.4-4.5).
#include "robust_centres.h"
#include "stages.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

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

// Cell indices of p+ and p- of the sample at vertex v.
std::array<Index, 2> choose_poles(const Delaunay& dt, Delaunay::Vertex_handle v,
                                  const std::vector<Point3>& centres, std::vector<Cell>& buffer) {
  buffer.clear();
  dt.incident_cells_threadsafe(v, std::back_inserter(buffer));
  const Point3& s = v->point();
  // Ties (cospherical inputs) go to the lexicographically smaller centre: a choice that
  // does not depend on the circulation order.
  auto better = [&](Index a, double da, Index b, double db) {
    return b == kNoPole || da > db || (da == db && centres[a] < centres[b]);
  };
  Index outer = kNoPole;
  double outer_d = -1;
  for (Cell c : buffer) {
    if (dt.is_infinite(c)) continue;
    const Index k = c->info();
    const double d = CGAL::squared_distance(centres[k], s);
    if (better(k, d, outer, outer_d)) outer = k, outer_d = d;
  }
  const Vector3 to_outer = centres[outer] - s;
  Index inner = kNoPole, fallback = kNoPole;
  double inner_d = -1, fallback_dot = 0;
  for (Cell c : buffer) {
    if (dt.is_infinite(c)) continue;
    const Index k = c->info();
    const double dot = (centres[k] - s) * to_outer;
    const double d = CGAL::squared_distance(centres[k], s);
    if (dot <= 0 && better(k, d, inner, inner_d)) inner = k, inner_d = d;
    if (fallback == kNoPole || dot < fallback_dot) fallback = k, fallback_dot = dot;
  }
  // A bounded Voronoi cell always has a vertex on the far side of s; the fallback only
  // guards against rounding in the dot product.
  return {outer, inner != kNoPole ? inner : fallback};
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

}  // namespace

PoleStage compute_poles(Delaunay& dt, const std::vector<Point3>& samples, bool keep_cells) {
  const std::vector<Cell> cells = number_finite_cells(dt);
  std::vector<Point3> centres(cells.size());
  parallel_indices(cells.size(), [&](std::size_t k) {
    const auto v = sorted_vertices(cells[k]);
    // Unweighted power vertex = circumcentre, with the exact fallback: a nearly flat cell of
    // cospherical samples (grid rings) gives doubles a centre off by the sphere's radius.
    using Weighted = Kernel::Weighted_point_3;
    centres[k] = power_vertex(Weighted(v[0]->point()), Weighted(v[1]->point()), Weighted(v[2]->point()),
                              Weighted(v[3]->point()));
  });

  const std::size_t n = samples.size();
  std::vector<Delaunay::Vertex_handle> vertex_of_sample(n);
  for (auto v : dt.finite_vertex_handles())
    if (v->info() < n) vertex_of_sample[v->info()] = v;

  std::vector<std::array<Index, 2>> chosen(n);
  tbb::enumerable_thread_specific<std::vector<Cell>> buffers;
  parallel_indices(n, [&](std::size_t i) {
    chosen[i] = choose_poles(dt, vertex_of_sample[i], centres, buffers.local());
  });

  // One pole per chosen cell, numbered in sample order (p+ before p-).
  PoleStage out;
  out.finite_cells = cells.size();
  std::vector<Index> cell_pole(cells.size(), kNoPole);
  out.poles.reserve(2 * n);
  out.sample_poles.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Index ids[2];
    for (int side = 0; side < 2; ++side) {
      const Index k = chosen[i][side];
      if (cell_pole[k] == kNoPole) {
        cell_pole[k] = static_cast<Index>(out.poles.size());
        Pole p;
        p.center = centres[k];
        p.radius = std::sqrt(CGAL::squared_distance(centres[k], samples[i]));
        out.poles.push_back(p);
      }
      ids[side] = cell_pole[k];
    }
    out.sample_poles[i] = {ids[0], ids[1], opposite_weight(samples[i], centres[chosen[i][0]],
                                                            centres[chosen[i][1]])};
  }
  const std::size_t before = out.poles.size();
  const CGAL::Bbox_3 box = CGAL::bbox_3(samples.begin(), samples.end());
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  const std::vector<Index> remap = weld_poles(out.poles, kWeldTolerance * diagonal);
  out.welded_poles = before - out.poles.size();
  for (auto& sp : out.sample_poles) sp.outer = remap[sp.outer], sp.inner = remap[sp.inner];
  for (auto& cp : cell_pole)
    if (cp != kNoPole) cp = remap[cp];

  if (keep_cells) {
    out.cells.resize(cells.size());
    parallel_indices(cells.size(), [&](std::size_t k) {
      const auto v = sorted_vertices(cells[k]);
      DelaunayCell& c = out.cells[k];
      for (int j = 0; j < 4; ++j) c.vertices[j] = v[j]->info();
      c.center = centres[k];
      c.radius = std::sqrt(CGAL::squared_distance(centres[k], v[0]->point()));
      c.pole = cell_pole[k];
    });
    tbb::parallel_sort(out.cells.begin(), out.cells.end(),
                       [](const DelaunayCell& a, const DelaunayCell& b) { return a.vertices < b.vertices; });
  }
  return out;
}

}  // namespace envcrust::powercrust
