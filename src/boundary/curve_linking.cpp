// Linking boundary candidates into components and ordering each along its MST diameter path,
// refined by binning all of the component's points along that path.
#include "boundary_detail.h"

#include "envcrust/mesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <map>
#include <optional>
#include <limits>
#include <numeric>
#include <tuple>

namespace envcrust::boundary::detail {
namespace {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  }
  bool unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (b < a) std::swap(a, b);
    parent[b] = a;
    return true;
  }
};

/// Tree distances from `start` over the MST adjacency; returns the farthest vertex and fills
/// the parent array.
std::size_t farthest(const std::vector<std::vector<std::pair<std::size_t, double>>>& adj,
                     std::size_t start, std::vector<std::size_t>& parent) {
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<double> dist(adj.size(), -1.0);
  parent.assign(adj.size(), none);
  std::vector<std::size_t> stack{start};
  dist[start] = 0;
  std::size_t best = start;
  while (!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    if (dist[v] > dist[best] || (dist[v] == dist[best] && v < best)) best = v;
    for (const auto& [w, len] : adj[v]) {
      if (dist[w] >= 0) continue;
      dist[w] = dist[v] + len;
      parent[w] = v;
      stack.push_back(w);
    }
  }
  return best;
}

// Removes one edge (a, b) from an adjacency list graph.
void erase_edge(std::vector<std::vector<std::size_t>>& adj, std::size_t a, std::size_t b) {
  adj[a].erase(std::find(adj[a].begin(), adj[a].end(), b));
  adj[b].erase(std::find(adj[b].begin(), adj[b].end(), a));
}

}  // namespace

LocalSpacings local_spacings(const std::vector<Point3>& points, const NeighbourTable& table, std::size_t neighbors) {
  constexpr std::size_t kSpacingNeighbours = 6;
  const std::size_t n = points.size();
  LocalSpacings out;
  out.own.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0.0;
    for (const std::uint32_t j : table.of(i).first(std::min<std::size_t>(kSpacingNeighbours, table.k())))
      sum += std::sqrt(CGAL::squared_distance(points[i], points[j]));
    out.own[i] = sum / static_cast<double>(kSpacingNeighbours + 1);
  }
  out.around.assign(n, 0.0);
  std::vector<double> near;
  for (std::size_t i = 0; i < n; ++i) {
    near.assign(1, out.own[i]);
    for (const std::uint32_t j : table.of(i).first(std::min<std::size_t>(neighbors, table.k()))) near.push_back(out.own[j]);
    const auto mid = near.begin() + static_cast<std::ptrdiff_t>(near.size() / 2);
    std::nth_element(near.begin(), mid, near.end());
    out.around[i] = *mid;
  }
  return out;
}

LinkReach local_link_reach(const LocalSpacings& spacings, double link_distance, double spacing) {
  std::vector<double> reach(spacings.around.size());
  // The local spacing where it exceeds the average by half or more, the average below a
  // third more, in between a ramp joining them: a part sampled as densely as the average (the
  // local spacing scatters by about 10% around it, and reads up to 20% more along a rim)
  // links as far as the average spacing says.
  for (std::size_t i = 0; i < reach.size(); ++i) {
    const double around = spacings.around[i];
    reach[i] = link_distance * std::max(spacing, std::min(around, 3.0 * (around - spacing)));
  }
  return LinkReach(std::move(reach));
}

std::vector<std::vector<std::size_t>> candidate_links(const FlaggedSubset& subset, const Candidates& candidates,
                                                      const LinkReach& reach, double min_dot) {
  const auto& [ids, flagged_points] = subset;
  const PointIndex index(flagged_points);
  std::vector<std::vector<std::size_t>> links(ids.size());
  // Each pair is found from the end with the longer reach; with one reach for all, from both
  // ends, and taken from the lower.
  for (std::size_t a = 0; a < ids.size(); ++a) {
    for (const std::size_t b : index.within(flagged_points[a], reach(ids[a]))) {
      if (b == a || (reach.is_uniform() && b < a)) continue;
      if (dot(candidates.conormals[ids[a]], candidates.conormals[ids[b]]) <= min_dot) continue;
      links[a].push_back(b);
      links[b].push_back(a);
    }
  }
  for (auto& list : links) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return links;
}

std::vector<std::vector<std::size_t>> link_candidates(const std::vector<Point3>& points,
                                                      const Candidates& candidates,
                                                      const LinkReach& reach, double min_dot) {
  const FlaggedSubset subset = flagged_subset(points, candidates);
  const auto& ids = subset.ids;
  const auto links = candidate_links(subset, candidates, reach, min_dot);
  UnionFind sets(ids.size());
  for (std::size_t a = 0; a < ids.size(); ++a)
    for (const std::size_t b : links[a]) sets.unite(a, b);
  std::vector<std::vector<std::size_t>> components;
  std::vector<std::size_t> slot(ids.size(), std::numeric_limits<std::size_t>::max());
  for (std::size_t a = 0; a < ids.size(); ++a) {
    const std::size_t root = sets.find(a);
    if (slot[root] == std::numeric_limits<std::size_t>::max()) {
      slot[root] = components.size();
      components.emplace_back();
    }
    components[slot[root]].push_back(ids[a]);
  }
  return components;
}

std::vector<std::vector<std::size_t>> nn_crust_edges(const std::vector<Point3>& points) {
  const std::size_t n = points.size();
  std::vector<std::vector<std::size_t>> adj(n);
  if (n < 2) return adj;
  const PointIndex index(points);
  auto join = [&adj](std::size_t a, std::size_t b) {
    if (std::find(adj[a].begin(), adj[a].end(), b) == adj[a].end()) {
      adj[a].push_back(b);
      adj[b].push_back(a);
    }
  };
  for (std::size_t a = 0; a < n; ++a) {
    // Grow the query until a point on the far side of the nearest one turns up; none among
    // the 64 nearest: the point ends an open curve (and the search stays cheap).
    const std::size_t k_max = std::min<std::size_t>(64, n);
    for (std::size_t k = std::min<std::size_t>(16, n);; k = std::min(2 * k, k_max)) {
      const auto near = index.nearest_indices(points[a], k);
      std::size_t nearest = n, other = n;
      for (const std::size_t b : near) {
        if (b == a || points[b] == points[a]) continue;
        if (nearest == n) {
          nearest = b;
        } else if (dot(points[b] - points[a], points[nearest] - points[a]) < 0) {
          other = b;
          break;
        }
      }
      if (nearest != n) join(a, nearest);
      if (other != n) join(a, other);
      if (other != n || k == k_max) break;
    }
  }
  // At a sharp corner the far-side neighbour can lie on another curve: drop joins between two
  // points that both have more than two, longest first.
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  for (std::size_t a = 0; a < n; ++a)
    for (const std::size_t b : adj[a])
      if (a < b) edges.emplace_back(a, b);
  auto length_of = [&points](const std::pair<std::size_t, std::size_t>& e) {
    return CGAL::squared_distance(points[e.first], points[e.second]);
  };
  std::stable_sort(edges.begin(), edges.end(),
                   [&](const auto& x, const auto& y) { return length_of(x) > length_of(y); });
  for (const auto& [a, b] : edges) {
    if (adj[a].size() > 2 && adj[b].size() > 2) erase_edge(adj, a, b);
  }
  return adj;
}

namespace {

// Reduces a nearly cyclic graph to its cycle: repeatedly removes the shortest chain (path
// through points with two joins) that is a spur (it ends at a point with one join) or a rung
// (both ends have three or more), the defects a band's centroids leave in their NN-crust.
// Points left without joins are dropped. Then walks the cycle; nullopt unless the points left
// form exactly one cycle of at least 3, or if more than `max_rounds` removals were needed.
std::optional<Polyline> single_cycle(const Polyline& pts, std::vector<std::vector<std::size_t>> adj,
                                     int max_rounds = 8) {
  const std::size_t n = pts.size();
  for (int round = 0;; ++round) {
    std::vector<std::size_t> best;  // vertices of the chain to remove, ends included
    for (std::size_t v = 0; v < n; ++v) {
      if (adj[v].size() == 2 || adj[v].empty()) continue;
      for (const std::size_t first : adj[v]) {
        std::vector<std::size_t> chain{v, first};
        while (adj[chain.back()].size() == 2 && chain.back() != v) {
          const std::size_t at = chain.back(), from = chain[chain.size() - 2];
          chain.push_back(adj[at][0] == from ? adj[at][1] : adj[at][0]);
        }
        const std::size_t end = chain.back();
        const bool is_spur = adj[v].size() == 1 || adj[end].size() == 1;
        const bool is_rung = end != v && adj[v].size() >= 3 && adj[end].size() >= 3;
        if ((is_spur || is_rung) && (best.empty() || chain.size() < best.size())) best = chain;
      }
    }
    if (best.empty()) break;
    if (round == max_rounds) return std::nullopt;
    for (std::size_t k = 0; k + 1 < best.size(); ++k) erase_edge(adj, best[k], best[k + 1]);
  }
  std::size_t start = n, used = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (adj[v].empty()) continue;
    if (adj[v].size() != 2) return std::nullopt;
    if (start == n) start = v;
    ++used;
  }
  if (used < 3) return std::nullopt;
  Polyline out;
  std::size_t previous = adj[start][1], at = start;
  do {
    out.push_back(pts[at]);
    const std::size_t next = adj[at][0] == previous ? adj[at][1] : adj[at][0];
    previous = at;
    at = next;
  } while (at != start && out.size() <= used);
  if (out.size() != used) return std::nullopt;  // several cycles
  return out;
}

}  // namespace

std::optional<Polyline> band_cycle(const std::vector<Point3>& points, const std::vector<std::size_t>& component,
                                   double radius) {
  // Greedy thinning in index order on a grid of cell `radius`: seeds at least `radius` apart.
  using Key = std::array<long long, 3>;
  auto key_of = [radius](const Point3& p) {
    return Key{static_cast<long long>(std::floor(p.x() / radius)), static_cast<long long>(std::floor(p.y() / radius)),
               static_cast<long long>(std::floor(p.z() / radius))};
  };
  std::map<Key, std::vector<std::size_t>> grid;  // seed ids (into `seeds`) per cell
  Polyline seeds;
  for (const std::size_t i : component) {
    const Point3& p = points[i];
    const Key k = key_of(p);
    bool is_covered = false;
    for (long long dx = -1; dx <= 1 && !is_covered; ++dx)
      for (long long dy = -1; dy <= 1 && !is_covered; ++dy)
        for (long long dz = -1; dz <= 1 && !is_covered; ++dz) {
          const auto it = grid.find(Key{k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == grid.end()) continue;
          for (const std::size_t sid : it->second)
            if (CGAL::squared_distance(seeds[sid], p) < radius * radius) {
              is_covered = true;
              break;
            }
        }
    if (!is_covered) {
      grid[k].push_back(seeds.size());
      seeds.push_back(p);
    }
  }
  if (seeds.size() < 3) return std::nullopt;
  // Each seed becomes the centroid of the band points nearest to it: a sample of the band's
  // centre line about `radius` apart.
  const PointIndex seed_index(seeds);
  std::vector<Vector3> sums(seeds.size(), Vector3(0, 0, 0));
  std::vector<std::size_t> counts(seeds.size(), 0);
  for (const std::size_t i : component) {
    const std::size_t sid = seed_index.nearest_indices(points[i], 1).front();
    sums[sid] = sums[sid] + (points[i] - CGAL::ORIGIN);
    ++counts[sid];
  }
  Polyline centres;
  for (std::size_t k = 0; k < seeds.size(); ++k)
    centres.push_back(CGAL::ORIGIN + sums[k] / static_cast<double>(counts[k]));
  return single_cycle(centres, nn_crust_edges(centres));
}

GivenCurves order_given_points(const std::vector<Point3>& points, const Candidates& candidates,
                               double bin_width) {
  const auto [ids, marked] = flagged_subset(points, candidates);
  const auto adj = nn_crust_edges(marked);
  GivenCurves out;
  std::vector<char> seen(ids.size(), 0);
  std::vector<std::size_t> slot(ids.size(), 0);  // position of a marked point in its component
  for (std::size_t start = 0; start < ids.size(); ++start) {
    if (seen[start]) continue;
    std::vector<std::size_t> members{start};
    seen[start] = 1;
    for (std::size_t m = 0; m < members.size(); ++m)
      for (const std::size_t b : adj[members[m]])
        if (!seen[b]) {
          seen[b] = 1;
          members.push_back(b);
        }
    std::vector<std::size_t> component;
    double longest = 0.0;
    for (const std::size_t a : members) {
      component.push_back(ids[a]);
      for (const std::size_t b : adj[a])
        longest = std::max(longest, std::sqrt(CGAL::squared_distance(marked[a], marked[b])));
    }
    std::sort(component.begin(), component.end());
    Polyline local;
    for (std::size_t m = 0; m < members.size(); ++m) {
      slot[members[m]] = m;
      local.push_back(marked[members[m]]);
    }
    std::vector<std::vector<std::size_t>> local_adj(members.size());
    for (std::size_t m = 0; m < members.size(); ++m)
      for (const std::size_t b : adj[members[m]]) local_adj[m].push_back(slot[b]);
    Centreline line;
    if (const auto cycle = single_cycle(local, local_adj)) {
      line.points = *cycle;
      line.length = mesh::closed_length(line.points);
      line.end_gap = std::sqrt(CGAL::squared_distance(line.points.back(), line.points.front()));
      line.open_length = line.length - line.end_gap;
    } else {
      line = order_component(points, component, LinkReach(1.01 * longest), bin_width);
    }
    out.components.push_back(std::move(component));
    out.centrelines.push_back(std::move(line));
  }
  return out;
}

Centreline bin_along_loop(const Polyline& band, const Polyline& loop, double bin_width) {
  Centreline out;
  const std::size_t n = loop.size();
  std::vector<double> arc(n + 1, 0.0);  // arc[n]: the whole closed length
  for (std::size_t k = 0; k < n; ++k)
    arc[k + 1] = arc[k] + std::sqrt(CGAL::squared_distance(loop[k], loop[(k + 1) % n]));
  const double total = arc[n];
  out.end_gap = std::sqrt(CGAL::squared_distance(loop.back(), loop.front()));
  if (!(total > 0)) {
    out.points = loop;
    return out;
  }
  // The arc position of a band point is that of its nearest loop vertex.
  const PointIndex loop_index(loop);
  auto position = [&](const Point3& p) { return arc[loop_index.nearest_indices(p, 1).front()]; };
  const auto bins = static_cast<std::size_t>(std::max(3.0, std::round(total / bin_width)));
  std::vector<Vector3> sums(bins, Vector3(0, 0, 0));
  std::vector<std::size_t> counts(bins, 0);
  for (const Point3& p : band) {
    const auto bin =
        std::min(bins - 1, static_cast<std::size_t>(position(p) / total * static_cast<double>(bins)));
    sums[bin] = sums[bin] + (p - CGAL::ORIGIN);
    ++counts[bin];
  }
  for (std::size_t b = 0; b < bins; ++b) {
    if (counts[b] > 0) out.points.push_back(CGAL::ORIGIN + sums[b] / static_cast<double>(counts[b]));
  }
  out.length = mesh::closed_length(out.points);
  out.open_length = out.length - std::sqrt(CGAL::squared_distance(out.points.back(), out.points.front()));
  return out;
}

Centreline order_component(const std::vector<Point3>& points,
                           const std::vector<std::size_t>& component, const LinkReach& reach,
                           double bin_width, const std::vector<Vector3>* conormals, double min_conormal_dot) {
  Polyline local;
  local.reserve(component.size());
  for (const std::size_t i : component) local.push_back(points[i]);
  Centreline out;
  if (local.size() < 3) {
    out.points = local;
    out.length = mesh::closed_length(local);
    out.open_length = local.empty() ? 0.0 : out.length - std::sqrt(CGAL::squared_distance(
                                                             local.back(), local.front()));
    return out;
  }
  // Minimum spanning tree (Kruskal, ties by index) of the distance graph within the links'
  // reach, of the links whose conormals agree when they are given: across a strip narrower
  // than the reach its two rims face each other, and a tree through such links takes a short
  // cut across the strip instead of going round its end.
  const PointIndex index(local);
  std::vector<std::tuple<double, std::size_t, std::size_t>> edges;
  for (std::size_t a = 0; a < local.size(); ++a) {
    for (const std::size_t b : index.within(local[a], reach(component[a]))) {
      if (b == a) continue;
      if (conormals && dot((*conormals)[component[a]], (*conormals)[component[b]]) <= min_conormal_dot) continue;
      edges.emplace_back(std::sqrt(CGAL::squared_distance(local[a], local[b])), std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  UnionFind sets(local.size());
  std::vector<std::vector<std::pair<std::size_t, double>>> adj(local.size());
  for (const auto& [len, a, b] : edges) {
    if (sets.unite(a, b)) {
      adj[a].emplace_back(b, len);
      adj[b].emplace_back(a, len);
    }
  }
  // Diameter path of the tree (of the component containing vertex 0: components are linked
  // within their reach, so this is all of it).
  std::vector<std::size_t> parent;
  const std::size_t end_a = farthest(adj, 0, parent);
  const std::size_t end_b = farthest(adj, end_a, parent);
  Polyline path;
  for (std::size_t v = end_b;; v = parent[v]) {
    path.push_back(local[v]);
    if (v == end_a) break;
  }
  return bin_along_loop(local, path, bin_width);
}

}  // namespace envcrust::boundary::detail
