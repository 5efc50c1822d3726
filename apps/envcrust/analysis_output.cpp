// JSON and text renderings of the analyzer's report.
#include "analysis_output.h"

#include "cli_common.h"

#include <ostream>

namespace envcrust::cli {
namespace {

nlohmann::json directed_json(const distance::DirectedDistance& d, double diag) {
  return {{"max", d.max},
          {"mean", d.mean},
          {"max_rel_diag", diag > 0 ? d.max / diag : 0.0},
          {"mean_rel_diag", diag > 0 ? d.mean / diag : 0.0},
          {"samples", d.samples},
          {"worst_point", {d.worst_point.x(), d.worst_point.y(), d.worst_point.z()}}};
}

std::string yes_no(bool b) { return b ? "yes" : "no"; }

}  // namespace

std::string knot_text(const knots::KnotReport& k) {
  if (k.type == knots::KnotType::Unknown)
    return "unknown (" + std::to_string(k.crossings) + " crossings in the simplest projection found: too many to read)";
  return knots::to_string(k.type) + " (Alexander " + k.alexander + ")";
}

nlohmann::json knot_json(const knots::KnotReport& k) {
  const bool read = k.type != knots::KnotType::Unknown;
  return {{"type", knots::to_string(k.type)},
          {"alexander", read ? nlohmann::json(k.alexander) : nlohmann::json(nullptr)},
          {"determinant", read ? nlohmann::json(k.determinant) : nlohmann::json(nullptr)},
          {"crossings", k.crossings},
          {"simplified_vertices", k.simplified_vertices},
          {"projections_agree", k.projections_agree}};
}

nlohmann::json analysis_json(const analysis::AnalysisReport& r) {
  const auto& t = r.topology;
  nlohmann::json j;
  j["vertices"] = t.vertices;
  j["faces"] = t.faces;
  j["edges"] = t.edges;
  j["input_vertices"] = t.input_vertices;
  j["welded_vertices"] = t.welded_vertices;
  j["unused_vertices"] = t.unused_vertices;
  j["components"] = t.components.size();
  j["is_manifold"] = t.is_manifold();
  j["is_closed"] = t.is_closed();
  j["non_manifold_edges"] = t.non_manifold_edges;
  j["non_manifold_vertices"] = t.non_manifold_vertices;
  j["boundary_edges"] = t.boundary_edges;
  j["degenerate_faces"] = t.degenerate_faces;
  j["duplicate_faces"] = t.duplicate_faces;
  j["misoriented_edges"] = t.misoriented_edges;
  j["euler_characteristic"] = t.euler_characteristic;
  j["is_orientable"] = t.is_orientable;
  j["boundary_loops"] = t.boundary_loops.size();
  if (r.self_intersections) {
    const auto& s = *r.self_intersections;
    nlohmann::json examples = nlohmann::json::array();
    for (const auto& p : s.examples) examples.push_back({p.x(), p.y(), p.z()});
    j["self_intersections"] = {{"face_pairs", s.face_pairs}, {"faces", s.faces}, {"examples", examples}};
    j["is_embedded"] = t.is_manifold() && s.face_pairs == 0;
  }
  nlohmann::json comps = nlohmann::json::array();
  for (const auto& c : t.components) {
    nlohmann::json cj = {{"vertices", c.vertices}, {"edges", c.edges}, {"faces", c.faces},
                         {"euler_characteristic", c.euler_characteristic},
                         {"boundary_loops", c.boundary_loops}, {"is_orientable", c.is_orientable},
                         {"is_manifold", c.is_manifold}};
    cj["genus"] = c.genus ? nlohmann::json(*c.genus) : nlohmann::json(nullptr);
    comps.push_back(cj);
  }
  j["component_list"] = comps;
  nlohmann::json loops = nlohmann::json::array();
  for (std::size_t i = 0; i < t.boundary_loops.size(); ++i) {
    const auto& l = t.boundary_loops[i];
    nlohmann::json lj = {{"vertices", l.vertices.size()}, {"length", l.length},
                         {"component", l.component}, {"is_oriented", l.is_oriented}};
    lj["knot"] = r.loops[i].knot ? knot_json(*r.loops[i].knot) : nlohmann::json(nullptr);
    loops.push_back(lj);
  }
  j["loops"] = loops;
  nlohmann::json links = nlohmann::json::array();
  for (const auto& l : r.linking)
    links.push_back({{"loops", {l.loop_a, l.loop_b}}, {"linking_number", l.linking_number},
                     {"is_signed", l.is_signed}});
  j["linking"] = links;
  if (r.distance) {
    const auto& d = *r.distance;
    j["distance"] = {{"reference_diagonal", d.reference_diagonal},
                     {"hausdorff", d.hausdorff},
                     {"hausdorff_rel_diag", d.relative(d.hausdorff)},
                     {"mesh_to_reference", directed_json(d.mesh_to_reference, d.reference_diagonal)},
                     {"reference_to_mesh", directed_json(d.reference_to_mesh, d.reference_diagonal)}};
  }
  if (!r.boundary_matches.empty()) {
    nlohmann::json matches = nlohmann::json::array();
    for (const auto& m : r.boundary_matches) {
      nlohmann::json mj = {{"reference_loop", m.reference_loop}};
      mj["mesh_loop"] = m.mesh_loop ? nlohmann::json(*m.mesh_loop) : nlohmann::json(nullptr);
      mj["hausdorff"] = m.mesh_loop ? nlohmann::json(m.hausdorff) : nlohmann::json(nullptr);
      if (m.mesh_loop && r.distance)
        mj["hausdorff_rel_diag"] = r.distance->relative(m.hausdorff);
      matches.push_back(mj);
    }
    j["boundary_matches"] = matches;
  }
  j["warnings"] = r.warnings;
  return j;
}

void print_analysis(std::ostream& out, const std::string& name, const analysis::AnalysisReport& r) {
  const auto& t = r.topology;
  out << name << ": " << t.vertices << " vertices, " << t.edges << " edges, " << t.faces
      << " faces, " << t.components.size() << " component" << (t.components.size() == 1 ? "" : "s") << "\n";
  out << "  manifold: " << yes_no(t.is_manifold()) << " (" << t.non_manifold_edges
      << " non-manifold edges, " << t.non_manifold_vertices << " non-manifold vertices), "
      << t.degenerate_faces << " degenerate faces, " << t.duplicate_faces << " duplicate faces\n";
  out << "  Euler characteristic " << t.euler_characteristic << ", orientable: " << yes_no(t.is_orientable)
      << ", boundary loops: " << t.boundary_loops.size() << "\n";
  if (r.self_intersections) {
    const auto& s = *r.self_intersections;
    out << "  self-intersections: ";
    if (s.face_pairs == 0)
      out << "none" << (t.is_manifold() ? " (an embedded surface)" : "") << "\n";
    else
      out << s.face_pairs << " pairs of faces pass through each other (" << s.faces << " faces), e.g. near ("
          << s.examples.front().x() << ", " << s.examples.front().y() << ", " << s.examples.front().z() << ")\n";
  }
  if (t.misoriented_edges > 0)
    out << "  faces not oriented alike: " << t.misoriented_edges << " edges that both their faces run the same way\n";
  if (t.welded_vertices > 0)
    out << "  " << t.welded_vertices << " vertices welded to another at the same position (counts are after "
        << "welding)\n";
  for (std::size_t c = 0; c < t.components.size() && c < 10; ++c) {
    const auto& comp = t.components[c];
    out << "  component " << c << ": chi " << comp.euler_characteristic << ", "
        << comp.boundary_loops << " loops, " << (comp.is_orientable ? "orientable" : "non-orientable");
    if (comp.genus) out << (comp.is_orientable ? ", genus " : ", cross-caps ") << *comp.genus;
    out << "\n";
  }
  if (t.components.size() > 10) out << "  ... " << t.components.size() - 10 << " more components\n";
  for (std::size_t i = 0; i < t.boundary_loops.size() && i < 20; ++i) {
    const auto& l = t.boundary_loops[i];
    out << "  loop " << i << ": " << l.vertices.size() << " vertices, length " << l.length;
    if (r.loops[i].knot) out << ", " << knot_text(*r.loops[i].knot);
    out << "\n";
  }
  for (const auto& l : r.linking)
    out << "  linking number of loops " << l.loop_a << " and " << l.loop_b << ": "
        << (l.is_signed ? "" : "|lk| = ") << l.linking_number << "\n";
  if (r.distance) {
    const auto& d = *r.distance;
    out << "  distance (reference diagonal " << d.reference_diagonal << "):\n"
        << "    mesh -> reference: max " << d.mesh_to_reference.max << " ("
        << percent(d.relative(d.mesh_to_reference.max)) << "), mean " << d.mesh_to_reference.mean << "\n"
        << "    reference -> mesh: max " << d.reference_to_mesh.max << " ("
        << percent(d.relative(d.reference_to_mesh.max)) << "), mean " << d.reference_to_mesh.mean << "\n"
        << "    Hausdorff " << d.hausdorff << " (" << percent(d.relative(d.hausdorff)) << ")\n";
  }
  for (const auto& m : r.boundary_matches) {
    out << "  reference boundary " << m.reference_loop << ": ";
    if (m.mesh_loop) {
      out << "nearest mesh loop " << *m.mesh_loop << " at Hausdorff " << m.hausdorff;
      if (r.distance) out << " (" << percent(r.distance->relative(m.hausdorff)) << ")";
    } else {
      out << "no mesh boundary loop";
    }
    out << "\n";
  }
  for (const auto& w : r.warnings) out << "  warning: " << w << "\n";
}

}  // namespace envcrust::cli
