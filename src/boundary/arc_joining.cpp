// arc_joining: open arcs of the flagged boundary band joined end to end into closed loops,
// for a hole whose boundary the angle-gap test flags only in pieces.
#include "boundary_detail.h"

#include <algorithm>

namespace envcrust::boundary::detail {
namespace {

double distance(const Point3& p, const Point3& q) { return std::sqrt(CGAL::squared_distance(p, q)); }

// End e of open arc e / 2: its front (e even) or back (e odd) point.
const Point3& end_point(const std::vector<Centreline>& lines, const std::vector<std::size_t>& open, std::size_t e) {
  const Polyline& p = lines[open[e / 2]].points;
  return e % 2 == 0 ? p.front() : p.back();
}

struct Link {
  double length;
  std::size_t e, f;  // ends of two different arcs
};

// Links between ends of different open arcs, shortest first; a link may reach
// max(limits.max_join, limits.max_join_local * the larger local spacing of its two ends,
// limits.max_join_rel_arc * the shorter open length of its two arcs).
std::vector<Link> candidate_links(const std::vector<Centreline>& lines, const std::vector<std::size_t>& open,
                                  const std::vector<Point3>& points, const PointIndex& index,
                                  const ArcJoinLimits& limits) {
  const std::size_t ends = 2 * open.size();
  std::vector<double> local(ends);
  for (std::size_t e = 0; e < ends; ++e) {
    const Point3& p = end_point(lines, open, e);
    local[e] = distance(p, points[index.nearest_indices(p, 7).back()]);
  }
  std::vector<Link> links;
  for (std::size_t e = 0; e < ends; ++e) {
    for (std::size_t f = e + 1; f < ends; ++f) {
      if (e / 2 == f / 2) continue;
      const double d = distance(end_point(lines, open, e), end_point(lines, open, f));
      const double shorter = std::min(lines[open[e / 2]].open_length, lines[open[f / 2]].open_length);
      if (d < std::max({limits.max_join, limits.max_join_local * std::max(local[e], local[f]),
                        limits.max_join_rel_arc * shorter})) {
        links.push_back({d, e, f});
      }
    }
  }
  std::sort(links.begin(), links.end(), [](const Link& a, const Link& b) {
    return a.length != b.length ? a.length < b.length : std::make_pair(a.e, a.f) < std::make_pair(b.e, b.f);
  });
  return links;
}

constexpr std::size_t kNone = static_cast<std::size_t>(-1);

// The arcs linked through `partner` from end `in` on: the ends in walking order, each arc
// entered at the first end of its pair and left at the second; it stops back at `in` (a
// cycle) or at an end with no partner (a chain, walked from one of its free ends).
std::vector<std::size_t> walk_links(std::size_t in, const std::vector<std::size_t>& partner) {
  std::vector<std::size_t> ends;
  const std::size_t first = in;
  do {
    const std::size_t out = in ^ 1U;
    ends.push_back(in);
    ends.push_back(out);
    in = partner[out];
  } while (in != kNone && in != first);
  return ends;
}

}  // namespace

std::size_t join_open_arcs(std::vector<std::vector<std::size_t>>& components, std::vector<Centreline>& lines,
                           const std::vector<Point3>& points, const PointIndex& index, const ArcJoinLimits& limits) {
  std::vector<std::size_t> open;
  for (std::size_t a = 0; a < lines.size(); ++a) {
    if (lines[a].end_gap > limits.close_gap && lines[a].open_length >= limits.min_arc) open.push_back(a);
  }
  if (open.size() < 2) return 0;
  // Greedy matching of ends, shortest links first (a link between the two ends of one chain
  // closes it into a cycle).
  const std::size_t ends = 2 * open.size();
  std::vector<std::size_t> partner(ends, kNone);
  std::vector<double> link_length(ends, 0.0);
  for (const Link& link : candidate_links(lines, open, points, index, limits)) {
    if (partner[link.e] != kNone || partner[link.f] != kNone) continue;
    partner[link.e] = link.f;
    partner[link.f] = link.e;
    link_length[link.e] = link_length[link.f] = link.length;
  }
  // The groups of linked arcs: each cycle walked from its lowest end, each chain of two or
  // more arcs from its lower free end. A group becomes one loop if its links, with the gap
  // that closes a chain, are shorter in all than the closing gaps its arcs would have alone
  // (a rim flagged in long pieces, as on a range scan's ragged edge, is one loop even when a
  // join across a wide unflagged stretch is missing); other groups leave their arcs as they were.
  std::vector<std::vector<std::size_t>> groups;
  std::vector<char> seen(ends, 0);
  for (const bool chains : {true, false}) {
    for (std::size_t e = 0; e < ends; ++e) {
      // A chain is walked from a free end whose arc is linked on at its other end; what is
      // left once the chains are walked are cycles.
      const bool starts = chains ? partner[e] == kNone && partner[e ^ 1U] != kNone : partner[e] != kNone;
      if (seen[e] || !starts) continue;
      groups.push_back(walk_links(e, partner));
      for (const std::size_t x : groups.back()) seen[x] = 1;
    }
  }
  std::vector<char> absorbed(lines.size(), 0);
  std::size_t made = 0;
  for (const std::vector<std::size_t>& group : groups) {
    const bool is_cycle = partner[group.back()] == group.front();
    double links = 0.0, own_gaps = 0.0, longest = 0.0;
    for (std::size_t k = 1; k < group.size(); k += 2) {
      own_gaps += lines[open[group[k] / 2]].end_gap;
      if (partner[group[k]] == kNone) continue;
      links += link_length[group[k]];
      longest = std::max(longest, link_length[group[k]]);
    }
    const double closing = is_cycle ? 0.0 : distance(end_point(lines, open, group.front()),
                                                     end_point(lines, open, group.back()));
    if (!(links + closing < own_gaps)) continue;
    std::size_t first = lines.size();
    for (std::size_t k = 0; k < group.size(); k += 2) first = std::min(first, open[group[k] / 2]);
    Polyline loop;
    std::vector<std::size_t> members;
    for (std::size_t k = 0; k < group.size(); k += 2) {
      const std::size_t arc = open[group[k] / 2];
      const Polyline& p = lines[arc].points;
      if (group[k] % 2 == 0) {
        loop.insert(loop.end(), p.begin(), p.end());
      } else {
        loop.insert(loop.end(), p.rbegin(), p.rend());
      }
      members.insert(members.end(), components[arc].begin(), components[arc].end());
      if (arc != first) absorbed[arc] = 1;
    }
    Centreline& line = lines[first];
    line.points = std::move(loop);
    line.end_gap = distance(line.points.back(), line.points.front());
    line.join_gap = longest;
    line.joined_arcs = group.size() / 2;
    line.length = 0.0;
    for (std::size_t k = 0; k < line.points.size(); ++k) {
      line.length += distance(line.points[k], line.points[(k + 1) % line.points.size()]);
    }
    line.open_length = line.length - line.end_gap;
    std::sort(members.begin(), members.end());
    components[first] = std::move(members);
    ++made;
  }
  std::size_t kept = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (absorbed[k]) continue;
    if (kept != k) {
      lines[kept] = std::move(lines[k]);
      components[kept] = std::move(components[k]);
    }
    ++kept;
  }
  lines.resize(kept);
  components.resize(kept);
  return made;
}

}  // namespace envcrust::boundary::detail
