// envcrust.analyze(): topology, boundary knots, linking and (against reference points) distances.
#include "analyze_binding.h"

#include "arrays.h"
#include "report_json.h"

#include "envcrust/analysis.h"

namespace envcrust::python {
namespace py = pybind11;
namespace {

py::object analyze(const py::handle& vertices, const py::handle& faces, const py::handle& reference, bool use_knots) {
  TriangleMesh mesh;
  mesh.vertices = to_points(vertices, "vertices");
  mesh.triangles = to_triangles(faces, mesh.vertices.size());
  analysis::Reference given;
  if (!reference.is_none()) given.points = to_points(reference, "reference");
  analysis::AnalyzeOptions options;
  options.use_knots = use_knots;
  analysis::AnalysisReport report;
  {
    py::gil_scoped_release released;
    report = analysis::analyze_mesh(mesh, given, options);
  }
  return to_python(analysis_json(report));
}

}  // namespace

void register_analyze(py::module_& module) {
  module.def("analyze", &analyze, py::arg("vertices"), py::arg("faces"), py::kw_only(),
             py::arg("reference") = py::none(), py::arg("knots") = true,
             "Analyze a triangle mesh as `envcrust analyze --json` does.\n\n"
             "vertices: n x 3; faces: m x 3 vertex indices; reference: optional k x 3 points to measure distances "
             "to; knots: read the knot type of each boundary loop.\nReturns a dict with the CLI's keys: "
             "euler_characteristic, boundary_loops, is_orientable, components, genus, is_manifold, is_closed, "
             "vertices, edges, faces, loops (length, knot), linking, component_list, self_intersections, "
             "distance (with a reference), warnings.");
}

}  // namespace envcrust::python
