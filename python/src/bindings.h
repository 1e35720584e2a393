#pragma once
// The parts of the Python module, each registering its functions and classes.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

namespace modaltyre::python {

namespace py = pybind11;

void bind_tyre(py::module_& m);      // Tyre, Footprint, fit_modes
void bind_studies(py::module_& m);   // validate, sweep, transient, effects, discover
void bind_identify(py::module_& m);  // identify
void bind_traction(py::module_& m);  // traction
void bind_init(py::module_& m);      // init

}  // namespace modaltyre::python
