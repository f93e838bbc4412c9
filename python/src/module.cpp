// shockfield._core: the pybind11 module behind `import shockfield` (docs/python.md). The C++
// errors become the Python exceptions of shockfield.errors carrying the same message the
// command line prints: InputError -> shockfield.InputError (a ValueError), RunError ->
// shockfield.RunError (a RuntimeError), StopRequested -> shockfield.StopRequested.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "shockfield/core/error.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  m.doc() = "shockfield's C++ library; use it through the package `shockfield`";
  m.attr("__version__") = SHOCKFIELD_VERSION;
  // Kept alive by the module's attributes for as long as the interpreter runs.
  const py::module_ errors = py::module_::import("shockfield.errors");
  m.attr("_errors") = errors;
  static PyObject* input_error = errors.attr("InputError").ptr();
  static PyObject* run_error = errors.attr("RunError").ptr();
  static PyObject* stop_requested = errors.attr("StopRequested").ptr();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const shockfield::InputError& e) {
      PyErr_SetString(input_error, e.what());
    } catch (const shockfield::RunError& e) {
      PyErr_SetString(run_error, e.what());
    } catch (const shockfield::StopRequested& e) {
      PyErr_SetString(stop_requested, e.what());
    }
  });
  shockfield::python::bind_analysis(m);
  shockfield::python::bind_simulation(m);
  shockfield::python::bind_atoms(m);
  shockfield::python::bind_geometry(m);
  shockfield::python::bind_data(m);
}
