// The reports the module returns. The run's stages and the boundary check use the CLI's own
// JSON builders (apps/envcrust/reconstruct_output.cpp, boundary_check_output.cpp); the
// analysis is written here with the CLI's keys, as the CLI's builder sits beside its text
// output and that needs the CLI's terminal helpers.
#include "report_json.h"

#include "boundary_check_output.h"
#include "reconstruct_output.h"

namespace envcrust::python {
namespace py = pybind11;
namespace {

nlohmann::json point_json(const Point3& p) { return {p.x(), p.y(), p.z()}; }

nlohmann::json directed_json(const distance::DirectedDistance& d, double diagonal) {
  return {{"max", d.max},
          {"mean", d.mean},
          {"max_rel_diag", diagonal > 0 ? d.max / diagonal : 0.0},
          {"mean_rel_diag", diagonal > 0 ? d.mean / diagonal : 0.0},
          {"samples", d.samples},
          {"worst_point", point_json(d.worst_point)}};
}

nlohmann::json knot_json(const knots::KnotReport& k) {
  const bool is_read = k.type != knots::KnotType::Unknown;
  return {{"type", knots::to_string(k.type)},
          {"alexander", is_read ? nlohmann::json(k.alexander) : nlohmann::json(nullptr)},
          {"determinant", is_read ? nlohmann::json(k.determinant) : nlohmann::json(nullptr)},
          {"crossings", k.crossings},
          {"simplified_vertices", k.simplified_vertices},
          {"projections_agree", k.projections_agree}};
}

nlohmann::json optional_json(const auto& value) { return value ? nlohmann::json(*value) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json analysis_json(const analysis::AnalysisReport& r) {
  const auto& t = r.topology;
  nlohmann::json j = {{"vertices", t.vertices},
                      {"faces", t.faces},
                      {"edges", t.edges},
                      {"input_vertices", t.input_vertices},
                      {"welded_vertices", t.welded_vertices},
                      {"unused_vertices", t.unused_vertices},
                      {"components", t.components.size()},
                      {"is_manifold", t.is_manifold()},
                      {"is_closed", t.is_closed()},
                      {"non_manifold_edges", t.non_manifold_edges},
                      {"non_manifold_vertices", t.non_manifold_vertices},
                      {"boundary_edges", t.boundary_edges},
                      {"degenerate_faces", t.degenerate_faces},
                      {"duplicate_faces", t.duplicate_faces},
                      {"misoriented_edges", t.misoriented_edges},
                      {"euler_characteristic", t.euler_characteristic},
                      {"is_orientable", t.is_orientable},
                      {"boundary_loops", t.boundary_loops.size()},
                      {"genus", optional_json(topology::total_genus(t))}};
  if (r.self_intersections) {
    const auto& s = *r.self_intersections;
    nlohmann::json examples = nlohmann::json::array();
    for (const auto& p : s.examples) examples.push_back(point_json(p));
    j["self_intersections"] = {{"face_pairs", s.face_pairs}, {"faces", s.faces}, {"examples", examples}};
    j["is_embedded"] = t.is_manifold() && s.face_pairs == 0;
  }
  j["component_list"] = nlohmann::json::array();
  for (const auto& c : t.components)
    j["component_list"].push_back({{"vertices", c.vertices},
                                   {"edges", c.edges},
                                   {"faces", c.faces},
                                   {"euler_characteristic", c.euler_characteristic},
                                   {"boundary_loops", c.boundary_loops},
                                   {"is_orientable", c.is_orientable},
                                   {"is_manifold", c.is_manifold},
                                   {"genus", optional_json(c.genus)}});
  j["loops"] = nlohmann::json::array();
  for (std::size_t i = 0; i < t.boundary_loops.size(); ++i) {
    const auto& l = t.boundary_loops[i];
    j["loops"].push_back({{"vertices", l.vertices.size()},
                          {"length", l.length},
                          {"component", l.component},
                          {"is_oriented", l.is_oriented},
                          {"knot", r.loops[i].knot ? knot_json(*r.loops[i].knot) : nlohmann::json(nullptr)}});
  }
  j["linking"] = nlohmann::json::array();
  for (const auto& l : r.linking)
    j["linking"].push_back(
        {{"loops", {l.loop_a, l.loop_b}}, {"linking_number", l.linking_number}, {"is_signed", l.is_signed}});
  if (r.distance) {
    const auto& d = *r.distance;
    j["distance"] = {{"reference_diagonal", d.reference_diagonal},
                     {"hausdorff", d.hausdorff},
                     {"hausdorff_rel_diag", d.relative(d.hausdorff)},
                     {"mesh_to_reference", directed_json(d.mesh_to_reference, d.reference_diagonal)},
                     {"reference_to_mesh", directed_json(d.reference_to_mesh, d.reference_diagonal)}};
  }
  j["warnings"] = r.warnings;
  return j;
}

nlohmann::json reconstruct_json(const input::PreparedInput& prepared, const pipeline::ReconstructResult& result,
                                const pipeline::ReconstructOptions& options, const RunChecks& checks, int threads) {
  nlohmann::json j = {{"input", "points"},
                      {"source", "points"},
                      {"input_points", prepared.samples.points.size()},
                      {"input_boundary_curves", prepared.samples.boundary.size()},
                      {"input_outliers_removed", prepared.outliers.size()},
                      {"notes", prepared.notes}};
  j.update(cli::run_stages_json(result, options));
  j["threads"] = threads;
  if (prepared.origin != CGAL::NULL_VECTOR)
    j["input_origin"] = {prepared.origin.x(), prepared.origin.y(), prepared.origin.z()};
  if (prepared.detection && !prepared.detection->loop_widths.empty())
    j["input_boundary_widths"] = prepared.detection->loop_widths;
  if (checks.analysis) {
    j["reference"] = "input points";
    j["analysis"] = analysis_json(*checks.analysis);
  }
  if (checks.boundary_check && checks.analysis)
    j["boundary_check"] = cli::boundary_check_json(*checks.boundary_check, checks.curves, checks.analysis->topology);
  if (checks.analysis)
    j["checks"] = {
        {"passed", checks.failed.empty()}, {"failed", checks.failed}, {"uncovered_patches", checks.uncovered_patches}};
  j["warnings"] = checks.warnings;
  return j;
}

py::object to_python(const nlohmann::json& document) {
  switch (document.type()) {
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [key, value] : document.items()) out[py::str(key)] = to_python(value);
      return out;
    }
    case nlohmann::json::value_t::array: {
      py::list out;
      for (const auto& value : document) out.append(to_python(value));
      return out;
    }
    case nlohmann::json::value_t::string:
      return py::str(document.get_ref<const std::string&>());
    case nlohmann::json::value_t::boolean:
      return py::bool_(document.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(document.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(document.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(document.get<double>());
    default:
      return py::none();
  }
}

}  // namespace envcrust::python
