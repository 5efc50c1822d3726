// envcrust.sample() and envcrust.surfaces(): points of the built-in surfaces, and what each is.
#include "sample_binding.h"

#include "arrays.h"

#include "envcrust/surfaces.h"

#include <pybind11/stl.h>

namespace envcrust::python {
namespace py = pybind11;
namespace {

py::object sample(const std::string& name, std::size_t count, std::uint64_t seed, double noise, bool with_normals) {
  const auto surface = surfaces::make_builtin(name);
  surfaces::SampleOptions options;
  options.count = count;
  options.seed = seed;
  options.noise_rel_diag = noise;
  options.with_normals = with_normals;
  PointSet points;
  {
    py::gil_scoped_release released;
    points = surfaces::sample_surface(*surface, options);
  }
  if (!with_normals) return points_array(points.points);
  return py::make_tuple(points_array(points.points), vectors_array(points.normals));
}

py::dict listing() {
  py::dict out;
  for (const auto& name : surfaces::builtin_names()) {
    const auto surface = surfaces::make_builtin(name);
    const auto t = surface->expected_topology();
    py::dict expected;
    expected["euler_characteristic"] = t.euler_characteristic;
    expected["boundary_loops"] = t.boundary_loops;
    expected["is_orientable"] = t.is_orientable;
    expected["boundary_knots"] = t.boundary_knots;
    expected["abs_linking_number"] = t.abs_linking_number;
    py::dict entry;
    entry["description"] = surface->description();
    entry["expected"] = expected;
    out[py::str(name)] = entry;
  }
  return out;
}

}  // namespace

void register_sample(py::module_& module) {
  module.def("sample", &sample, py::arg("name"), py::arg("n") = 10000, py::kw_only(), py::arg("seed") = 1,
             py::arg("noise") = 0.0, py::arg("normals") = false,
             "Points drawn uniformly by area from a built-in surface (the points of `envcrust sample NAME -n N "
             "--seed S`).\n\nname: see surfaces(); n: how many; seed: same seed, same points; noise: Gaussian, a "
             "fraction of the diagonal.\nReturns an n x 3 float64 array, or (points, normals) with normals=True. "
             "Raises envcrust.InvalidInput for an unknown name (naming the known ones), envcrust.InvalidOptions for "
             "n = 0.");
  module.def("surfaces", &listing,
             "The built-in surfaces: name -> {description, expected: {euler_characteristic, boundary_loops, "
             "is_orientable, boundary_knots, abs_linking_number}}.");
}

}  // namespace envcrust::python
