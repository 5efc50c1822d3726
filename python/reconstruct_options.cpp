// The keyword options of envcrust.reconstruct(): each names a library option, bound as the
// CLI binds its flag (apps/envcrust/cmd_reconstruct.cpp), with the same defaults.
#include "reconstruct_options.h"

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <vector>

namespace envcrust::python {
namespace py = pybind11;
namespace {

std::string shown(const py::handle& value) { return py::repr(value).cast<std::string>(); }

double positive(const py::handle& value, const char* name, bool zero_allowed) {
  const double x = value.cast<double>();
  if (!std::isfinite(x) || x < 0 || (x == 0 && !zero_allowed))
    throw py::value_error(std::string(name) + " must be a number " + (zero_allowed ? ">= 0" : "> 0") + " (got " +
                          shown(value) + ")");
  return x;
}

std::string one_of(const py::handle& value, const char* name, std::initializer_list<const char*> choices) {
  const std::string text = value.cast<std::string>();
  std::string listed;
  for (const char* c : choices) {
    if (text == c) return text;
    listed += (listed.empty() ? "'" : ", '") + std::string(c) + "'";
  }
  throw py::value_error(std::string(name) + " must be one of " + listed + " (got " + shown(value) + ")");
}

// A class number as the CLI's --classes takes it: a whole number in 0..255 (LAS classes are a
// byte); numpy's integers count, bools and floats do not.
bool is_class_number(const py::handle& value) {
  if (py::isinstance<py::bool_>(value) || !PyIndex_Check(value.ptr())) return false;
  const long long n = py::int_(py::reinterpret_borrow<py::object>(value)).cast<long long>();
  return n >= 0 && n <= 255;
}

// None: every point; one class number or a sequence of them (list, tuple, numpy array).
std::vector<int> class_list(const py::handle& value) {
  if (value.is_none()) return {};
  const auto refused = [&] {
    return py::value_error("classes must be a class number or a list of them, whole numbers in 0..255; None keeps "
                           "every point (got " + shown(value) + ")");
  };
  if (is_class_number(value)) return {py::int_(py::reinterpret_borrow<py::object>(value)).cast<int>()};
  if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) || !py::isinstance<py::iterable>(value))
    throw refused();
  std::vector<int> classes;
  for (const py::handle item : value) {
    if (!is_class_number(item)) throw refused();
    classes.push_back(py::int_(py::reinterpret_borrow<py::object>(item)).cast<int>());
  }
  // The library reads an empty list as every point; asked for no class, a user means none.
  if (classes.empty()) throw refused();
  return classes;
}

using Setter = std::function<void(ReconstructSettings&, const py::handle&)>;

const std::map<std::string, Setter>& setters() {
  static const std::map<std::string, Setter> all = {
      {"rho",
       [](ReconstructSettings& s, const py::handle& v) {
         if (v.is_none() || (py::isinstance<py::str>(v) && v.cast<std::string>() == "auto")) {
           s.options.envelope.rho.reset();
           return;
         }
         const double rho = py::isinstance<py::str>(v) || py::isinstance<py::bool_>(v) ? -1.0 : v.cast<double>();
         if (!(rho > 0) || !std::isfinite(rho))
           throw py::value_error("rho must be 'auto', None or a positive number (got " + shown(v) + ")");
         s.options.envelope.rho = rho;
       }},
      {"rho_adaptive",
       [](ReconstructSettings& s, const py::handle& v) {
         s.options.envelope.rho_mode = v.cast<bool>() ? envelope::RhoMode::Adaptive : envelope::RhoMode::Uniform;
       }},
      {"spacing", [](ReconstructSettings& s, const py::handle& v) { s.options.envelope.spacing_rel_rho = positive(v, "spacing", false); }},
      {"seed",
       [](ReconstructSettings& s, const py::handle& v) {
         if (py::isinstance<py::bool_>(v) || !py::isinstance<py::int_>(v) || v.cast<py::int_>() < py::int_(0))
           throw py::value_error("seed must be a whole number >= 0 (got " + shown(v) + ")");
         s.options.envelope.seed = v.cast<std::uint64_t>();
       }},
      {"threads",
       [](ReconstructSettings& s, const py::handle& v) {
         if (py::isinstance<py::bool_>(v) || !py::isinstance<py::int_>(v) || v.cast<long long>() < 0)
           throw py::value_error("threads must be a whole number >= 0, 0 for every core (got " + shown(v) + ")");
         s.threads = static_cast<int>(std::min<long long>(v.cast<long long>(), std::numeric_limits<int>::max()));
       }},
      {"method",
       [](ReconstructSettings& s, const py::handle& v) {
         s.options.method = one_of(v, "method", {"envelope", "powercrust"}) == "envelope" ? pipeline::Method::Envelope
                                                                                          : pipeline::Method::PowerCrust;
       }},
      {"extract",
       [](ReconstructSettings& s, const py::handle& v) {
         s.extract = v.is_none() ? "" : one_of(v, "extract", {"sheet", "samples", "powershape"});
         s.options.extraction = s.extract == "powershape" ? pipeline::Extraction::PowerShape : pipeline::Extraction::Sheet;
       }},
      {"orientable",
       [](ReconstructSettings& s, const py::handle& v) {
         if (py::isinstance<py::bool_>(v))
           s.orientable = v.cast<bool>() ? "yes" : "no";
         else
           s.orientable = one_of(v, "orientable", {"auto", "yes", "no"});
       }},
      {"cut_handles",
       [](ReconstructSettings& s, const py::handle& v) {
         if (v.is_none())
           s.cut_handles.reset();
         else
           s.cut_handles = positive(v, "cut_handles", true);
       }},
      {"remesh", [](ReconstructSettings& s, const py::handle& v) { s.use_remesh = v.cast<bool>(); }},
      {"adaptive_retry", [](ReconstructSettings& s, const py::handle& v) { s.use_adaptive_retry = v.cast<bool>(); }},
      {"power_crust_fallback",
       [](ReconstructSettings& s, const py::handle& v) { s.use_power_crust_fallback = v.cast<bool>(); }},
      {"keep_outliers", [](ReconstructSettings& s, const py::handle& v) { s.input.use_outlier_removal = !v.cast<bool>(); }},
      {"detect_boundary",
       [](ReconstructSettings& s, const py::handle& v) { s.input.use_boundary_detection = v.cast<bool>(); }},
      {"boundary_min_width",
       [](ReconstructSettings& s, const py::handle& v) {
         s.input.boundary.min_loop_width = positive(v, "boundary_min_width", true);
       }},
      {"classes", [](ReconstructSettings& s, const py::handle& v) { s.input.classes = class_list(v); }},
      {"creases",
       [](ReconstructSettings& s, const py::handle& v) {
         s.input.creases = one_of(v, "creases", {"round", "join"}) == "join" ? input::CreaseMode::Join
                                                                              : input::CreaseMode::Round;
       }},
      {"force", [](ReconstructSettings& s, const py::handle& v) { s.force = v.cast<bool>(); }},
      {"analysis", [](ReconstructSettings& s, const py::handle& v) { s.use_analysis = v.cast<bool>(); }},
      {"progress",
       [](ReconstructSettings& s, const py::handle& v) {
         if (!v.is_none() && !PyCallable_Check(v.ptr()))
           throw py::type_error("progress must be a callable (stage, fraction) or None (got " + shown(v) + ")");
         s.progress = py::reinterpret_borrow<py::object>(v);
       }},
  };
  return all;
}

}  // namespace

const char* const kReconstructKeywordsDoc = R"(
Options (keywords; the defaults are those of `envcrust reconstruct`):
  rho=None                  envelope radius; None or 'auto': chosen from the samples
  rho_adaptive=False        let rho vary over the surface (--rho-adaptive)
  spacing=0.25              envelope sample spacing, a fraction of rho
  seed=1                    seed of the envelope's thinning
  threads=0                 threads to run on; 0: every core
  method='envelope'         or 'powercrust' (plain Power Crust: closes every boundary)
  extract=None              'sheet', 'samples' (the points meshed along the sheet) or 'powershape';
                            None: as the CLI chooses for a point file
  orientable='auto'         'yes' (True): cut out twists; 'no' (False): never
  cut_handles=None          cut handles narrower than this many rho; None: 1.5 for point clouds
  remesh=False              remesh the result isotropically
  adaptive_retry=True       try a local rho first, rerun with adaptive rho when a run fails its checks
  power_crust_fallback=True try the plain Power Crust when the envelope's result fails its checks
                            (and first, on input without boundary curves)
  keep_outliers=False       keep the stray samples that are otherwise removed
  detect_boundary=True      False: the surface is closed (--no-boundary)
  boundary_min_width=0      drop detected loops narrower than this many sample spacings
  classes=None              keep only the points of these classes, e.g. [2, 6] (needs classification=);
                            None: every point
  creases='round'           or 'join': sharp creases of points with normals
  force=False               run a given rho the sampling cannot support
  analysis=True             False: no analysis and no checks in the report
  progress=None             callable(stage: str, fraction: float), called between steps
)";

ReconstructSettings parse_reconstruct_keywords(const py::kwargs& keywords) {
  ReconstructSettings settings;
  settings.input.name = "points";
  for (const auto& [key, value] : keywords) {
    const std::string name = key.cast<std::string>();
    const auto setter = setters().find(name);
    if (setter == setters().end())
      throw py::type_error("reconstruct() got an unexpected keyword argument '" + name + "'");
    try {
      setter->second(settings, value);
    } catch (const py::cast_error&) {
      throw py::type_error(name + " has the wrong type (got " + shown(value) + ")");
    }
  }
  return settings;
}

pipeline::ReconstructOptions options_for_run(const ReconstructSettings& settings, const pipeline::InputKind& kind) {
  pipeline::ReconstructOptions options = settings.options;
  if (settings.use_remesh) options.remesh = remesh::RemeshOptions{};
  options = pipeline::options_for_input(kind, options);
  if (settings.extract == "samples") options.mesh_samples = interpolate::InterpolateOptions{};
  if (settings.extract == "sheet") options.mesh_samples.reset();
  auto& sheet = options.sheet;
  if (settings.orientable == "yes") {
    sheet.cut_to_orientable = true;
    sheet.orientable_max_twist_loop_rel_rho = std::numeric_limits<double>::infinity();
  } else if (settings.orientable == "no") {
    sheet.cut_to_orientable = false;
  }
  if (settings.cut_handles) sheet.cut_handles_rel_rho = *settings.cut_handles;
  if (!settings.use_adaptive_retry)
    options.use_adaptive_retry = options.use_local_rho_first = options.use_power_crust_first = false;
  if (!settings.use_power_crust_fallback) options.use_power_crust_fallback = options.use_power_crust_first = false;
  if (options.method == pipeline::Method::Envelope && options.extraction == pipeline::Extraction::Sheet) return options;
  if (settings.orientable == "yes" || settings.cut_handles.value_or(0) > 0)
    throw py::value_error("orientable and cut_handles apply to the medial sheet (method='envelope', extract='sheet')");
  sheet.cut_to_orientable = false;
  sheet.cut_handles_rel_rho = 0;
  return options;
}

}  // namespace envcrust::python
