// The module's exceptions, mirroring the library's (errors.h), and the translation of the
// library's errors into them, each keeping its one-line message.
#pragma once

#include <pybind11/pybind11.h>

namespace envcrust::python {

/// Adds envcrust.Error (base of all below), InvalidInput (also a ValueError), DegenerateInput
/// (an InvalidInput), InvalidOptions (a ValueError), IoError (an OSError) and NumericalFailure
/// (a RuntimeError) to `module`, and translates the library's exceptions into them.
void register_exceptions(pybind11::module_& module);

}  // namespace envcrust::python
