// The power diagram of the weighted poles (regular triangulation) and its pole graph (docs/method.md §7.5).
#include "power_diagram.h"

#include "incident_cells.h"

#include <CGAL/Spatial_lock_grid_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace envcrust::powercrust {

static_assert(sizeof(Regular::Cell) == 72, "RtCellBase: CompactCell and an empty hidden-point container");
namespace {

// Poles per block of the graph build: rows are gathered per block, then copied in place.
constexpr std::size_t kBlock = 4096;

struct GraphBlock {
  std::vector<Index> neighbours;
  std::vector<std::size_t> degree;
};

// The hidden poles each visible pole covers (compressed rows).
struct CoveredLists {
  std::vector<std::size_t> offsets;
  std::vector<Index> poles;
};

CoveredLists covered_lists(const std::vector<Index>& cover) {
  CoveredLists c;
  c.offsets.assign(cover.size() + 1, 0);
  for (const Index q : cover)
    if (q != kNoPole) ++c.offsets[q + 1];
  for (std::size_t p = 0; p < cover.size(); ++p) c.offsets[p + 1] += c.offsets[p];
  c.poles.resize(c.offsets.back());
  std::vector<std::size_t> fill(c.offsets.begin(), c.offsets.end() - 1);
  for (std::size_t p = 0; p < cover.size(); ++p)
    if (cover[p] != kNoPole) c.poles[fill[cover[p]]++] = static_cast<Index>(p);
  return c;
}

void gather_block(const PowerDiagram& diagram, const std::vector<Index>& cover, const CoveredLists& covered,
                  std::size_t begin, std::size_t end, GraphBlock& block) {
  const Regular& rt = *diagram.rt;
  IncidentCells<Regular> incident;
  std::vector<Index> row;
  block.degree.assign(end - begin, 0);
  for (std::size_t p = begin; p < end; ++p) {
    row.clear();
    const RtVertex v = diagram.vertex_of_pole[p];
    if (v == RtVertex()) {  // hidden: no power cell; its one neighbour is the pole hiding it
      if (cover[p] != kNoPole) row.push_back(cover[p]);
    } else {
      for (auto c : incident(v))
        for (int j = 0; j < 4; ++j) {
          const RtVertex w = c->vertex(j);
          if (w != v && !rt.is_infinite(w)) row.push_back(w->info());
        }
      row.insert(row.end(), covered.poles.begin() + static_cast<std::ptrdiff_t>(covered.offsets[p]),
                 covered.poles.begin() + static_cast<std::ptrdiff_t>(covered.offsets[p + 1]));
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

Kernel::Weighted_point_3 PowerDiagram::site(const std::vector<Pole>& poles, Index id) const {
  const Pole& pole = poles[id];
  const Point3& c = pole.center;
  const double amount = offset.empty() ? 0.0 : offset[id];
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
                                 double joggle, const std::vector<bool>& skip) {
  PowerDiagram out;
  if (joggle > 0) {
    const double diagonal = std::sqrt(CGAL::square(lock_box.xmax() - lock_box.xmin()) +
                                      CGAL::square(lock_box.ymax() - lock_box.ymin()) +
                                      CGAL::square(lock_box.zmax() - lock_box.zmin()));
    out.offset.resize(poles.size());
    for (std::size_t i = 0; i < poles.size(); ++i)
      out.offset[i] = static_cast<float>(joggle * std::min(poles[i].radius, diagonal));
  }
  using Weighted = Kernel::Weighted_point_3;
  std::vector<std::pair<Weighted, Index>> input;
  input.reserve(poles.size());
  for (std::size_t i = 0; i < poles.size(); ++i)
    if (skip.empty() || !skip[i]) input.emplace_back(out.site(poles, static_cast<Index>(i)), static_cast<Index>(i));
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

std::vector<Index> covering_poles(const PowerDiagram& diagram, const std::vector<Pole>& poles) {
  // The nearest power vertex among the corners of the cell holding the site. CGAL's
  // nearest_power_vertex walks on to better neighbours: through the high-degree axis poles of
  // an exact torus that took 12 minutes at 100k samples. Sites are located in spatial order,
  // each walk starting at the previous cell.
  const Regular& rt = *diagram.rt;
  using Located = std::pair<Point3, Index>;
  std::vector<Located> hidden;
  for (std::size_t p = 0; p < poles.size(); ++p)
    if (poles[p].is_hidden) hidden.emplace_back(diagram.site(poles, static_cast<Index>(p)).point(), static_cast<Index>(p));
  CGAL::spatial_sort(hidden.begin(), hidden.end(),
                     CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::First_of_pair_property_map<Located>>());
  std::vector<Index> cover(poles.size(), kNoPole);
  Regular::Cell_handle cell;
  for (const auto& [point, p] : hidden) {
    cell = rt.locate(diagram.site(poles, p), cell);
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 4; ++j) {
      const RtVertex v = cell->vertex(j);
      if (rt.is_infinite(v)) continue;
      const auto& w = v->point();
      const double power = CGAL::squared_distance(point, w.point()) - w.weight();
      if (power < best) best = power, cover[p] = v->info();
    }
  }
  return cover;
}

PoleGraph build_pole_graph(const PowerDiagram& diagram, const std::vector<Pole>& poles) {
  const std::size_t n = poles.size();
  const std::vector<Index> cover = covering_poles(diagram, poles);
  const CoveredLists covered = covered_lists(cover);
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<GraphBlock> parts(blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    gather_block(diagram, cover, covered, b * kBlock, std::min(n, (b + 1) * kBlock), parts[b]);
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
