// envcrust.sample() and envcrust.surfaces(): the built-in test surfaces.
#pragma once

#include <pybind11/pybind11.h>

namespace envcrust::python {

/// Adds sample and surfaces to `module`.
void register_sample(pybind11::module_& module);

}  // namespace envcrust::python
