// The Python module `envcrust`: reconstruction, analysis, the built-in surfaces and the file
// formats of the library, on numpy arrays. Each binding lives in its own file.
#include "analyze_binding.h"
#include "exceptions.h"
#include "io_binding.h"
#include "reconstruct_binding.h"
#include "sample_binding.h"

#include <pybind11/pybind11.h>

PYBIND11_MODULE(envcrust, module) {
  module.doc() =
      "envcrust: reconstruction of surfaces with boundary from point samples, through their rho-envelope.\n\n"
      "reconstruct(points, normals=None, colors=None, **options) -> Reconstruction (vertices, faces, normals, "
      "colors, report)\nanalyze(vertices, faces) -> dict; sample(name, n) -> points; surfaces() -> dict\n"
      "read_points(path) -> dict; read_mesh(path) -> (vertices, faces); write_mesh(path, vertices, faces, "
      "colors=None)\nErrors: envcrust.Error and its subclasses, with the CLI's one-line messages.";
  envcrust::python::register_exceptions(module);
  envcrust::python::register_reconstruct(module);
  envcrust::python::register_analyze(module);
  envcrust::python::register_sample(module);
  envcrust::python::register_io(module);
  module.attr("__version__") = ENVCRUST_VERSION;
}
