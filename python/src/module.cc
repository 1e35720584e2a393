// The extension modaltyre._modaltyre: errors, then the bound functions (bindings.h).
// Library InputError -> modaltyre.InputError (a ValueError), ComputationError ->
// modaltyre.ComputationError (a RuntimeError), with the CLI's message.
#include "bindings.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::python {
namespace {

// The exception instance carries the location as attributes file, line, key.
void raise_input_error(PyObject* type, const InputError& e) {
  py::object err = py::reinterpret_borrow<py::object>(type)(e.what());
  err.attr("file") = e.where().file;
  err.attr("line") = e.where().line;
  err.attr("key") = e.where().key;
  PyErr_SetObject(type, err.ptr());
}

}  // namespace
}  // namespace modaltyre::python

PYBIND11_MODULE(_modaltyre, m) {
  namespace py = pybind11;
  using namespace modaltyre::python;
  m.doc() =
      "ModalTyre: tyre-road contact from experimental modal parameters (seed 001) and "
      "rheological identification (seed 000).";
  static py::exception<modaltyre::InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<modaltyre::ComputationError> computation_error(m, "ComputationError",
                                                                      PyExc_RuntimeError);
  input_error.doc() =
      "Bad input: the message names file, line and key as the CLI's (exit code 2); attributes "
      "file, line (0: not tied to a line), key.";
  computation_error.doc() =
      "A computation failed (no convergence, with its residual), as the CLI's exit code 1.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const modaltyre::InputError& e) {
      raise_input_error(input_error.ptr(), e);
    } catch (const modaltyre::ComputationError& e) {
      computation_error(e.what());
    }
  });
  bind_tyre(m);
  bind_studies(m);
  bind_identify(m);
}
