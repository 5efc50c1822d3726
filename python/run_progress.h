// The Progress a run gets from Python: the stages run without the GIL, and each report takes
// it back to check for Ctrl-C and call the user's callable.
#pragma once

#include "envcrust/progress.h"

#include <pybind11/pybind11.h>

#include <atomic>

namespace envcrust::python {

/// A Progress whose reports (made by the stages between their steps, on the calling thread)
/// take the GIL, run Python's signal handlers (PyErr_CheckSignals: Ctrl-C raises
/// KeyboardInterrupt) and call `callback(stage, fraction)` unless it is None. When either
/// raises, `cancel` is set and the Python exception is thrown through the stages as
/// pybind11::error_already_set, which ends the run and reaches the caller unchanged.
/// `callback` must outlive the run (the caller holds it); it is not reference-counted here,
/// as the stages copy the Progress without the GIL.
Progress run_progress(pybind11::handle callback, std::atomic<bool>& cancel);

}  // namespace envcrust::python
