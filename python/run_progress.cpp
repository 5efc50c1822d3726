// The Progress a run gets from Python: Ctrl-C and the user's callable, checked between steps.
#include "run_progress.h"

#include <string>

namespace envcrust::python {
namespace py = pybind11;

Progress run_progress(py::handle callback, std::atomic<bool>& cancel) {
  Progress progress;
  progress.cancel = &cancel;
  progress.callback = [callback, &cancel](std::string_view stage, double fraction) {
    py::gil_scoped_acquire gil;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!callback.is_none()) callback(std::string(stage), fraction);
    } catch (const py::error_already_set&) {
      cancel = true;
      throw;
    }
  };
  return progress;
}

}  // namespace envcrust::python
