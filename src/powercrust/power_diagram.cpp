// The power diagram of the weighted poles (regular triangulation) and its pole graph (METHOD 4.6).
#include "power_diagram.h"

#include <CGAL/Spatial_lock_grid_3.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace envcrust::powercrust {
namespace {

// Poles per block of the graph build: rows are gathered per block, then copied in place.
constexpr std::size_t kBlock = 4096;

struct GraphBlock {
  std::vector<Index> neighbours;
  std::vector<std::size_t> degree;
};

void gather_block(const PowerDiagram& diagram, std::size_t begin, std::size_t end, GraphBlock& block) {
  const Regular& rt = *diagram.rt;
  std::vector<Regular::Cell_handle> cells;
  std::vector<Index> row;
  block.degree.assign(end - begin, 0);
  for (std::size_t p = begin; p < end; ++p) {
    const RtVertex v = diagram.vertex_of_pole[p];
    if (v == RtVertex()) continue;  // hidden: no power cell, no neighbours
    cells.clear();
    rt.incident_cells_threadsafe(v, std::back_inserter(cells));
    row.clear();
    for (auto c : cells)
      for (int j = 0; j < 4; ++j) {
        const RtVertex w = c->vertex(j);
        if (w != v && !rt.is_infinite(w)) row.push_back(w->info());
      }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    block.degree[p - begin] = row.size();
    block.neighbours.insert(block.neighbours.end(), row.begin(), row.end());
  }
}

// A uniform number in [-1, 1) from a 64-bit key (splitmix64 finaliser).
double hashed_unit(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return 2.0 * (static_cast<double>(x >> 11) * 0x1.0p-53) - 1.0;
}

}  // namespace

Kernel::Weighted_point_3 power_site(const Pole& pole, Index id, double joggle) {
  const Point3& c = pole.center;
  const double amount = joggle * pole.radius;
  const std::uint64_t key = 3 * static_cast<std::uint64_t>(id);
  const Point3 moved = amount > 0 ? Point3(c.x() + amount * hashed_unit(key), c.y() + amount * hashed_unit(key + 1),
                                           c.z() + amount * hashed_unit(key + 2))
                                  : c;
  return {moved, pole.radius * pole.radius};
}

double intersection_weight(const Pole& p, const Pole& q) {
  const double den = 2.0 * p.radius * q.radius;
  if (den == 0) return -1.0;
  return (p.radius * p.radius + q.radius * q.radius - CGAL::squared_distance(p.center, q.center)) /
         den;
}

PowerDiagram build_power_diagram(std::vector<Pole>& poles, const CGAL::Bbox_3& lock_box, bool parallel,
                                 double joggle) {
  using Weighted = Kernel::Weighted_point_3;
  std::vector<std::pair<Weighted, Index>> input;
  input.reserve(poles.size());
  for (std::size_t i = 0; i < poles.size(); ++i)
    input.emplace_back(power_site(poles[i], static_cast<Index>(i), joggle), static_cast<Index>(i));
  PowerDiagram out;
  out.joggle = joggle;
  {
    Regular::Lock_data_structure lock(lock_box, 50);
    out.rt = std::make_unique<Regular>(Kernel(), parallel ? &lock : nullptr);
    out.rt->insert(input.begin(), input.end());
    out.rt->set_lock_data_structure(nullptr);
  }
  out.vertex_of_pole.assign(poles.size(), RtVertex());
  for (auto v : out.rt->finite_vertex_handles()) out.vertex_of_pole[v->info()] = v;
  for (std::size_t i = 0; i < poles.size(); ++i)
    poles[i].is_hidden = out.vertex_of_pole[i] == RtVertex();
  return out;
}

PoleGraph build_pole_graph(const PowerDiagram& diagram, const std::vector<Pole>& poles) {
  const std::size_t n = poles.size();
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<GraphBlock> parts(blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    gather_block(diagram, b * kBlock, std::min(n, (b + 1) * kBlock), parts[b]);
  });
  PoleGraph g;
  g.offsets.assign(n + 1, 0);
  std::vector<std::size_t> block_start(blocks + 1, 0);
  for (std::size_t b = 0; b < blocks; ++b) {
    for (std::size_t k = 0; k < parts[b].degree.size(); ++k)
      g.offsets[b * kBlock + k + 1] = g.offsets[b * kBlock + k] + parts[b].degree[k];
    block_start[b + 1] = block_start[b] + parts[b].neighbours.size();
  }
  g.neighbours.resize(g.offsets[n]);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    std::copy(parts[b].neighbours.begin(), parts[b].neighbours.end(),
              g.neighbours.begin() + static_cast<std::ptrdiff_t>(block_start[b]));
  });
  return g;
}

}  // namespace envcrust::powercrust
