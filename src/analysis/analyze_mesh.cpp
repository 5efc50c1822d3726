// analyze_mesh: composes topology, knot invariants of boundary loops and distances.
#include "envcrust/analysis.h"
#include "envcrust/errors.h"
#include "envcrust/mesh.h"
#include "envcrust/nearest_index.h"

#include <CGAL/bounding_box.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

namespace envcrust::analysis {
namespace {

bool loops_share_a_vertex(const topology::BoundaryLoop& a, const topology::BoundaryLoop& b) {
  const std::set<Index> va(a.vertices.begin(), a.vertices.end());
  return std::any_of(b.vertices.begin(), b.vertices.end(),
                     [&](Index v) { return va.count(v) > 0; });
}

void analyze_loops(AnalysisReport& report, const AnalyzeOptions& options) {
  const auto& topo = report.topology;
  const auto& loops = topo.boundary_loops;
  report.loops.resize(loops.size());
  for (std::size_t i = 0; i < loops.size(); ++i) report.loops[i].loop = i;
  if (!options.use_knots || loops.empty()) return;
  if (loops.size() > options.max_knot_loops) {
    report.warnings.push_back("knot analysis skipped: " + std::to_string(loops.size()) +
                              " boundary loops (limit " +
                              std::to_string(options.max_knot_loops) + ")");
    return;
  }
  std::vector<Polyline> curves;
  for (const auto& loop : loops) curves.push_back(loop.polyline(topo.points));
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (curves[i].size() < 3) {
      report.warnings.push_back("boundary loop " + std::to_string(i) + " has fewer than 3 vertices");
      continue;
    }
    try {
      report.loops[i].knot = knots::identify_knot(curves[i], options.knot);
    } catch (const Error& e) {
      report.warnings.push_back("boundary loop " + std::to_string(i) + ": " + e.what());
    }
  }
  for (std::size_t a = 0; a < loops.size(); ++a) {
    for (std::size_t b = a + 1; b < loops.size(); ++b) {
      if (curves[a].size() < 3 || curves[b].size() < 3) continue;
      if (loops_share_a_vertex(loops[a], loops[b])) {
        report.warnings.push_back("boundary loops " + std::to_string(a) + " and " +
                                  std::to_string(b) + " touch: no linking number");
        continue;
      }
      try {
        LinkingReport link;
        link.loop_a = a;
        link.loop_b = b;
        link.is_signed = loops[a].is_oriented && loops[b].is_oriented;
        link.linking_number = knots::linking_number(curves[a], curves[b], options.knot);
        if (!link.is_signed) link.linking_number = std::abs(link.linking_number);
        report.linking.push_back(link);
      } catch (const Error& e) {
        report.warnings.push_back("linking of loops " + std::to_string(a) + " and " +
                                  std::to_string(b) + ": " + e.what());
      }
    }
  }
}

// A lower bound of the Hausdorff distance between two curves: the farthest vertex of either
// from the other's bounding box.
double hausdorff_lower_bound(const Polyline& a, const CGAL::Bbox_3& box_a, const Polyline& b, const CGAL::Bbox_3& box_b) {
  auto farthest_from = [](const Polyline& c, const CGAL::Bbox_3& box) {
    double worst = 0.0;
    for (const auto& p : c) {
      const double dx = std::max({box.xmin() - p.x(), 0.0, p.x() - box.xmax()});
      const double dy = std::max({box.ymin() - p.y(), 0.0, p.y() - box.ymax()});
      const double dz = std::max({box.zmin() - p.z(), 0.0, p.z() - box.zmax()});
      worst = std::max(worst, dx * dx + dy * dy + dz * dz);
    }
    return std::sqrt(worst);
  };
  return std::max(farthest_from(a, box_b), farthest_from(b, box_a));
}

// Each reference curve's nearest loop. Loops are tried in order of the lower bound and the
// exact distance is computed only while the bound is below the best so far (a scan has tens
// of curves and loops, most of them far apart).
std::vector<BoundaryMatch> match_boundaries(const topology::MeshTopology& topo, const std::vector<Polyline>& reference) {
  std::vector<Polyline> curves;
  std::vector<CGAL::Bbox_3> boxes;
  for (const auto& loop : topo.boundary_loops) {
    curves.push_back(loop.polyline(topo.points));
    boxes.push_back(CGAL::bbox_3(curves.back().begin(), curves.back().end()));
  }
  std::vector<BoundaryMatch> matches;
  for (std::size_t r = 0; r < reference.size(); ++r) {
    BoundaryMatch match;
    match.reference_loop = r;
    match.hausdorff = std::numeric_limits<double>::infinity();
    const CGAL::Bbox_3 box = CGAL::bbox_3(reference[r].begin(), reference[r].end());
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t m = 0; m < curves.size(); ++m)
      order.emplace_back(hausdorff_lower_bound(reference[r], box, curves[m], boxes[m]), m);
    std::sort(order.begin(), order.end());
    for (const auto& [bound, m] : order) {
      if (bound >= match.hausdorff) break;
      const double d = distance::closed_polyline_hausdorff(reference[r], curves[m]);
      if (d < match.hausdorff) {
        match.hausdorff = d;
        match.mesh_loop = m;
      }
    }
    matches.push_back(match);
  }
  return matches;
}

}  // namespace

AnalysisReport analyze_mesh(const TriangleMesh& mesh, const Reference& reference,
                            const AnalyzeOptions& options) {
  return analyze_mesh(mesh, topology::analyze_topology(mesh), reference, options);
}

AnalysisReport analyze_mesh(const TriangleMesh& mesh, topology::MeshTopology topology,
                            const Reference& reference, const AnalyzeOptions& options) {
  AnalysisReport report;
  report.topology = std::move(topology);
  const auto& t = report.topology;
  if (t.non_manifold_edges > 0)
    report.warnings.push_back(std::to_string(t.non_manifold_edges) + " non-manifold edges");
  if (t.non_manifold_vertices > 0)
    report.warnings.push_back(std::to_string(t.non_manifold_vertices) + " non-manifold vertices");
  if (t.degenerate_faces > 0)
    report.warnings.push_back(std::to_string(t.degenerate_faces) + " degenerate faces");
  if (t.duplicate_faces > 0)
    report.warnings.push_back(std::to_string(t.duplicate_faces) + " duplicate faces");
  analyze_loops(report, options);
  if (options.use_self_intersections) {
    report.self_intersections = mesh::self_intersections(mesh);
    if (const auto& s = *report.self_intersections; s.face_pairs > 0) {
      std::ostringstream w;
      w << s.face_pairs << " pairs of faces pass through each other (" << s.faces << " faces), e.g. near ("
        << s.examples.front().x() << ", " << s.examples.front().y() << ", " << s.examples.front().z()
        << "): the mesh is not embedded";
      report.warnings.push_back(w.str());
    }
  }
  if (reference.mesh) {
    report.distance = distance::compare_to_mesh(mesh, *reference.mesh, options.distance);
  } else if (!reference.points.empty()) {
    report.distance = distance::compare_to_points(mesh, reference.points, options.distance);
  }
  if (!reference.boundary.empty()) report.boundary_matches = match_boundaries(report.topology, reference.boundary);
  return report;
}

knots::KnotReport analyze_curve(const Polyline& curve, const AnalyzeOptions& options) {
  return knots::identify_knot(curve, options.knot);
}

BoundaryCheck check_boundary(const topology::MeshTopology& topology, const std::vector<Polyline>& curves,
                             double tolerance, double follow_fraction, double min_resolvable_length) {
  if (!(tolerance > 0)) throw InvalidInput("check_boundary: tolerance must be > 0");
  if (!(follow_fraction > 0 && follow_fraction <= 1))
    throw InvalidInput("check_boundary: follow_fraction must be in (0, 1]");
  if (!(min_resolvable_length >= 0)) throw InvalidInput("check_boundary: min_resolvable_length must be >= 0");
  BoundaryCheck check;
  check.tolerance = tolerance;
  check.follow_fraction = follow_fraction;
  check.min_resolvable_length = min_resolvable_length;
  check.matches = match_boundaries(topology, curves);
  std::vector<char> explained(topology.boundary_loops.size(), 0);
  // Searched only when a curve is not followed: the result's vertices near it, if any.
  std::unique_ptr<NearestIndex> result_points;
  auto is_left_out = [&](const Polyline& curve) {
    if (!result_points) result_points = std::make_unique<NearestIndex>(topology.points);
    if (result_points->empty()) return true;
    return std::none_of(curve.begin(), curve.end(),
                        [&](const Point3& p) { return result_points->any_within(p, tolerance); });
  };
  for (const auto& m : check.matches) {
    double follow = std::numeric_limits<double>::infinity();
    if (m.mesh_loop) {
      follow = distance::closed_polyline_partial_hausdorff(
          curves[m.reference_loop], topology.boundary_loops[*m.mesh_loop].polyline(topology.points), follow_fraction);
    }
    check.follow_distances.push_back(follow);
    if (follow <= tolerance) {
      explained[*m.mesh_loop] = 1;
      continue;
    }
    if (mesh::closed_length(curves[m.reference_loop]) < min_resolvable_length) check.unresolved_curves.push_back(m.reference_loop);
    else check.missing_curves.push_back(m.reference_loop);
    if (is_left_out(curves[m.reference_loop])) check.left_out_curves.push_back(m.reference_loop);
  }
  for (std::size_t l = 0; l < explained.size(); ++l)
    if (!explained[l]) check.extra_loops.push_back(l);
  return check;
}

}  // namespace envcrust::analysis
