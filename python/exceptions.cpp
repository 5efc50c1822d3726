// The module's exceptions and the translation of the library's errors into them.
#include "exceptions.h"

#include "envcrust/errors.h"

#include <exception>
#include <string>

namespace envcrust::python {
namespace py = pybind11;
namespace {

// A new exception class module.<name> with the given bases, kept for the module's lifetime
// (the translator below uses it at any time).
PyObject* add_class(py::module_& module, const char* name, std::initializer_list<PyObject*> bases,
                    const char* doc) {
  py::tuple base_tuple(bases.size());
  std::size_t i = 0;
  for (PyObject* base : bases) base_tuple[i++] = py::reinterpret_borrow<py::object>(base);
  PyObject* type = PyErr_NewExceptionWithDoc(("envcrust." + std::string(name)).c_str(), doc, base_tuple.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  module.add_object(name, py::handle(type));  // add_object takes a new reference; `type` keeps its own
  return type;
}

}  // namespace

void register_exceptions(py::module_& module) {
  static PyObject* const error =
      add_class(module, "Error", {PyExc_Exception}, "Base of every error envcrust raises; str() is a one-line message.");
  static PyObject* const invalid_input =
      add_class(module, "InvalidInput", {error, PyExc_ValueError},
                "The input is malformed (non-finite coordinates, bad indices, ...).");
  static PyObject* const degenerate_input =
      add_class(module, "DegenerateInput", {invalid_input},
                "The input is well formed but degenerate (too few points, all on a line, ...).");
  static PyObject* const invalid_options = add_class(
      module, "InvalidOptions", {error, PyExc_ValueError}, "An option has a value outside its range; the message names it.");
  static PyObject* const io_error =
      add_class(module, "IoError", {error, PyExc_OSError}, "Reading or writing a file failed; the message names the file.");
  static PyObject* const numerical_failure = add_class(module, "NumericalFailure", {error, PyExc_RuntimeError},
                                                       "A computation failed although the input was valid.");
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const DegenerateInput& e) {
      PyErr_SetString(degenerate_input, e.what());
    } catch (const InvalidInput& e) {
      PyErr_SetString(invalid_input, e.what());
    } catch (const InvalidOptions& e) {
      PyErr_SetString(invalid_options, e.what());
    } catch (const IoError& e) {
      PyErr_SetString(io_error, e.what());
    } catch (const NumericalFailure& e) {
      PyErr_SetString(numerical_failure, e.what());
    } catch (const Error& e) {
      PyErr_SetString(error, e.what());
    }
  });
}

}  // namespace envcrust::python
