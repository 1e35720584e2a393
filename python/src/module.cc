// The extension modaltyre._modaltyre: errors, then the bound functions (bindings.h).
// Library InputError -> modaltyre.InputError (a ValueError), ComputationError ->
// modaltyre.ComputationError (a RuntimeError), with the CLI's message.
#include <algorithm>
#include <map>
#include <regex>
#include <string>

#include "bindings.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::python {
namespace {

// The Python argument a command-line option stands for: the library's shared checks
// (report/) name the CLI's options, which a Python caller never typed (issue 38).
std::string python_name(const std::string& option) {
  static const std::map<std::string, std::string> special = {{"--load", "load_N"},
                                                             {"--fx", "horizontal_force_N"},
                                                             {"--set", "overrides"},
                                                             {"--threads", "threads"}};
  if (const auto it = special.find(option); it != special.end()) return it->second;
  std::string name = option.substr(2);
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

// Every "--option" in a message (at its start or after a blank, a bracket or a quote, so that
// a file name with "--" in it is left alone), as its Python argument.
std::string python_names(const std::string& text) {
  static const std::regex option("(^|[\\s(`'\"])(--[A-Za-z][A-Za-z0-9-]*)");
  std::string out;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), option);
       it != std::sregex_iterator(); ++it) {
    const auto at = static_cast<std::size_t>(it->position(2));
    out += text.substr(last, at - last) + python_name(it->str(2));
    last = at + static_cast<std::size_t>(it->length(2));
  }
  return out + text.substr(last);
}

// The exception instance carries the location as attributes file, line, key.
void raise_input_error(PyObject* type, const InputError& e) {
  InputLocation where = e.where();
  std::string message = e.what();
  const std::string prefix = format_location(where, "");
  const std::string tail = message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
  if (where.file.rfind("--", 0) == 0) where.file = python_name(where.file);
  message = format_location(where, python_names(tail));
  py::object err = py::reinterpret_borrow<py::object>(type)(message);
  err.attr("file") = where.file;
  err.attr("line") = where.line;
  err.attr("key") = where.key;
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
  bind_traction(m);
  bind_init(m);
}
