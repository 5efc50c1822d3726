// envcrust.reconstruct(): the input stage, the pipeline and the analysis, run as
// `envcrust reconstruct` runs them on a point file, on numpy arrays instead of files.
#include "reconstruct_binding.h"

#include "arrays.h"
#include "reconstruct_options.h"
#include "boundary_check_output.h"
#include "report_json.h"
#include "rho_support.h"
#include "run_progress.h"

#include "envcrust/attributes.h"
#include "envcrust/errors.h"
#include "envcrust/input.h"
#include "envcrust/mesh.h"
#include "envcrust/normals.h"
#include "envcrust/pipeline.h"

#include <tbb/global_control.h>

#include <atomic>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>

namespace envcrust::python {
namespace py = pybind11;
namespace {

/// What reconstruct() returns.
struct Reconstruction {
  py::object vertices, faces, normals, colors, report;
};

// One class number per point, as a float scalar named "classification" (what the library's
// classes choose from, and what read_points gives for a LAS file): whole numbers of any integer
// dtype, or floats with whole values such as read_points' float32 column.
std::vector<float> to_classification(const py::handle& object, std::size_t count) {
  py::array any;
  try {
    any = py::array::ensure(object);
  } catch (const py::error_already_set&) {
  }
  if (!any) throw py::value_error("classification must be an array of shape (n,)");
  if (any.ndim() != 1) {
    std::ostringstream shape;
    for (py::ssize_t d = 0; d < any.ndim(); ++d) shape << (d ? ", " : "") << any.shape(d);
    throw py::value_error("classification must be an array of shape (n,), got shape (" + shape.str() + ")");
  }
  const char kind = any.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::value_error("classification must hold whole numbers, got dtype " + py::str(any.dtype()).cast<std::string>());
  if (static_cast<std::size_t>(any.shape(0)) != count)
    throw py::value_error("classification must have " + std::to_string(count) + " values (one per point), got " +
                          std::to_string(any.shape(0)));
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(any);
  const auto r = values.unchecked<1>();
  std::vector<float> classes(count);
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    // Beyond 2^24 a float no longer holds every whole number, and two classes could merge.
    if (r(i) != std::floor(r(i)) || std::abs(r(i)) > 16777216.0) {
      std::ostringstream text;
      text << "classification: row " << i << " has " << r(i) << ", not a whole number within +-2^24";
      throw py::value_error(text.str());
    }
    classes[i] = static_cast<float>(r(i));
  }
  return classes;
}

// Runs a stage on the points, naming them at the head of what it refuses, as the CLI names
// its input file (cli::naming_input).
template <class Stage>
auto naming_points(Stage&& stage) {
  auto named = [](const std::string& what) { return what.rfind("points:", 0) == 0 ? what : "points: " + what; };
  try {
    return stage();
  } catch (const DegenerateInput& e) {
    throw DegenerateInput(named(e.what()));
  } catch (const NumericalFailure& e) {
    throw NumericalFailure(named(e.what()));
  } catch (const InvalidInput& e) {
    throw InvalidInput(named(e.what()));
  }
}

// The CLI's refusal of a given rho the sampling cannot support, in the module's words for its flags.
std::string refusal_text(const cli::RhoSupport& support) {
  std::string text = cli::rho_refusal("points", support);
  for (const auto& [flag, keyword] : {std::pair<std::string, std::string>{"--rho auto", "rho='auto'"},
                                      {"--rho ", "rho="},
                                      {"--force", "force=True"}})
    for (std::size_t at = text.find(flag); at != std::string::npos; at = text.find(flag, at + keyword.size()))
      text.replace(at, flag.size(), keyword);
  return text;
}

void check_rho(const ReconstructSettings& settings, const pipeline::ReconstructOptions& options,
               const envelope::SurfaceSamples& samples) {
  const auto& e = options.envelope;
  if (settings.force || !e.rho || options.method != pipeline::Method::Envelope ||
      e.rho_mode != envelope::RhoMode::Uniform || samples.points.size() < 2)
    return;
  const cli::RhoSupport support = cli::rho_support(samples, *e.rho, e.spacing_rel_rho);
  if (!support.is_supported()) throw InvalidInput(refusal_text(support));
}

// Why a run came out empty (the CLI's reasons, in the module's words for its options).
std::string empty_result_reason(const pipeline::ReconstructOptions& options, const envelope::SurfaceSamples& samples,
                                const envelope::EnvelopeSamples& e) {
  std::ostringstream reason;
  reason << "points: the reconstruction is empty";
  if (options.method != pipeline::Method::Envelope) return reason.str();
  const double diagonal = mesh::bbox_diagonal(samples.points);
  if (e.rho < e.min_rho_for_gaps)
    reason << ": rho " << e.rho << " is too small for the input's gaps (up to " << e.input_coverage << "); use rho="
           << e.min_rho_for_gaps << " or more, or input with gaps below " << e.input_coverage * e.rho / e.min_rho_for_gaps;
  else if (e.is_input_too_sparse)
    reason << ": the input is too sparse or noisy for its size (rho " << e.rho << " is " << std::setprecision(3)
           << 100.0 * e.rho / diagonal << "% of its diagonal); sample it denser";
  else if (e.rho > 0.25 * diagonal)
    reason << ": rho " << e.rho << " is more than a quarter of the input's size (diagonal " << diagonal
           << "), so its envelope is one blob around it; use a rho below " << 0.1 * diagonal << " (or rho='auto')";
  else
    reason << ": no piece of the medial sheet held together (rho " << e.rho << ", " << e.samples.size()
           << " envelope samples from " << samples.points.size() << " input points); try denser input";
  return reason.str();
}

// The analysis of the result against the input points, and its checks (the CLI's, for a
// point file without --reference).
RunChecks check_run(const input::PreparedInput& prepared, const pipeline::ReconstructResult& result) {
  RunChecks checks;
  checks.warnings = prepared.warnings;
  checks.warnings.insert(checks.warnings.end(), result.warnings.begin(), result.warnings.end());
  analysis::Reference reference;
  reference.points = prepared.samples.points;
  checks.analysis = result.topology ? analysis::analyze_mesh(result.mesh, *result.topology, reference)
                                    : analysis::analyze_mesh(result.mesh, reference);
  for (const auto& c : prepared.samples.boundary) checks.curves.push_back(c.polyline());
  pipeline::ResultChecks own =
      pipeline::check_result(*checks.analysis, prepared.samples, result, prepared.kind.is_boundary_detected);
  checks.boundary_check = std::move(own.boundary);
  checks.failed = std::move(own.failed);
  // As the CLI: said, not failed.
  checks.uncovered_patches = own.uncovered_patches;
  if (checks.uncovered_patches > 0) checks.warnings.push_back(cli::uncovered_patches_warning(checks.uncovered_patches));
  return checks;
}

// What a run computes without the GIL.
struct Run {
  input::PreparedInput prepared;
  pipeline::ReconstructOptions options;
  pipeline::ReconstructResult result;
  RunChecks checks;
  std::vector<Vector3> normals;  ///< per vertex, from the faces (as the CLI writes them)
  PointAttributes attributes;    ///< the nearest input point's, per vertex (colours when given)
  int threads = 0;
};

Run run(input::PointInput points, const ReconstructSettings& settings, const Progress& progress) {
  const auto thread_limit =
      settings.threads > 0 ? std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                                   static_cast<std::size_t>(settings.threads))
                           : nullptr;
  Run out;
  out.threads = static_cast<int>(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  out.prepared = input::prepare_points(std::move(points), settings.input, progress);
  out.options = options_for_run(settings, out.prepared.kind);
  check_rho(settings, out.options, out.prepared.samples);
  out.result = naming_points([&] { return pipeline::reconstruct(out.prepared.samples, out.options, progress); });
  if (out.result.mesh.triangles.empty())
    throw NumericalFailure(empty_result_reason(out.options, out.prepared.samples, out.result.envelope));
  progress.report("analysis", 0.0);
  if (settings.use_analysis) {
    out.checks = check_run(out.prepared, out.result);
  } else {
    out.checks.warnings = out.prepared.warnings;
    out.checks.warnings.insert(out.checks.warnings.end(), out.result.warnings.begin(), out.result.warnings.end());
  }
  out.normals = normals::mesh_vertex_normal_lines(out.result.mesh);
  out.attributes =
      attributes::carry_nearest(out.prepared.attribute_points, out.prepared.attributes, out.result.mesh.vertices);
  // Returned in the input's coordinates; the stages ran near a local origin (input::PreparedInput::origin).
  input::restore_origin(out.result.mesh.vertices, out.prepared.origin);
  progress.report("analysis", 1.0);
  return out;
}

Reconstruction reconstruct(const py::handle& points, const py::handle& normals, const py::handle& colors,
                           const py::handle& classification, const py::kwargs& keywords) {
  const ReconstructSettings settings = parse_reconstruct_keywords(keywords);
  input::PointInput input;
  input.points.points.points = to_points(points, "points");
  const std::size_t count = input.points.points.points.size();
  if (!normals.is_none()) {
    input.points.points.normals = to_vectors(normals, "normals");
    if (input.points.points.normals.size() != count)
      throw py::value_error("normals must have " + std::to_string(count) + " rows (one per point), got " +
                            std::to_string(input.points.points.normals.size()));
  }
  if (!colors.is_none()) input.points.attributes.colours = to_colours(colors, count);
  if (!classification.is_none()) {
    input.points.attributes.names.push_back("classification");
    input.points.attributes.scalars.push_back(to_classification(classification, count));
  }
  std::atomic<bool> cancel = false;
  const Progress progress = run_progress(settings.progress, cancel);
  Run done;
  {
    py::gil_scoped_release released;
    done = run(std::move(input), settings, progress);
  }
  Reconstruction out;
  out.vertices = points_array(done.result.mesh.vertices);
  out.faces = triangles_array(done.result.mesh.triangles);
  out.normals = vectors_array(done.normals);
  out.colors = done.attributes.has_colours() ? py::object(colours_array(done.attributes.colours)) : py::none();
  out.report = to_python(reconstruct_json(done.prepared, done.result, done.options, done.checks, done.threads));
  return out;
}

std::string describe(const Reconstruction& r) {
  const py::dict report = r.report;
  std::string text = "<envcrust.Reconstruction: " + std::to_string(py::len(r.vertices)) + " vertices, " +
                     std::to_string(py::len(r.faces)) + " faces";
  if (report.contains("analysis")) {
    const py::dict a = report["analysis"];
    text += ", chi " + py::str(a["euler_characteristic"]).cast<std::string>() + ", " +
            py::str(a["boundary_loops"]).cast<std::string>() + " boundary loops, " +
            (a["is_orientable"].cast<bool>() ? "orientable" : "non-orientable");
  }
  return text + ">";
}

}  // namespace

void register_reconstruct(py::module_& module) {
  py::class_<Reconstruction>(module, "Reconstruction",
                             "The result of reconstruct(): the mesh as numpy arrays, and the report.")
      .def_readonly("vertices", &Reconstruction::vertices, "n x 3 float64: the vertex positions")
      .def_readonly("faces", &Reconstruction::faces, "m x 3 int64: the triangles' vertex indices")
      .def_readonly("normals", &Reconstruction::normals,
                    "n x 3 float64: vertex normal lines from the faces (their sign flips across the seam of a "
                    "non-orientable result)")
      .def_readonly("colors", &Reconstruction::colors,
                    "n x 3 uint8: each vertex the colour of its nearest input point, when colors were given; else None")
      .def_readonly("report", &Reconstruction::report,
                    "dict: the report of `envcrust reconstruct --json` (envelope, seconds, analysis, boundary_check, "
                    "checks, warnings, ...)")
      .def("__repr__", &describe);
  module.def("reconstruct", &reconstruct, py::arg("points"), py::arg("normals") = py::none(),
             py::arg("colors") = py::none(), py::arg("classification") = py::none(),
             (std::string("Reconstruct a surface (with boundary) from points sampled on it, as `envcrust reconstruct` "
                          "does from a point file.\n\n"
                          "points: n x 3 array; normals: n x 3 (any sign, optional: estimated when None); colors: n x 3, "
                          "0..255 integers or 0..1 floats (optional; carried to the nearest output vertices); "
                          "classification: n class numbers (optional; classes= keeps some of them, as --classes "
                          "does with a LAS file's).\n"
                          "Returns a Reconstruction. Raises envcrust.Error subclasses with the CLI's messages "
                          "(InvalidInput and InvalidOptions are ValueErrors), ValueError for arrays of the wrong shape, "
                          "TypeError for an unknown option, KeyboardInterrupt on Ctrl-C (checked between the steps).\n") +
              kReconstructKeywordsDoc)
                 .c_str());
}

}  // namespace envcrust::python
