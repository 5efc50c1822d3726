// envcrust.read_points(), read_mesh() and write_mesh(): the library's file formats (io.h).
#pragma once

#include <pybind11/pybind11.h>

namespace envcrust::python {

/// Adds read_points, read_mesh and write_mesh to `module`.
void register_io(pybind11::module_& module);

}  // namespace envcrust::python
