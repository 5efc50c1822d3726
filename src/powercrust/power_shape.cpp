// The power shape: regular-triangulation simplices whose vertices are all In poles (METHOD 4.9).
#include "stages.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>

namespace envcrust::powercrust {
namespace {

template <class T>
void sort_unique(std::vector<T>& v) {
  tbb::parallel_sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <std::size_t N>
std::array<Index, N> sorted(std::array<Index, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

// Simplices of the In pole p whose smallest vertex is p (so each is found by one pole only).
void collect(const PowerDiagram& diagram, const std::vector<Pole>& poles, Index p, PowerShape& shape,
             std::vector<Regular::Cell_handle>& cells) {
  const Regular& rt = *diagram.rt;
  const RtVertex v = diagram.vertex_of_pole[p];
  auto inner = [&](RtVertex w) { return !rt.is_infinite(w) && poles[w->info()].label == PoleLabel::In; };
  cells.clear();
  rt.incident_cells_threadsafe(v, std::back_inserter(cells));
  for (auto c : cells) {
    bool all = true;
    for (int j = 0; j < 4; ++j) all = all && inner(c->vertex(j));
    if (all) {
      const auto t = sorted(std::array<Index, 4>{c->vertex(0)->info(), c->vertex(1)->info(),
                                                 c->vertex(2)->info(), c->vertex(3)->info()});
      if (t[0] == p) shape.tetrahedra.push_back(t);
    }
    const int i = c->index(v);
    for (int skip = 0; skip < 4; ++skip) {  // the three facets of c that contain v
      if (skip == i) continue;
      std::array<Index, 3> f{};
      int k = 0;
      bool all_inner = true;
      for (int j = 0; j < 4; ++j) {
        if (j == skip) continue;
        all_inner = all_inner && inner(c->vertex(j));
        f[k++] = all_inner ? c->vertex(j)->info() : 0;
      }
      if (all_inner && sorted(f)[0] == p) shape.triangles.push_back(sorted(f));
    }
    for (int j = 0; j < 4; ++j)
      if (j != i && inner(c->vertex(j)) && c->vertex(j)->info() > p)
        shape.edges.push_back({p, c->vertex(j)->info()});
  }
}

}  // namespace

PowerShape extract_power_shape(const PowerDiagram& diagram, const std::vector<Pole>& poles) {
  std::vector<Index> inner;
  for (std::size_t p = 0; p < poles.size(); ++p)
    if (poles[p].label == PoleLabel::In && !poles[p].is_hidden) inner.push_back(static_cast<Index>(p));
  tbb::enumerable_thread_specific<PowerShape> parts;
  tbb::enumerable_thread_specific<std::vector<Regular::Cell_handle>> scratch;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, inner.size(), 256),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i != r.end(); ++i)
                        collect(diagram, poles, inner[i], parts.local(), scratch.local());
                    });
  PowerShape shape;
  for (const auto& part : parts) {
    shape.edges.insert(shape.edges.end(), part.edges.begin(), part.edges.end());
    shape.triangles.insert(shape.triangles.end(), part.triangles.begin(), part.triangles.end());
    shape.tetrahedra.insert(shape.tetrahedra.end(), part.tetrahedra.begin(), part.tetrahedra.end());
  }
  sort_unique(shape.edges);
  sort_unique(shape.triangles);
  sort_unique(shape.tetrahedra);
  return shape;
}

}  // namespace envcrust::powercrust
