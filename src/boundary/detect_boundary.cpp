// detect_boundary: option checks, then angle-gap candidates, support filter, linking,
// ordering, smoothing, resampling and frames of each boundary loop of a point cloud.
#include "boundary_detail.h"

#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/normals.h"

#include <algorithm>
#include <optional>
#include <cmath>
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

// Neighbours of the average spacing s (normals::average_spacing).
constexpr int kSpacingNeighbours = 6;

// Seed spacing of band_cycle, in spacings s: the flagged band is 1-2 s wide.
constexpr double kBandSeedSpacing = 4.0;
// Longest join between open arcs made into one loop, in s: a slot a few spacings wide whose
// tight ends went unflagged (the bunny's long base slot: 4.6 s) ...
constexpr double kMaxArcJoin = 10.0;
// ... or in local spacings (6th-neighbour distance at the arc ends) where the rim is sampled
// more sparsely than the average: the lion head's neck rim came in four arcs 2-4 local
// spacings (11-19 s) apart.
constexpr double kMaxArcJoinLocal = 5.0;
// ... or as a fraction of the shorter of the two arcs: a range scan's ragged rim (the face
// scan's) is flagged in arcs 90-480 s long, 10-13 s apart where it turns sharply; chains of
// false candidates are too short to reach far.
constexpr double kMaxArcJoinRelArc = 0.15;
// Shortest arc joined, as a fraction of min_loop_length: false-candidate chains around random
// voids reach 10 s at 50k points (two of them were joined into a false loop on the saddle).
constexpr double kMinJoinedArc = 0.6;
// Normal lines within 30 degrees of each other: the same sheet.
constexpr double kSameSheetCos = 0.866;
// Largest move of a curve vertex out to (or in to) its outermost samples, in s: the fitted
// centre line lies about 0.8 s inside the band's outer edge.
constexpr double kMaxOuterFit = 2.0;
// An outer rim: conormals on average within 60 degrees of pointing away from its centroid.
constexpr double kOuterRimCos = 0.5;

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
  require(o.max_sampled_beyond >= 0 && o.max_sampled_beyond <= 1, "max_sampled_beyond", o.max_sampled_beyond,
          "in [0, 1]");
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
    const auto near = index.nearest_indices(points[i], 7);
    d.push_back(detail::length(points[near.back()] - points[i]));
  }
  if (d.empty()) return 0.0;
  const auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  return *mid;
}

// How much of an outer rim has the same sheet going on beyond it: 0 for a loop whose
// conormals point on average into it (a hole: on average within 60 degrees of its centroid;
// across a hole or a slot nothing tells a hole from a gap in the sampling), else the fraction
// of its vertices where a ball of radius w/4 centred w/2 out along the conormal (w = the
// loop's width, 4 area / perimeter) holds an input point other than the loop's own, within
// w/8 of the vertex's tangent plane and with a normal line within 30 degrees of the vertex's.
// Beyond the outer rim of a surface nothing lies there; beyond the rim of a patch sampled
// more densely than its surroundings (whose nearest neighbours all lie on the dense side, so
// the angle-gap test flags it) lie the sparse samples.
double sheet_beyond_fraction(const BoundaryCurve& curve, const std::vector<Point3>& points,
                             const std::vector<Vector3>& normals, const detail::PointIndex& index,
                             const std::vector<std::size_t>& component) {
  const std::size_t m = curve.vertices.size();
  const Polyline loop = curve.polyline();
  const double w = loop_width(loop);
  if (m < 3 || !(w > 0)) return 0.0;
  Vector3 sum(0, 0, 0);
  for (const Point3& p : loop) sum = sum + (p - CGAL::ORIGIN);
  const Point3 centre = CGAL::ORIGIN + sum / static_cast<double>(m);
  double inward = 0.0;
  for (const BoundaryVertex& v : curve.vertices) inward += detail::dot(v.conormal, detail::unit(centre - v.position));
  if (inward > -kOuterRimCos * static_cast<double>(m)) return 0.0;
  std::size_t sampled = 0;
  for (const BoundaryVertex& v : curve.vertices) {
    for (const std::size_t i : index.within(v.position + 0.5 * w * v.conormal, 0.25 * w)) {
      if (std::abs(detail::dot(points[i] - v.position, v.normal)) < 0.125 * w &&
          std::abs(detail::dot(normals[i], v.normal)) > kSameSheetCos &&
          !std::binary_search(component.begin(), component.end(), i)) {
        ++sampled;
        break;
      }
    }
  }
  return static_cast<double>(sampled) / static_cast<double>(m);
}

// The spacing a component's loop length is measured in: the median over its points of their
// local spacing (link reach over link_distance), at least s. A loop in a sparsely sampled part
// is held to as many of its own spacings as one elsewhere.
double loop_spacing(const std::vector<std::size_t>& component, const detail::LinkReach& reach,
                    double link_distance, double s) {
  if (reach.is_uniform()) return std::max(s, reach(0) / link_distance);
  std::vector<double> own;
  own.reserve(component.size());
  for (const std::size_t i : component) own.push_back(reach(i) / link_distance);
  if (own.empty()) return s;
  const auto mid = own.begin() + static_cast<std::ptrdiff_t>(own.size() / 2);
  std::nth_element(own.begin(), mid, own.end());
  return std::max(s, *mid);
}

// Per vertex of a curve resampled at spacing s, the smoothing's half window: as many vertices
// as span smoothing_half_window local spacings (of the nearest sample; at least s), so that a
// rim sampled sparsely is smoothed over as many of its samples as one sampled at s.
std::vector<int> local_half_windows(const Polyline& curve, const detail::PointIndex& index,
                                    const detail::LinkReach& reach, const BoundaryOptions& options, double s) {
  std::vector<int> out;
  out.reserve(curve.size());
  for (const Point3& p : curve) {
    const double local = std::max(s, reach(index.nearest_indices(p, 1).front()) / options.link_distance);
    out.push_back(static_cast<int>(std::lround(options.smoothing_half_window * local / s)));
  }
  return out;
}

// Turns each component of flagged candidates, with its ordered centreline, into a closed,
// framed curve (resampled, smoothed); fills `out` (curves, flags, conormals, warnings). With
// `reach` (detected candidates), components whose centreline or final loop is shorter than
// min_loop_length (in the component's own spacing, loop_spacing) or narrower than
// min_loop_width are dropped and counted; without it only those that order into fewer than 3
// points are, with a warning.
void build_curves(const std::vector<Point3>& points, const std::vector<Vector3>& normals,
                  const detail::PointIndex& index, const detail::Candidates& candidates,
                  const BoundaryOptions& options, const std::vector<std::vector<std::size_t>>& components,
                  const std::vector<detail::Centreline>& lines, const detail::LinkReach* reach,
                  BoundaryDetection& out) {
  const bool drop_small = reach != nullptr;
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
    const double min_length =
        options.min_loop_length * (reach ? loop_spacing(component, *reach, options.link_distance, s) : s);
    if (drop_small && line.open_length < min_length) {
      ++out.dropped_loops;
      continue;
    }
    Polyline curve = detail::resample_closed(line.points, s);
    curve = reach && !reach->is_uniform()
                ? detail::smooth_closed(curve, local_half_windows(curve, index, *reach, options, s))
                : detail::smooth_closed(curve, options.smoothing_half_window);
    // Framed once for the inlets and the fit; again only when an inlet was cut off.
    std::optional<BoundaryCurve> unfitted;
    auto frame = [&] {
      std::vector<std::string> unused;  // the final framing below warns
      return detail::frame_curve(curve, points, normals, index, candidates, component, 0, unused);
    };
    if (drop_small && options.close_narrow_inlets) {
      unfitted = frame();
      const std::size_t before = out.closed_inlets;
      Polyline closed = detail::close_inlets(*unfitted, options.min_loop_length * s, out.closed_inlets);
      if (out.closed_inlets > before) {
        curve = detail::resample_closed(closed, s);
        unfitted.reset();
      }
    }
    if (options.fit_to_outer_samples) {
      BoundaryCurve fitted = unfitted ? std::move(*unfitted) : frame();
      detail::fit_to_outer_samples(fitted, points, index, candidates, component, s, kMaxOuterFit * s,
                                   options.take_in_samples_beyond);
      curve = fitted.polyline();
    }
    curve = detail::resample_closed(detail::remove_switchbacks(curve), output_spacing);
    // Once its switchbacks are gone a path that ran out and back along one chain of flagged
    // samples (a crack, a spur of the band) can be left a loop shorter than any kept one
    // (the face scan's: its path 26 spacings end to end, the loop 0.7): it is held to the
    // same length.
    if (drop_small && mesh::closed_length(curve) < min_length) {
      ++out.dropped_loops;
      continue;
    }
    const double local = local_spacing(points, index, component);
    const double width = local > 0 ? loop_width(curve) / local : 0.0;
    if (drop_small && options.min_loop_width > 0 && local > 0 && width < options.min_loop_width) {
      ++out.dropped_loops;
      continue;
    }
    const std::size_t id = out.curves.size();
    std::vector<std::string> notes;
    if (line.joined_arcs > 0) {
      notes.push_back("curve " + std::to_string(id) + ": " + std::to_string(line.joined_arcs) +
                      " open arcs joined into one loop across gaps of up to " + format_number(line.join_gap / s) +
                      " spacings (parts of the rim went unflagged)");
    } else if (line.end_gap > options.close_distance * s) {
      notes.push_back("curve " + std::to_string(id) + ": the ordered path's ends are " +
                      format_number(line.end_gap / s) + " spacings apart; closed across the gap");
    }
    BoundaryCurve framed = detail::frame_curve(curve, points, normals, index, candidates, component, id, notes);
    const double beyond = sheet_beyond_fraction(framed, points, normals, index, component);
    if (drop_small && beyond > options.max_sampled_beyond) {
      ++out.dropped_loops;
      const Point3& p = framed.vertices.front().position;
      out.warnings.push_back("a loop of length " + format_number(mesh::closed_length(framed.polyline())) +
                             " near (" + format_number(p.x()) + ", " + format_number(p.y()) + ", " +
                             format_number(p.z()) + ") dropped: its conormals point out of it, but beyond " +
                             format_number(std::round(100 * beyond)) +
                             "% of it the surface goes on (the rim of a densely sampled patch, not a boundary)");
      continue;
    }
    for (auto& note : notes) out.warnings.push_back(std::move(note));
    if (options.outward_offset != 0) {
      for (BoundaryVertex& v : framed.vertices) {
        v.position = v.position + options.outward_offset * s * v.conormal;
      }
    }
    out.sampled_beyond.push_back(beyond);
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

// Checked options and unit normals of a cloud with enough points for the neighbour queries.
std::vector<Vector3> checked_normals(const std::vector<Point3>& points, const std::vector<Vector3>& normal_lines,
                                     const BoundaryOptions& options) {
  validate(options);
  std::vector<Vector3> normals = unit_normals(points, normal_lines);
  if (points.size() < static_cast<std::size_t>(options.neighbors) + 1) {
    throw DegenerateInput("boundary detection needs at least " + std::to_string(options.neighbors + 1) +
                          " points, each with its " + std::to_string(options.neighbors) + " nearest neighbours (got " +
                          std::to_string(points.size()) + ")");
  }
  return normals;
}

}  // namespace

namespace {

// The neighbours the detection reads per point: the angle gaps' and the spacing's.
unsigned needed_neighbours(const BoundaryOptions& options) {
  return static_cast<unsigned>(std::max(options.neighbors, kSpacingNeighbours));
}

// detect_boundary with its input checked (unit normals) and a table that fits.
BoundaryDetection detect_checked(const std::vector<Point3>& points, const std::vector<Vector3>& normals,
                                 const NeighbourTable& table, const BoundaryOptions& options) {
  BoundaryDetection out;
  out.spacing = normals::average_spacing(points, table, kSpacingNeighbours);
  const double s = out.spacing;
  const detail::PointIndex index(points);

  detail::Candidates candidates = detail::angle_gap_candidates(points, normals, table, options);
  const auto neighbors = static_cast<std::size_t>(options.neighbors);
  // Local spacings only for the options that read them (two passes over the table).
  const detail::LocalSpacings spacings = options.drop_density_steps || options.link_in_local_spacing
                                             ? detail::local_spacings(points, table, neighbors)
                                             : detail::LocalSpacings{};
  if (options.drop_density_steps)
    detail::unflag_density_steps(points, normals, table, index, spacings, candidates, neighbors);
  const detail::LinkReach reach = options.link_in_local_spacing
                                      ? detail::local_link_reach(spacings, options.link_distance, s)
                                      : detail::LinkReach(options.link_distance * s);
  detail::keep_connected_to_strong(points, candidates, reach, options.link_min_conormal_dot);
  if (options.require_two_sided_support) {
    detail::filter_two_sided_support(points, normals, candidates, options.support_radius * s,
                                     options.link_min_conormal_dot);
  }
  auto components = detail::link_candidates(points, candidates, reach, options.link_min_conormal_dot);
  std::size_t thick_points = 0;
  if (const std::size_t thick = detail::drop_thick_groups(points, table, neighbors, components, thick_points);
      thick > 0) {
    out.dropped_loops += thick;
    out.warnings.push_back(std::to_string(thick) + " group" + (thick == 1 ? "" : "s") + " of " +
                           std::to_string(thick_points) +
                           " boundary candidates dropped: their neighbourhoods are no sheet (a tube, tip or "
                           "crumpled part thinner than the sampling resolves)");
  }
  std::vector<detail::Centreline> lines;
  // Each band is ordered along the diameter path of its linking tree; when that path's ends
  // stay apart (a small or ragged loop whose tree branches), along the NN-crust cycle of its
  // thinned centre line instead, if it has one.
  for (const auto& component : components) {
    detail::Centreline line = detail::order_component(points, component, reach, s, &candidates.conormals,
                                                      options.link_min_conormal_dot);
    if (line.end_gap > options.close_distance * s) {
      if (const auto cycle = detail::band_cycle(points, component, kBandSeedSpacing * s)) {
        Polyline band;
        for (const std::size_t i : component) band.push_back(points[i]);
        line = detail::bin_along_loop(band, detail::resample_closed(*cycle, 0.5 * s), s);
      }
    }
    lines.push_back(std::move(line));
  }
  detail::join_open_arcs(components, lines, points, index,
                         {.close_gap = options.close_distance * s,
                          .min_arc = kMinJoinedArc * options.min_loop_length * s,
                          .max_join = kMaxArcJoin * s,
                          .max_join_local = kMaxArcJoinLocal,
                          .max_join_rel_arc = kMaxArcJoinRelArc});
  build_curves(points, normals, index, candidates, options, components, lines, &reach, out);
  return out;
}

}  // namespace

BoundaryDetection detect_boundary(const std::vector<Point3>& points,
                                  const std::vector<Vector3>& normal_lines,
                                  const BoundaryOptions& options) {
  const std::vector<Vector3> normals = checked_normals(points, normal_lines, options);
  return detect_checked(points, normals, NeighbourTable(points, needed_neighbours(options)), options);
}

BoundaryDetection detect_boundary(const std::vector<Point3>& points, const std::vector<Vector3>& normal_lines,
                                  const NeighbourTable& table, const BoundaryOptions& options) {
  const std::vector<Vector3> normals = checked_normals(points, normal_lines, options);
  if (table.size() != points.size() || table.k() < needed_neighbours(options)) {
    throw InvalidOptions("boundary detection: a neighbour table of " + std::to_string(table.size()) + " rows of " +
                         std::to_string(table.k()) + " for " + std::to_string(points.size()) + " points and " +
                         std::to_string(needed_neighbours(options)) + " neighbours");
  }
  return detect_checked(points, normals, table, options);
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
  out.spacing = normals::average_spacing(points, kSpacingNeighbours);
  const double s = out.spacing;
  const detail::PointIndex index(points);
  const auto k = static_cast<std::size_t>(options.neighbors) + 1;
  detail::Candidates candidates;
  candidates.flagged.assign(points.size(), 0);
  candidates.strong.assign(points.size(), 0);
  candidates.conormals.assign(points.size(), Vector3(0, 0, 0));
  std::vector<char> matched(points.size(), 0);
  std::size_t matched_count = 0;
  for (std::size_t g = 0; g < given.points.size(); ++g) {
    const Point3& q = given.points[g];
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()) || !std::isfinite(q.z())) {
      throw InvalidInput("boundary point " + std::to_string(g) + " has a non-finite coordinate");
    }
    const std::size_t i = index.nearest_indices(q, 1).front();
    const double d = detail::length(points[i] - q);
    if (d > options.link_distance * s) {
      throw InvalidInput("boundary point " + std::to_string(g) + " at (" + format_number(q.x()) + ", " +
                         format_number(q.y()) + ", " + format_number(q.z()) + ") is " +
                         format_number(d / s) + " spacings from the nearest sample (at most " +
                         format_number(options.link_distance) + ")");
    }
    if (!matched[i]) matched[i] = 1, ++matched_count;
    Vector3 c = given.has_normals() ? detail::unit_perpendicular(given.normals[g], normals[i]) : Vector3(0, 0, 0);
    if (c == Vector3(0, 0, 0)) c = centroid_conormal(points, normals[i], index.nearest_indices(points[i], k), i);
    if (c == Vector3(0, 0, 0)) continue;  // no direction away from the neighbours: not a boundary
    if (!candidates.flagged[i]) candidates.conormals[i] = c;
    candidates.flagged[i] = candidates.strong[i] = 1;
  }
  // A boundary is a curve along the rim: points on most of the samples are the surface itself
  // (given as its own boundary, every sample made a curve vertex took 9.9 GB).
  if (2 * matched_count > points.size())
    throw InvalidInput("the " + std::to_string(given.points.size()) + " boundary points given fall on " +
                       std::to_string(matched_count) + " of the " + std::to_string(points.size()) +
                       " samples, more than half: a boundary is the rim of the surface, not the surface");
  // Given points may be spaced unevenly: the NN-crust joins each to its curve neighbours.
  const detail::GivenCurves given_curves = detail::order_given_points(points, candidates, s);
  build_curves(points, normals, index, candidates, options, given_curves.components, given_curves.centrelines,
               nullptr, out);
  return out;
}

}  // namespace envcrust::boundary
