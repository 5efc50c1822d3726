// detect_boundary: option checks, then angle-gap candidates, support filter, linking,
// ordering, smoothing, resampling and frames of each boundary loop of a point cloud.
#include "boundary_detail.h"

#include "envcrust/errors.h"
#include "envcrust/normals.h"

#include <algorithm>
#include <sstream>

namespace envcrust::boundary {
namespace detail {

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace detail

namespace {

using detail::format_number;

// Seed spacing of band_cycle, in spacings s: the flagged band is 1-2 s wide.
constexpr double kBandSeedSpacing = 4.0;
// Longest join between two open arcs made into one loop, in s: a slot a few spacings wide
// whose tight ends went unflagged (the bunny's long base slot: 4.6 s).
constexpr double kMaxArcJoin = 10.0;
// Shortest arc joined, as a fraction of min_loop_length: false-candidate chains around random
// voids reach 10 s at 50k points (two of them were joined into a false loop on the saddle).
constexpr double kMinJoinedArc = 0.6;

void require(bool ok, const std::string& field, double value, const std::string& range) {
  if (!ok) {
    throw InvalidOptions("boundary detection: " + field + " must be " + range + " (got " +
                         format_number(value) + ")");
  }
}

void validate(const BoundaryOptions& o) {
  require(o.neighbors >= 8, "neighbors", o.neighbors, ">= 8");
  require(o.gap_threshold_deg > 0 && o.gap_threshold_deg < 360, "gap_threshold_deg",
          o.gap_threshold_deg, "in (0, 360)");
  require(o.weak_gap_threshold_deg > 0 && o.weak_gap_threshold_deg <= o.gap_threshold_deg,
          "weak_gap_threshold_deg", o.weak_gap_threshold_deg, "in (0, gap_threshold_deg]");
  require(o.conormal_agreement_deg > 0 && o.conormal_agreement_deg <= 180,
          "conormal_agreement_deg", o.conormal_agreement_deg, "in (0, 180]");
  require(o.support_radius > 0 && std::isfinite(o.support_radius), "support_radius",
          o.support_radius, "> 0");
  require(o.link_distance > 0 && std::isfinite(o.link_distance), "link_distance",
          o.link_distance, "> 0");
  require(o.link_min_conormal_dot >= -1 && o.link_min_conormal_dot < 1, "link_min_conormal_dot",
          o.link_min_conormal_dot, "in [-1, 1)");
  require(o.close_distance > 0 && std::isfinite(o.close_distance), "close_distance",
          o.close_distance, "> 0");
  require(o.smoothing_half_window >= 0, "smoothing_half_window", o.smoothing_half_window, ">= 0");
  require(o.min_loop_length >= 0 && std::isfinite(o.min_loop_length), "min_loop_length",
          o.min_loop_length, ">= 0");
  if (o.curve_spacing) {
    require(*o.curve_spacing > 0 && std::isfinite(*o.curve_spacing), "curve_spacing",
            *o.curve_spacing, "> 0");
  }
  require(o.min_loop_width >= 0 && std::isfinite(o.min_loop_width), "min_loop_width", o.min_loop_width, ">= 0");
  require(o.outward_offset >= -5 && o.outward_offset <= 5, "outward_offset", o.outward_offset,
          "in [-5, 5]");
}

std::vector<Vector3> unit_normals(const std::vector<Point3>& points,
                                  const std::vector<Vector3>& normal_lines) {
  if (normal_lines.size() != points.size()) {
    throw InvalidInput("boundary detection: " + std::to_string(normal_lines.size()) +
                       " normal lines for " + std::to_string(points.size()) + " points");
  }
  std::vector<Vector3> out;
  out.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Point3& p = points[i];
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      throw InvalidInput("point " + std::to_string(i) + " has a non-finite coordinate");
    }
    const double len = detail::length(normal_lines[i]);
    if (!(len > 0) || !std::isfinite(len)) {
      throw InvalidInput("normal line " + std::to_string(i) + " is zero or not finite");
    }
    out.push_back(normal_lines[i] / len);
  }
  return out;
}

// 4 area / perimeter of a closed polyline (area = norm of its vector area): a disc's
// diameter, about twice the width of a long slot.
double loop_width(const Polyline& curve) {
  Vector3 area(0, 0, 0);
  double perimeter = 0.0;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    const Point3& a = curve[i];
    const Point3& b = curve[(i + 1) % curve.size()];
    area = area + 0.5 * CGAL::cross_product(a - CGAL::ORIGIN, b - CGAL::ORIGIN);
    perimeter += detail::length(b - a);
  }
  return perimeter > 0 ? 4.0 * detail::length(area) / perimeter : 0.0;
}

// Median over the component's points of the distance to their 6th neighbour.
double local_spacing(const std::vector<Point3>& points, const detail::PointIndex& index,
                     const std::vector<std::size_t>& component) {
  std::vector<double> d;
  d.reserve(component.size());
  for (const std::size_t i : component) {
    const auto near = index.nearest(points[i], 7);
    d.push_back(detail::length(points[near.back()] - points[i]));
  }
  if (d.empty()) return 0.0;
  const auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  return *mid;
}

// Turns each component of flagged candidates, with its ordered centreline, into a closed,
// framed curve (resampled, smoothed); fills `out` (curves, flags, conormals, warnings). With
// `drop_small`, components shorter than min_loop_length or narrower than min_loop_width are
// dropped and counted; without it only those that order into fewer than 3 points are, with a
// warning.
void build_curves(const std::vector<Point3>& points, const std::vector<Vector3>& normals,
                  const detail::PointIndex& index, const detail::Candidates& candidates,
                  const BoundaryOptions& options, const std::vector<std::vector<std::size_t>>& components,
                  const std::vector<detail::Centreline>& lines, bool drop_small, BoundaryDetection& out) {
  const double s = out.spacing;
  const double output_spacing = options.curve_spacing.value_or(s);
  out.is_boundary_point.assign(points.size(), false);
  out.conormals.assign(points.size(), Vector3(0, 0, 0));
  for (std::size_t c = 0; c < components.size(); ++c) {
    const auto& component = components[c];
    const detail::Centreline& line = lines[c];
    if (line.points.size() < 3) {
      ++out.dropped_loops;
      if (!drop_small) {
        const Point3& p = points[component.front()];
        out.warnings.push_back("a group of " + std::to_string(component.size()) + " boundary points near (" +
                               format_number(p.x()) + ", " + format_number(p.y()) + ", " +
                               format_number(p.z()) + ") makes no loop; ignored");
      }
      continue;
    }
    if (drop_small && line.open_length < options.min_loop_length * s) {
      ++out.dropped_loops;
      continue;
    }
    Polyline curve = detail::resample_closed(line.points, s);
    curve = detail::smooth_closed(curve, options.smoothing_half_window);
    curve = detail::resample_closed(curve, output_spacing);
    const double local = local_spacing(points, index, component);
    const double width = local > 0 ? loop_width(curve) / local : 0.0;
    if (drop_small && options.min_loop_width > 0 && local > 0 && width < options.min_loop_width) {
      ++out.dropped_loops;
      continue;
    }
    const std::size_t id = out.curves.size();
    if (line.join_gap > 0) {
      out.warnings.push_back("curve " + std::to_string(id) +
                             ": two open arcs joined into one loop across gaps of up to " +
                             format_number(line.join_gap / s) +
                             " spacings (the hole's thin ends went undetected)");
    } else if (line.end_gap > options.close_distance * s) {
      out.warnings.push_back("curve " + std::to_string(id) + ": the ordered path's ends are " +
                             format_number(line.end_gap / s) +
                             " spacings apart; closed across the gap");
    }
    BoundaryCurve framed = detail::frame_curve(curve, points, normals, index, candidates,
                                               component, id, out.warnings);
    if (options.outward_offset != 0) {
      for (BoundaryVertex& v : framed.vertices) {
        v.position = v.position + options.outward_offset * s * v.conormal;
      }
    }
    out.curves.push_back(std::move(framed));
    out.loop_widths.push_back(width);
    for (const std::size_t i : component) {
      out.is_boundary_point[i] = true;
      out.conormals[i] = candidates.conormals[i];
    }
  }
}

// Unit outward conormal of a boundary sample: away from the centroid of its neighbours, in
// the plane perpendicular to its normal line n.
Vector3 centroid_conormal(const std::vector<Point3>& points, const Vector3& n,
                          const std::vector<std::size_t>& neighbors, std::size_t self) {
  Vector3 sum(0, 0, 0);
  for (const std::size_t j : neighbors)
    if (j != self) sum = sum + (points[j] - points[self]);
  return detail::unit_perpendicular(-sum, n);
}

// Pairs of open arcs (ordered bands whose ends stay more than `close_gap` apart, such as the
// two flagged sides of a slot whose tight ends went unflagged) joined end to end into one
// loop, when both joins are shorter than `max_join` and together shorter than the two arcs'
// own closing gaps, and both arcs at least `min_arc` long (chains of false candidates around
// random voids stay shorter). Greedy, shortest joins first; joined components are merged
// into the first. Returns the number of joins made.
std::size_t join_open_arcs(std::vector<std::vector<std::size_t>>& components,
                           std::vector<detail::Centreline>& lines, double close_gap, double max_join,
                           double min_arc) {
  struct Join {
    double cost;
    std::size_t a, b;
    bool reverse_b;
  };
  auto dist = [](const Point3& p, const Point3& q) { return std::sqrt(CGAL::squared_distance(p, q)); };
  std::vector<Join> joins;
  for (std::size_t a = 0; a < lines.size(); ++a) {
    if (lines[a].end_gap <= close_gap || lines[a].open_length < min_arc) continue;
    for (std::size_t b = a + 1; b < lines.size(); ++b) {
      if (lines[b].end_gap <= close_gap || lines[b].open_length < min_arc) continue;
      const Polyline &pa = lines[a].points, &pb = lines[b].points;
      for (const bool reverse : {false, true}) {
        const Point3& b_first = reverse ? pb.back() : pb.front();
        const Point3& b_last = reverse ? pb.front() : pb.back();
        const double j1 = dist(pa.back(), b_first), j2 = dist(b_last, pa.front());
        if (j1 < max_join && j2 < max_join && j1 + j2 < lines[a].end_gap + lines[b].end_gap)
          joins.push_back({j1 + j2, a, b, reverse});
      }
    }
  }
  std::sort(joins.begin(), joins.end(), [](const Join& x, const Join& y) { return x.cost < y.cost; });
  std::vector<char> used(lines.size(), 0), absorbed(lines.size(), 0);
  std::size_t made = 0;
  for (const Join& j : joins) {
    if (used[j.a] || used[j.b]) continue;
    used[j.a] = used[j.b] = 1;
    absorbed[j.b] = 1;
    Polyline& pa = lines[j.a].points;
    Polyline pb = lines[j.b].points;
    if (j.reverse_b) std::reverse(pb.begin(), pb.end());
    const double join_in = dist(pa.back(), pb.front());
    pa.insert(pa.end(), pb.begin(), pb.end());
    detail::Centreline& line = lines[j.a];
    line.end_gap = dist(pa.back(), pa.front());
    line.join_gap = std::max(join_in, line.end_gap);
    line.length = 0;
    for (std::size_t k = 0; k < pa.size(); ++k) line.length += dist(pa[k], pa[(k + 1) % pa.size()]);
    line.open_length = line.length - dist(pa.back(), pa.front());
    components[j.a].insert(components[j.a].end(), components[j.b].begin(), components[j.b].end());
    std::sort(components[j.a].begin(), components[j.a].end());
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

// Checked options and unit normals of a cloud with enough points for the neighbour queries.
std::vector<Vector3> checked_normals(const std::vector<Point3>& points, const std::vector<Vector3>& normal_lines,
                                     const BoundaryOptions& options) {
  validate(options);
  std::vector<Vector3> normals = unit_normals(points, normal_lines);
  if (points.size() < static_cast<std::size_t>(options.neighbors) + 1) {
    throw DegenerateInput("boundary detection needs at least neighbors + 1 = " +
                          std::to_string(options.neighbors + 1) + " points (got " +
                          std::to_string(points.size()) + ")");
  }
  return normals;
}

}  // namespace

BoundaryDetection detect_boundary(const std::vector<Point3>& points,
                                  const std::vector<Vector3>& normal_lines,
                                  const BoundaryOptions& options) {
  const std::vector<Vector3> normals = checked_normals(points, normal_lines, options);
  BoundaryDetection out;
  out.spacing = normals::average_spacing(points, 6);
  const double s = out.spacing;
  const detail::PointIndex index(points);

  detail::Candidates candidates = detail::angle_gap_candidates(points, normals, index, options);
  detail::keep_connected_to_strong(points, candidates, options.link_distance * s,
                                   options.link_min_conormal_dot);
  if (options.require_two_sided_support) {
    detail::filter_two_sided_support(points, normals, candidates, options.support_radius * s,
                                     options.link_min_conormal_dot);
  }
  const double link_radius = options.link_distance * s;
  auto components =
      detail::link_candidates(points, candidates, link_radius, options.link_min_conormal_dot);
  std::vector<detail::Centreline> lines;
  // Each band is ordered along the diameter path of its linking tree; when that path's ends
  // stay apart (a small or ragged loop whose tree branches), along the NN-crust cycle of its
  // thinned centre line instead, if it has one.
  for (const auto& component : components) {
    detail::Centreline line = detail::order_component(points, component, link_radius, s);
    if (line.end_gap > options.close_distance * s) {
      if (const auto cycle = detail::band_cycle(points, component, kBandSeedSpacing * s)) {
        Polyline band;
        for (const std::size_t i : component) band.push_back(points[i]);
        line = detail::bin_along_loop(band, detail::resample_closed(*cycle, 0.5 * s), s);
      }
    }
    lines.push_back(std::move(line));
  }
  join_open_arcs(components, lines, options.close_distance * s, kMaxArcJoin * s, kMinJoinedArc * options.min_loop_length * s);
  build_curves(points, normals, index, candidates, options, components, lines, true, out);
  return out;
}

BoundaryDetection boundary_from_points(const std::vector<Point3>& points,
                                       const std::vector<Vector3>& normal_lines, const PointSet& given,
                                       const BoundaryOptions& options) {
  const std::vector<Vector3> normals = checked_normals(points, normal_lines, options);
  if (given.points.empty()) throw InvalidInput("no boundary points given");
  if (given.has_normals() && given.normals.size() != given.points.size()) {
    throw InvalidInput(std::to_string(given.normals.size()) + " boundary conormals for " +
                       std::to_string(given.points.size()) + " boundary points");
  }
  BoundaryDetection out;
  out.spacing = normals::average_spacing(points, 6);
  const double s = out.spacing;
  const detail::PointIndex index(points);
  const auto k = static_cast<std::size_t>(options.neighbors) + 1;
  detail::Candidates candidates;
  candidates.flagged.assign(points.size(), 0);
  candidates.strong.assign(points.size(), 0);
  candidates.conormals.assign(points.size(), Vector3(0, 0, 0));
  for (std::size_t g = 0; g < given.points.size(); ++g) {
    const Point3& q = given.points[g];
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z())) {
      throw InvalidInput("boundary point " + std::to_string(g) + " has a non-finite coordinate");
    }
    const std::size_t i = index.nearest(q, 1).front();
    const double d = detail::length(points[i] - q);
    if (d > options.link_distance * s) {
      throw InvalidInput("boundary point " + std::to_string(g) + " at (" + format_number(q.x()) + ", " +
                         format_number(q.y()) + ", " + format_number(q.z()) + ") is " +
                         format_number(d / s) + " spacings from the nearest sample (at most " +
                         format_number(options.link_distance) + ")");
    }
    Vector3 c = given.has_normals() ? detail::unit_perpendicular(given.normals[g], normals[i]) : Vector3(0, 0, 0);
    if (c == Vector3(0, 0, 0)) c = centroid_conormal(points, normals[i], index.nearest(points[i], k), i);
    if (c == Vector3(0, 0, 0)) continue;  // no direction away from the neighbours: not a boundary
    if (!candidates.flagged[i]) candidates.conormals[i] = c;
    candidates.flagged[i] = candidates.strong[i] = 1;
  }
  // Given points may be spaced unevenly: the NN-crust joins each to its curve neighbours.
  const detail::GivenCurves given_curves = detail::order_given_points(points, candidates, s);
  build_curves(points, normals, index, candidates, options, given_curves.components, given_curves.centrelines,
               false, out);
  return out;
}

}  // namespace envcrust::boundary
