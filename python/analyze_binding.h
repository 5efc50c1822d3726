// envcrust.analyze(): the analyzer's report of a mesh given as arrays.
#pragma once

#include <pybind11/pybind11.h>

namespace envcrust::python {

/// Adds analyze to `module`.
void register_analyze(pybind11::module_& module);

}  // namespace envcrust::python
