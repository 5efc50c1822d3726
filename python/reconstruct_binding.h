// envcrust.reconstruct(): points (and normals, colours) in, a Reconstruction out.
#pragma once

#include <pybind11/pybind11.h>

namespace envcrust::python {

/// Adds the class Reconstruction and the function reconstruct() to `module`.
void register_reconstruct(pybind11::module_& module);

}  // namespace envcrust::python
