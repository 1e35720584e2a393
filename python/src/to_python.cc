#include "to_python.h"

#include "modaltyre/core/conditions.h"
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

py::object checked(const nlohmann::json& j) {
  report::check_finite(j);
  return to_python(j);
}

}  // namespace modaltyre::python
