#include "to_python.h"

#include <cmath>

#include "modaltyre/core/conditions.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/report/check_finite.h"

namespace modaltyre::python {

py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = to_python(it.value());
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& e : j) l.append(to_python(e));
      return l;
    }
    case nlohmann::json::value_t::string:
      return py::str(j.get<std::string>());
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    default:
      return py::none();
  }
}

py::array_t<double> owned_array(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

py::array_t<double> column_of(const nlohmann::json& rows, const std::string& key) {
  std::vector<double> v;
  for (const auto& r : rows) v.push_back(r.at(key).get<double>());
  return owned_array(v);
}

py::array numeric_array(const nlohmann::json& j) {
  if (!j.empty() && j.front().is_array()) {
    const auto rows = static_cast<py::ssize_t>(j.size());
    const auto cols = static_cast<py::ssize_t>(j.front().size());
    py::array_t<double> a({rows, cols});
    auto m = a.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < rows; ++i) {
      MODALTYRE_CHECK(static_cast<py::ssize_t>(j[i].size()) == cols, "ragged numeric array");
      for (py::ssize_t k = 0; k < cols; ++k) m(i, k) = j[i][k].get<double>();
    }
    return a;
  }
  return owned_array(j.get<std::vector<double>>());
}

namespace {

std::string yaml_text(const py::handle& v) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    std::string s = "[";
    for (const auto& e : v) s += (s.size() > 1 ? ", " : "") + yaml_text(e);
    return s + "]";
  }
  return py::str(v).cast<std::string>();
}

}  // namespace

std::vector<std::string> overrides_of(const py::dict& overrides) {
  std::vector<std::string> out;
  for (const auto& [k, v] : overrides)
    out.push_back(py::str(k).cast<std::string>() + "=" + yaml_text(v));
  return out;
}

std::vector<report::ConditionSetting> conditions_of(const py::dict& conditions) {
  std::vector<std::string> assignments = overrides_of(conditions);
  auto settings = report::take_condition_settings(assignments, "conditions");
  if (!assignments.empty()) {
    const std::string& a = assignments.front();
    std::string names;
    for (const auto& c : condition_catalogue()) names += (names.empty() ? "" : ", ") + c.name;
    throw InputError({"conditions", 0, a.substr(0, a.find('='))},
                     "not an operating condition; the conditions are " + names +
                         " (config keys go in overrides)");
  }
  return settings;
}

namespace {

std::string type_name(const py::handle& v) {
  return py::str(py::type::of(v).attr("__name__")).cast<std::string>();
}

}  // namespace

namespace {

// A NUL ends a path for the operating system: "new.yaml\0.csv" would name new.yaml (Python's own
// open() refuses it the same way).
std::string without_nul(std::string path, const char* name) {
  if (path.find('\0') != std::string::npos) {
    throw InputError({name, 0, ""}, "'" + printable(path) +
                                        "' contains a NUL byte, which no path can hold (it "
                                        "would end the path there)");
  }
  return path;
}

}  // namespace

std::string path_arg(const py::handle& v, const char* name) {
  if (py::isinstance<py::str>(v)) return without_nul(v.cast<std::string>(), name);
  if (py::hasattr(v, "__fspath__")) {
    const py::object p = py::module_::import("os").attr("fspath")(v);
    if (py::isinstance<py::str>(p)) return without_nul(p.cast<std::string>(), name);
  }
  throw InputError({name, 0, ""}, "must be a path (str or pathlib.Path), got " + type_name(v));
}

std::string optional_path_arg(const py::handle& v, const char* name) {
  return v.is_none() ? std::string() : path_arg(v, name);
}

double number_arg(const py::handle& v, const char* name) {
  // bool is an int in Python (and numpy.bool_ has __float__): True is never a load.
  const std::string type = type_name(v);
  if (type == "bool" || type == "bool_" || py::isinstance<py::str>(v) ||
      !(py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v) ||
        py::hasattr(v, "__float__"))) {
    throw InputError({name, 0, ""}, "must be a number, got " + type + " " +
                                        printable(py::repr(v).cast<std::string>()));
  }
  double x = 0;
  try {
    x = py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
  } catch (py::error_already_set& e) {
    // An int past the largest double (10**400) cannot be a float: a number out of any range.
    if (!e.matches(PyExc_OverflowError)) throw;
    throw InputError({name, 0, ""}, "must be a finite number; " +
                                        printable(py::repr(v).cast<std::string>(), 40) +
                                        " is too large for one");
  }
  if (!std::isfinite(x)) throw InputError({name, 0, ""}, "must be a finite number");
  return x;
}

long long int_arg(const py::handle& v, const char* name, long long lo, long long hi) {
  // bool is an int in Python: True is never a count or an order.
  const std::string type = type_name(v);
  if (type == "bool" || type == "bool_" || !py::isinstance<py::int_>(v)) {
    throw InputError({name, 0, ""}, "must be an int, got " + type + " " +
                                        printable(py::repr(v).cast<std::string>(), 40));
  }
  int overflow = 0;
  const long long k = PyLong_AsLongLongAndOverflow(v.ptr(), &overflow);
  if (overflow == 0 && k == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (overflow != 0 || k < lo || k > hi) {
    throw InputError({name, 0, ""}, printable(py::repr(v).cast<std::string>(), 40) +
                                        " is outside " + std::to_string(lo) + "-" +
                                        std::to_string(hi));
  }
  return k;
}

std::optional<double> optional_number_arg(const py::handle& v, const char* name) {
  if (v.is_none()) return std::nullopt;
  return number_arg(v, name);
}

std::vector<double> numbers_arg(const py::handle& v, const char* name) {
  if (py::isinstance<py::str>(v) || !py::hasattr(v, "__iter__")) {
    throw InputError({name, 0, ""}, "must be a sequence of numbers, got " + type_name(v));
  }
  std::vector<double> out;
  for (const auto& item : v) out.push_back(number_arg(item, name));
  return out;
}

std::optional<int> threads_arg(const py::handle& v, const char* name) {
  if (v.is_none()) return std::nullopt;
  const double x = number_arg(v, name);
  if (x != std::floor(x) || x < 1 || x > 4096) {
    throw InputError({name, 0, ""}, py::str(v).cast<std::string>() +
                                        " is not a thread count in [1, 4096] (the CLI's "
                                        "--threads range; None: every core)");
  }
  return static_cast<int>(x);
}

py::object checked(const nlohmann::json& j) {
  report::check_finite(j);
  return to_python(j);
}

}  // namespace modaltyre::python
