// The power shape: regular-triangulation simplices whose vertices are all In poles (docs/method.md §7.8).
#include "incident_cells.h"
#include "stages.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace envcrust::powercrust {
namespace {

template <class T>
void sort_unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

template <std::size_t N>
std::array<Index, N> sorted(std::array<Index, N> a) {
  std::sort(a.begin(), a.end());
  return a;
}

struct Scratch {
  IncidentCells<Regular> incident;
  PowerShape pole;  ///< the simplices of one pole, before deduplication
};

// The simplices whose smallest vertex is the In pole p (so each is found by one pole only),
// sorted and without duplicates (a triangle is seen from its two cells, an edge from all of
// its cells: on an exact torus the duplicates took more memory than the live triangulation).
void collect(const PowerDiagram& diagram, const std::vector<Pole>& poles, Index p, PowerShape& shape,
             Scratch& scratch) {
  const Regular& rt = *diagram.rt;
  const RtVertex v = diagram.vertex_of_pole[p];
  auto inner = [&](RtVertex w) { return !rt.is_infinite(w) && poles[w->info()].label == PoleLabel::In; };
  auto& found = scratch.pole;
  found.edges.clear(), found.triangles.clear(), found.tetrahedra.clear();
  for (auto c : scratch.incident(v)) {
    bool all = true;
    for (int j = 0; j < 4; ++j) all = all && inner(c->vertex(j));
    if (all) {
      const auto t = sorted(std::array<Index, 4>{c->vertex(0)->info(), c->vertex(1)->info(),
                                                 c->vertex(2)->info(), c->vertex(3)->info()});
      if (t[0] == p) found.tetrahedra.push_back(t);
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
      if (all_inner && sorted(f)[0] == p) found.triangles.push_back(sorted(f));
    }
    for (int j = 0; j < 4; ++j)
      if (j != i && inner(c->vertex(j)) && c->vertex(j)->info() > p)
        found.edges.push_back({p, c->vertex(j)->info()});
  }
  sort_unique(found.edges);
  sort_unique(found.triangles);
  sort_unique(found.tetrahedra);
  shape.edges.insert(shape.edges.end(), found.edges.begin(), found.edges.end());
  shape.triangles.insert(shape.triangles.end(), found.triangles.begin(), found.triangles.end());
  shape.tetrahedra.insert(shape.tetrahedra.end(), found.tetrahedra.begin(), found.tetrahedra.end());
}

template <class T>
void append(std::vector<T>& to, std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
  from = {};
}

}  // namespace

PowerShape extract_power_shape(const PowerDiagram& diagram, const std::vector<Pole>& poles) {
  std::vector<Index> inner;
  for (std::size_t p = 0; p < poles.size(); ++p)
    if (poles[p].label == PoleLabel::In && !poles[p].is_hidden) inner.push_back(static_cast<Index>(p));
  // Blocks of consecutive poles, concatenated in order: the simplices come out sorted, as
  // each pole's are and each starts with its pole.
  constexpr std::size_t kBlock = 1024;
  std::vector<PowerShape> blocks((inner.size() + kBlock - 1) / kBlock);
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(std::size_t{0}, blocks.size(), [&](std::size_t b) {
    for (std::size_t i = b * kBlock; i < std::min(inner.size(), (b + 1) * kBlock); ++i)
      collect(diagram, poles, inner[i], blocks[b], scratch.local());
  });
  PowerShape shape;
  std::size_t sizes[3] = {0, 0, 0};
  for (const auto& b : blocks) sizes[0] += b.edges.size(), sizes[1] += b.triangles.size(), sizes[2] += b.tetrahedra.size();
  shape.edges.reserve(sizes[0]);
  shape.triangles.reserve(sizes[1]);
  shape.tetrahedra.reserve(sizes[2]);
  for (auto& b : blocks) {
    append(shape.edges, b.edges);
    append(shape.triangles, b.triangles);
    append(shape.tetrahedra, b.tetrahedra);
  }
  return shape;
}

}  // namespace envcrust::powercrust
