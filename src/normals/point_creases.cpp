// Sharp creases of a point cloud whose normal lines jump across them: where the tangent
// planes of two near neighbours meet in a line between them at a sharp bend.
#include "envcrust/normals.h"

#include "envcrust/errors.h"
#include "envcrust/nearest_index.h"
#include "envcrust/union_find.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>

namespace envcrust::normals {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

struct Found {
  CreaseSegment segment;
  double bend_deg;
};

// The crease that samples p and q (unit normal lines n, m) read, if their tangent planes meet
// in a line between them bent as their normal lines say.
std::optional<Found> crease_of_pair(const Point3& p, const Vector3& n, const Point3& q, const Vector3& m,
                                    const PointCreaseOptions& o) {
  const double c = n * m;
  const double sin2 = 1.0 - c * c;
  const double line_angle = std::acos(std::min(1.0, std::abs(c))) / kDegree;
  if (!(line_angle >= o.min_line_angle_deg)) return std::nullopt;
  // The point x of the planes' common line nearest the pair's midpoint: x = mid + a n + b m
  // with n.x = n.p and m.x = m.q.
  const Point3 mid = CGAL::midpoint(p, q);
  const double rn = n * (p - mid), rm = m * (q - mid);
  const double a = (rn - c * rm) / sin2, b = (rm - c * rn) / sin2;
  const Point3 x = mid + a * n + b * m;
  const double gap = std::sqrt(CGAL::squared_distance(p, q));
  if (!(std::sqrt(CGAL::squared_distance(x, mid)) <= gap)) return std::nullopt;  // the line is not between them
  Vector3 d = CGAL::cross_product(n, m);
  d = d / std::sqrt(d.squared_length());
  auto square_to_line = [&](const Point3& s) -> std::optional<Vector3> {
    Vector3 u = s - x;
    u = u - (u * d) * d;
    const double length = std::sqrt(u.squared_length());
    if (!(length > 0.05 * gap)) return std::nullopt;  // on the line: no side to read
    return u / length;
  };
  const auto up = square_to_line(p), uq = square_to_line(q);
  if (!up || !uq) return std::nullopt;
  const double wedge_deg = std::acos(std::clamp(*up * *uq, -1.0, 1.0)) / kDegree;
  const double bend = 180.0 - wedge_deg;
  if (!(bend > o.min_bend_deg)) return std::nullopt;
  if (std::abs(std::min(bend, 180.0 - bend) - line_angle) > o.max_disagreement_deg) return std::nullopt;
  Vector3 wedge = *up + *uq;
  const double wedge_length = std::sqrt(wedge.squared_length());
  if (!(wedge_length > 0)) return std::nullopt;
  return Found{{x - gap * d, x + gap * d, wedge / wedge_length}, bend};
}

}  // namespace

mesh::SharpEdges point_creases(const std::vector<Point3>& points, const std::vector<Vector3>& normal_lines,
                               const PointCreaseOptions& o) {
  if (!(o.min_bend_deg > 0 && o.min_bend_deg < 180))
    throw InvalidOptions("point creases: min_bend_deg must be in (0, 180) (got " + std::to_string(o.min_bend_deg) + ")");
  if (!(o.min_line_angle_deg > 0 && o.min_line_angle_deg <= 90))
    throw InvalidOptions("point creases: min_line_angle_deg must be in (0, 90] (got " +
                         std::to_string(o.min_line_angle_deg) + ")");
  if (!(o.max_disagreement_deg >= 0))
    throw InvalidOptions("point creases: max_disagreement_deg must be >= 0 (got " +
                         std::to_string(o.max_disagreement_deg) + ")");
  if (o.neighbors < 1)
    throw InvalidOptions("point creases: neighbors must be >= 1 (got " + std::to_string(o.neighbors) + ")");
  if (normal_lines.size() != points.size())
    throw InvalidOptions("point creases: " + std::to_string(normal_lines.size()) + " normal lines for " +
                         std::to_string(points.size()) + " points");
  mesh::SharpEdges out;
  if (points.size() < 2) return out;
  const NearestIndex index(points);
  const auto k = static_cast<unsigned>(std::min<std::size_t>(o.neighbors + 1, points.size()));
  // Per point the pairs it forms with its neighbours, keyed by the smaller index first: a
  // pair both ends find is read once.
  struct Pair {
    std::size_t lo, hi;
    bool operator<(const Pair& other) const { return std::tie(lo, hi) < std::tie(other.lo, other.hi); }
    bool operator==(const Pair& other) const { return lo == other.lo && hi == other.hi; }
  };
  std::vector<std::vector<Pair>> per_point(points.size());
  const auto order = mesh::hilbert_order(points);
  tbb::parallel_for(std::size_t{0}, order.size(), [&](std::size_t r) {
    const std::size_t i = order[r];
    for (const auto& [j, distance] : index.nearest(points[i], k))
      if (j != i && distance > 0) per_point[i].push_back({std::min(i, j), std::max(i, j)});
  });
  std::vector<Pair> pairs;
  for (auto& list : per_point) pairs.insert(pairs.end(), list.begin(), list.end());
  per_point = {};
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::vector<std::optional<Found>> found(pairs.size());
  tbb::parallel_for(std::size_t{0}, pairs.size(), [&](std::size_t e) {
    const auto [i, j] = pairs[e];
    found[e] = crease_of_pair(points[i], normal_lines[i], points[j], normal_lines[j], o);
  });
  std::vector<double> lengths;
  for (const auto& f : found) {
    if (!f) continue;
    lengths.push_back(std::sqrt(CGAL::squared_distance(f->segment.a, f->segment.b)));
    if (f->bend_deg > out.max_bend_deg) {
      out.max_bend_deg = f->bend_deg;
      out.sharpest = CGAL::midpoint(f->segment.a, f->segment.b);
    }
    out.segments.push_back(f->segment);
  }
  out.count = out.segments.size();
  if (out.segments.empty()) return out;
  // The creases' length: a minimum spanning forest of the segments' midpoints (over their 8
  // nearest neighbours), without links longer than 3 pairs, so separate creases are not joined.
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double max_link = 3.0 * lengths[lengths.size() / 2];
  std::vector<Point3> middles;
  for (const auto& seg : out.segments) middles.push_back(CGAL::midpoint(seg.a, seg.b));
  const NearestIndex middle_index(middles);
  struct Link {
    double length;
    std::uint32_t a, b;
    bool operator<(const Link& other) const { return std::tie(length, a, b) < std::tie(other.length, other.a, other.b); }
  };
  std::vector<Link> links;
  const auto link_k = static_cast<unsigned>(std::min<std::size_t>(9, middles.size()));
  for (std::size_t m = 0; m < middles.size(); ++m)
    for (const auto& [other, distance] : middle_index.nearest(middles[m], link_k))
      if (other > m && distance <= max_link)
        links.push_back({distance, static_cast<std::uint32_t>(m), static_cast<std::uint32_t>(other)});
  std::sort(links.begin(), links.end());
  topology::UnionFind forest(middles.size());
  for (const Link& link : links) {
    if (forest.find(link.a) == forest.find(link.b)) continue;
    forest.unite(link.a, link.b);
    out.total_length += link.length;
  }
  return out;
}

}  // namespace envcrust::normals
