#pragma once
// Conversions between the library's JSON documents and Python objects, and the NumPy arrays the
// module returns. Every array owns its memory (a copy): no view outlives the C++ object it
// would point into.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/report/condition_settings.h"

namespace modaltyre::python {

namespace py = pybind11;

/// The JSON document as Python objects: dict, list, str, int, float, bool, None.
py::object to_python(const nlohmann::json& j);

/// A float64 array owning a copy of `values`.
py::array_t<double> owned_array(const std::vector<double>& values);

/// A float64 array of one member of every element of a JSON array of objects
/// (e.g. the units' x_mm of a footprint case).
py::array_t<double> column_of(const nlohmann::json& rows, const std::string& key);

/// A float64 array of a JSON array of numbers, or a 2D array of a JSON array of equal-length
/// arrays of numbers (a pressure map).
py::array numeric_array(const nlohmann::json& j);

/// `{key: value}` as the "key=value" overrides of the command line's --set (YAML text:
/// true/false, numbers as Python writes them, lists as [a, b]).
std::vector<std::string> overrides_of(const py::dict& overrides);

/// `{name: value}` operating conditions (hold_s=60, surface='soil'): the names, ranges and words
/// of the catalogue (core/conditions.h) and the CLI's checks of `--set name=value`, errors at
/// "conditions" (InputError, a name that is no condition included).
std::vector<report::ConditionSetting> conditions_of(const py::dict& conditions);

/// A path argument: a str or an os.PathLike (pathlib.Path); anything else is an InputError
/// naming the Python argument `name`.
std::string path_arg(const py::handle& v, const char* name);

/// An optional path argument: None gives "".
std::string optional_path_arg(const py::handle& v, const char* name);

/// A number argument: an int or a float (NumPy scalars included), finite; a bool (True is an
/// int in Python, never a load) or anything else is an InputError naming `name`.
double number_arg(const py::handle& v, const char* name);

/// An int argument in [lo, hi] (a Python int of any size, NumPy integers not taken): a bool, a
/// float or an int outside the range is an InputError naming `name`.
long long int_arg(const py::handle& v, const char* name, long long lo, long long hi);

/// None or number_arg.
std::optional<double> optional_number_arg(const py::handle& v, const char* name);

/// A sequence of number_arg (a str is not a sequence of numbers).
std::vector<double> numbers_arg(const py::handle& v, const char* name);

/// A thread count as the CLI's --threads takes it: None (every core) or an int in [1, 4096].
std::optional<int> threads_arg(const py::handle& v, const char* name);

/// Checks the document for non-finite numbers (as the CLI does) and converts it.
py::object checked(const nlohmann::json& j);

}  // namespace modaltyre::python
