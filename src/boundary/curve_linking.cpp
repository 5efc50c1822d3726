// Linking boundary candidates into components and ordering each along its MST diameter path,
// refined by binning all of the component's points along that path.
#include "boundary_detail.h"

#include <algorithm>
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

double closed_length(const Polyline& p) {
  double len = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    len += std::sqrt(CGAL::squared_distance(p[i], p[(i + 1) % p.size()]));
  }
  return len;
}

}  // namespace

std::vector<std::vector<std::size_t>> link_candidates(const std::vector<Point3>& points,
                                                      const Candidates& candidates,
                                                      double radius, double min_dot) {
  const auto [ids, flagged_points] = flagged_subset(points, candidates);
  const PointIndex index(flagged_points);
  UnionFind sets(ids.size());
  for (std::size_t a = 0; a < ids.size(); ++a) {
    for (const std::size_t b : index.within(flagged_points[a], radius)) {
      if (b <= a) continue;
      if (dot(candidates.conormals[ids[a]], candidates.conormals[ids[b]]) > min_dot) {
        sets.unite(a, b);
      }
    }
  }
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
    // Grow the query until a point on the far side of the nearest one turns up.
    for (std::size_t k = std::min<std::size_t>(16, n);; k = std::min(2 * k, n)) {
      const auto near = index.nearest(points[a], k);
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
      if (other != n || k == n) break;
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
    if (adj[a].size() > 2 && adj[b].size() > 2) {
      adj[a].erase(std::find(adj[a].begin(), adj[a].end(), b));
      adj[b].erase(std::find(adj[b].begin(), adj[b].end(), a));
    }
  }
  return adj;
}

GivenCurves order_given_points(const std::vector<Point3>& points, const Candidates& candidates,
                               double bin_width) {
  const auto [ids, marked] = flagged_subset(points, candidates);
  const auto adj = nn_crust_edges(marked);
  GivenCurves out;
  std::vector<char> seen(ids.size(), 0);
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
    bool is_cycle = members.size() >= 3;
    for (const std::size_t a : members) {
      component.push_back(ids[a]);
      is_cycle = is_cycle && adj[a].size() == 2;
      for (const std::size_t b : adj[a]) longest = std::max(longest, std::sqrt(CGAL::squared_distance(marked[a], marked[b])));
    }
    Centreline line;
    if (is_cycle) {  // walk it
      std::size_t previous = adj[start][1], at = start;
      do {
        line.points.push_back(marked[at]);
        const std::size_t next = adj[at][0] == previous ? adj[at][1] : adj[at][0];
        previous = at;
        at = next;
      } while (at != start && line.points.size() <= members.size());
      line.length = closed_length(line.points);
      line.open_length = line.length - std::sqrt(CGAL::squared_distance(line.points.back(), line.points.front()));
      line.end_gap = std::sqrt(CGAL::squared_distance(line.points.back(), line.points.front()));
    } else {
      std::sort(component.begin(), component.end());
      line = order_component(points, component, 1.01 * longest, bin_width);
    }
    std::sort(component.begin(), component.end());
    out.components.push_back(std::move(component));
    out.centrelines.push_back(std::move(line));
  }
  return out;
}

Centreline order_component(const std::vector<Point3>& points,
                           const std::vector<std::size_t>& component, double link_radius,
                           double bin_width) {
  Polyline local;
  local.reserve(component.size());
  for (const std::size_t i : component) local.push_back(points[i]);
  Centreline out;
  if (local.size() < 3) {
    out.points = local;
    out.length = closed_length(local);
    out.open_length = local.empty() ? 0.0 : out.length - std::sqrt(CGAL::squared_distance(
                                                             local.back(), local.front()));
    return out;
  }
  // Minimum spanning tree (Kruskal, ties by index) of the distance graph within link_radius.
  const PointIndex index(local);
  std::vector<std::tuple<double, std::size_t, std::size_t>> edges;
  for (std::size_t a = 0; a < local.size(); ++a) {
    for (const std::size_t b : index.within(local[a], link_radius)) {
      if (b > a) edges.emplace_back(std::sqrt(CGAL::squared_distance(local[a], local[b])), a, b);
    }
  }
  std::sort(edges.begin(), edges.end());
  UnionFind sets(local.size());
  std::vector<std::vector<std::pair<std::size_t, double>>> adj(local.size());
  for (const auto& [len, a, b] : edges) {
    if (sets.unite(a, b)) {
      adj[a].emplace_back(b, len);
      adj[b].emplace_back(a, len);
    }
  }
  // Diameter path of the tree (of the component containing vertex 0: components are linked
  // within link_radius, so this is all of it).
  std::vector<std::size_t> parent;
  const std::size_t end_a = farthest(adj, 0, parent);
  const std::size_t end_b = farthest(adj, end_a, parent);
  Polyline path;
  std::vector<double> arc;
  for (std::size_t v = end_b;; v = parent[v]) {
    if (!path.empty()) {
      arc.push_back(arc.back() + std::sqrt(CGAL::squared_distance(path.back(), local[v])));
    } else {
      arc.push_back(0.0);
    }
    path.push_back(local[v]);
    if (v == end_a) break;
  }
  out.end_gap = std::sqrt(CGAL::squared_distance(local[end_a], local[end_b]));
  const double total = arc.back() + out.end_gap;
  // Bin every component point by the arc-length position of its nearest path vertex.
  const auto bins = static_cast<std::size_t>(std::max(3.0, std::round(total / bin_width)));
  std::vector<Vector3> sums(bins, Vector3(0, 0, 0));
  std::vector<std::size_t> counts(bins, 0);
  const PointIndex path_index(path);
  for (const Point3& p : local) {
    const std::size_t v = path_index.nearest(p, 1).front();
    const auto bin = std::min(bins - 1, static_cast<std::size_t>(arc[v] / total *
                                                                 static_cast<double>(bins)));
    sums[bin] = sums[bin] + (p - CGAL::ORIGIN);
    ++counts[bin];
  }
  for (std::size_t b = 0; b < bins; ++b) {
    if (counts[b] > 0) out.points.push_back(CGAL::ORIGIN + sums[b] / static_cast<double>(counts[b]));
  }
  out.length = closed_length(out.points);
  out.open_length =
      out.length - std::sqrt(CGAL::squared_distance(out.points.back(), out.points.front()));
  return out;
}

}  // namespace envcrust::boundary::detail
