#pragma once
// The parts of shockfield._core, one function per file (docs/python.md).
#include <pybind11/pybind11.h>

namespace shockfield::python {

void bind_analysis(pybind11::module_& m);  // analysis_bindings.cpp

}  // namespace shockfield::python
