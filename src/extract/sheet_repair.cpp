// The repairs of the cleaned sheet: orientation seams, balls that are not discs, faces that
// pass through each other; each closes the holes it leaves (docs/method.md §8.6-8.7).
#include "sheet_repair.h"

#include "sheet_projection.h"

#include "envcrust/mesh.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace envcrust::extract {
namespace {

// Notches a cut leaves in the rim (CutHoleOptions::close_cut_notches), in rho: border vertices
// within kNotchOnCurve of a curve lie on it (snapped ones lie on it exactly); a notch reaches
// kNotchMinDepth in (a cut ball of 0.5 rho, the self-intersection cut's, reaches about that
// far), and spans at most kNotchMaxWidth along the curve (a handle ball of 1.5 rho: 3 rho).
constexpr double kNotchOnCurve = 0.1;
constexpr double kNotchMinDepth = 0.25;
constexpr double kNotchMaxWidth = 4.0;
// A self-intersection cut round that leaves no fewer pairs is retried with twice the radius,
// up to this many times the first radius. Measured on the face scan's points:
// at 0.5 rho a round left its 84 pairs, at 1 rho none.
constexpr double kMaxCutWidening = 4.0;
// A border loop runs along a boundary curve when half its vertices lie within this many rho
// of one (fill_loops_away_from_boundary, drop_pieces_away_from_boundary).
constexpr double kOnCurveRelRho = 2.0;

// Pinholes fanned, then (with fill_cut_holes) the holes away from the boundary curves closed
// with discs, optionally once the pieces cut off from every curve are dropped, and the
// notches in the rim closed.
CutHoleStats close_holes(TaggedMesh& sheet, const RepairSite& site, const CutHoleOptions& options,
                         bool drop_cut_off_pieces) {
  CutHoleStats s;
  s.small_holes_filled = fill_small_holes(sheet, site, options.fill_loops_shorter_than_rel_rho);
  if (!options.fill_cut_holes) return s;
  const double on_curve = kOnCurveRelRho * site.rho;
  if (drop_cut_off_pieces) s.components_dropped += drop_pieces_away_from_boundary(sheet, site.boundary_points, on_curve);
  s.discs = fill_loops_away_from_boundary(sheet, site.boundary_points, on_curve, HoleFill::Patch);
  // A cut that reached the rim opened a notch in it rather than a hole: closed back to the
  // curve (a disc glued along an arc of the border: the topology stays).
  if (options.close_cut_notches)
    s.notches_closed = close_border_notches(sheet, site.surface, kNotchOnCurve * site.rho, kNotchMinDepth * site.rho,
                                            kNotchMaxWidth * site.rho);
  return s;
}

// The text a cut's warning ends with.
std::string discs_said(const CutHoleStats& holes) {
  if (holes.discs == 0) return "";
  return "; " + std::to_string(holes.discs) + " hole" + (holes.discs == 1 ? "" : "s") + " closed with a disc";
}

}  // namespace

CutHoleStats& CutHoleStats::operator+=(const CutHoleStats& o) {
  components_dropped += o.components_dropped;
  small_holes_filled += o.small_holes_filled;
  discs += o.discs;
  notches_closed += o.notches_closed;
  return *this;
}

RepairSite make_repair_site(const envelope::EnvelopeSamples& envelope, const envelope::SurfaceSamples& surface,
                            const NearestIndex& samples, const std::vector<double>& max_component_distance) {
  RepairSite site{.surface = surface, .samples = samples, .max_component_distance = max_component_distance,
                  .boundary_points = {}, .rho = envelope.rho, .local_rho = {}};
  for (const auto& c : surface.boundary)
    for (const auto& b : c.vertices) site.boundary_points.push_back(b.position);
  if (envelope.local_rho.size() == surface.points.size())
    site.local_rho = [&envelope, &samples](const Point3& p) { return envelope.local_rho[samples.nearest(p).first]; };
  return site;
}

std::size_t fill_small_holes(TaggedMesh& sheet, const RepairSite& site, double max_length_rel_rho) {
  if (!(max_length_rel_rho > 0)) return 0;
  if (!site.local_rho) return fill_short_loops(sheet, max_length_rel_rho * site.rho);
  return fill_short_loops(sheet, max_length_rel_rho, site.local_rho);
}

CutHoleStats close_cut_holes(TaggedMesh& sheet, const RepairSite& site, const CutHoleOptions& options) {
  CutHoleStats s;
  s.components_dropped =
      filter_components(sheet, site.samples, site.max_component_distance, options.min_component_area_fraction);
  s += close_holes(sheet, site, options, true);
  // The repair can open holes of its own where it removes faces or splits a vertex:
  // pinholes, fanned too, and slits (on the bunny's ear tip a 4-vertex loop 23 mm long and
  // under 1 mm wide), closed like the cut holes.
  const ManifoldRepairStats repaired = make_manifold(sheet);
  if (repaired.faces_dropped + repaired.non_manifold_faces_removed + repaired.degenerate_faces_removed +
          repaired.vertices_split > 0) {
    s += close_holes(sheet, site, options, false);
    make_manifold(sheet);
  }
  return s;
}

OrientationRepairStats repair_orientation(TaggedMesh& sheet, const RepairSite& site,
                                          const OrientationRepairOptions& options, const CutHoleOptions& holes,
                                          std::vector<std::string>& warnings) {
  OrientationRepairStats s;
  s.cut = cut_to_orientable(sheet, options.cut_rel_rho * site.rho, options.max_twist_loop_rel_rho * site.rho);
  if (s.cut.twists_kept > 0) {
    std::ostringstream w;
    w << "the sheet has " << s.cut.twists_kept << " orientation-reversing twist" << (s.cut.twists_kept == 1 ? "" : "s")
      << " that no loop shorter than " << std::setprecision(3) << options.max_twist_loop_rel_rho
      << " rho reverses: kept as part of the surface (a Moebius strip's twist), not cut";
    warnings.push_back(w.str());
  }
  if (s.cut.seams > 0) {
    s.holes = close_cut_holes(sheet, site, holes);
    warnings.push_back("the sheet was non-orientable: " + std::to_string(s.cut.faces_removed) +
                       " faces removed around " + std::to_string(s.cut.seams) + " orientation seam" +
                       (s.cut.seams == 1 ? "" : "s") +
                       (s.cut.still_non_orientable ? "; still non-orientable after 3 rounds" : "") +
                       discs_said(s.holes));
  }
  return s;
}

HandleRepairStats repair_handles(TaggedMesh& sheet, const RepairSite& site, const HandleRepairOptions& options,
                                 const CutHoleOptions& holes, std::vector<std::string>& warnings) {
  HandleRepairStats s;
  s.cut = cut_local_handles(sheet, options.radius_rel_rho * site.rho);
  if (s.cut.balls > 0) {
    s.holes = close_cut_holes(sheet, site, holes);
    std::ostringstream w;
    w << "the sheet was not a disc in " << s.cut.balls << " ball" << (s.cut.balls == 1 ? "" : "s") << " of radius "
      << options.radius_rel_rho << " rho: " << s.cut.faces_removed << " faces removed there" << discs_said(s.holes);
    warnings.push_back(w.str());
  }
  return s;
}

SelfIntersectionRepairStats repair_self_intersections(TaggedMesh& sheet, const RepairSite& site,
                                                      const SelfIntersectionRepairOptions& options,
                                                      const CutHoleOptions& holes, std::vector<std::string>& warnings) {
  SelfIntersectionRepairStats s;
  // Relaxed first: most folds open without losing faces; what is left is cut out and the
  // holes closed with discs, in rounds (below).
  mesh::SelfIntersections found = mesh::self_intersections(sheet.mesh, 0);
  s.found = found.face_pairs;
  if (found.face_pairs > 0) {
    found = smooth_self_intersections(sheet.mesh, std::move(found), 3);
    s.smoothed = s.found - std::min(s.found, found.face_pairs);
    s.cut = found.face_pairs;
    // Each round cuts, closes the holes, then checks what that made: the cut removed every
    // face that passed through another, so only the faces the repairs and discs made can
    // now. A round is kept only when it leaves fewer pairs than it found. A round that would
    // leave less than 3/4 of the faces is undone too: a sheet that crosses itself nearly
    // everywhere (an input far too sparse for its size) is kept rather than cut away, and
    // the report says so.
    const std::size_t faces_at_start = sheet.mesh.triangles.size(), to_cut = found.face_pairs;
    const int max_rounds = std::max(1, options.rounds);
    // A round that leaves no fewer pairs is tried again with twice the radius (the discs
    // closing a small cut can pass through the folds around it; a wider cut takes them in),
    // up to kMaxCutWidening times the radius.
    double radius = options.cut_rel_rho * site.rho;
    const double max_radius = kMaxCutWidening * radius;
    while (found.face_pairs > 0 && s.rounds < max_rounds) {
      TaggedMesh previous = sheet;
      const std::size_t removed_now = cut_self_intersections(sheet, found, radius).faces_removed;
      s.holes += close_cut_holes(sheet, site, holes);
      if (4 * sheet.mesh.triangles.size() < 3 * faces_at_start) {
        sheet = std::move(previous);
        if (s.rounds == 0)
          warnings.push_back("the sheet passes through itself at " + std::to_string(to_cut) +
                             " face pairs, too many to cut out (" + std::to_string(removed_now) + " of " +
                             std::to_string(faces_at_start) + " faces): left as it is");
        break;
      }
      const std::vector<char> made = faces_not_in(sheet.mesh, previous.mesh);
      mesh::SelfIntersections left =
          smooth_self_intersections(sheet.mesh, mesh::self_intersections(sheet.mesh, 0, &made), 3);
      if (left.face_pairs >= found.face_pairs) {
        sheet = std::move(previous);
        if (2 * radius > max_radius) break;
        radius *= 2;
        ++s.widenings;
        continue;
      }
      found = std::move(left);
      s.faces_removed += removed_now;
      ++s.rounds;
    }
    if (s.rounds == 0) s.cut = 0;
  }
  s.left = found.face_pairs;
  if (s.found > 0) {
    std::ostringstream w;
    w << "the sheet passed through itself at " << s.found << " face pairs: relaxed there"
      << (s.cut > 0 ? ", then " + std::to_string(s.faces_removed) + " faces removed around the " +
                          std::to_string(s.cut) + " pairs that was not enough for, and the holes closed (" +
                          std::to_string(s.rounds) + " round" + (s.rounds == 1 ? "" : "s") + ")"
                    : std::string());
    warnings.push_back(w.str());
  }
  return s;
}

}  // namespace envcrust::extract
