#include "modaltyre/studies/sweep_spec.h"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <utility>

#include "modaltyre/core/conditions.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/csv.h"

namespace modaltyre::studies {

namespace {

namespace fs = std::filesystem;

int line_of(const YAML::Node& n) { return n.Mark().line >= 0 ? n.Mark().line + 1 : 0; }

SweepValue scalar_value(const YAML::Node& n) {
  SweepValue v;
  v.line = line_of(n);
  if (n.IsScalar()) {
    v.text = n.Scalar();
    v.number = parse_finite_double(v.text);
  } else {
    YAML::Emitter e;
    e << YAML::Flow << n;
    v.text = e.c_str();
  }
  YAML::Emitter e;
  e << n;
  v.yaml = e.c_str();
  return v;
}

// Flattens nested mappings of set: into dotted keys (`tread: {modulus_MPa: 8}` is
// `tread.modulus_MPa: 8`).
void flatten_set(const YAML::Node& node, const std::string& prefix, const std::string& file,
                 std::vector<SweepAssignment>& out) {
  for (const auto& kv : node) {
    const std::string key = prefix.empty() ? kv.first.Scalar() : prefix + "." + kv.first.Scalar();
    const int line = line_of(kv.first);
    if (kv.second.IsMap()) {
      flatten_set(kv.second, key, file, out);
      continue;
    }
    if (!kv.second || kv.second.IsNull()) {
      throw InputError({file, line, "set." + key}, "missing value");
    }
    for (const auto& other : out) {
      if (other.key == key) {  // "a.b: 1" and "a: {b: 2}" name one key
        throw InputError({file, line, "set." + key}, "key appears twice in set (first at line " +
                                                         std::to_string(other.where.line) + ")");
      }
    }
    SweepAssignment a;
    a.key = key;
    a.value = scalar_value(kv.second);
    a.where = {file, line, "set." + key};
    out.push_back(std::move(a));
  }
}

void flatten_grid(const YAML::Node& node, const std::string& prefix, const std::string& file,
                  std::vector<SweepAxis>& out) {
  for (const auto& kv : node) {
    const std::string key = prefix.empty() ? kv.first.Scalar() : prefix + "." + kv.first.Scalar();
    const InputLocation where{file, line_of(kv.first), "grid." + key};
    if (kv.second.IsMap()) {
      flatten_grid(kv.second, key, file, out);
      continue;
    }
    if (key == "loads_N") {
      throw InputError(where,
                       "sweep the vertical load with load_N (one load per case); "
                       "loads_N is the tyre config's list");
    }
    if (!kv.second.IsSequence()) {
      throw InputError(where, "expected a list of values, e.g. [1, 2, 3]");
    }
    if (kv.second.size() == 0) throw InputError(where, "empty list: give at least one value");
    for (const auto& other : out) {
      if (other.key == key) {
        throw InputError(where, "key appears twice in grid (first at line " +
                                    std::to_string(other.where.line) + ")");
      }
    }
    SweepAxis axis;
    axis.key = key;
    axis.where = where;
    axis.condition = is_sweep_condition(key);
    for (const auto& item : kv.second) {
      if (!item.IsScalar()) {
        throw InputError({file, line_of(item), where.key}, "every list item must be one value");
      }
      axis.values.push_back(scalar_value(item));
    }
    out.push_back(std::move(axis));
  }
}

// A condition value, named at the line of the value itself when it has one: a word of the
// catalogue's, or a finite number within its range (the range read_measurements() accepts, so
// that a sweep never writes a file that cannot be read back as measured data).
void check_condition(const ConditionInfo& info, const SweepValue& v, const InputLocation& where) {
  const InputLocation at{where.file, v.line > 0 ? v.line : where.line, where.key};
  if (const std::string why = footprint_refusal(info.id); !why.empty()) throw InputError(at, why);
  if (info.is_text()) {
    if (!info.value_of(v.text)) throw InputError(at, info.refusal(v.text));
    return;
  }
  if (!v.number)
    throw InputError(
        at, "expected a finite number, got '" + printable(v.text) + "'" + decimal_hint(v.text));
  if (!info.in_range(*v.number)) throw InputError(at, info.refusal(v.text));
}

}  // namespace

bool is_sweep_condition(const std::string& key) { return find_condition(key) != nullptr; }

namespace {

// A base that is itself a sweep file (its own base: and grid:) would be read as a tyre config
// and refused for what a config lacks ("modal.hammer_csv: required", issue 38): name it.
void refuse_sweep_as_base(const std::string& base, const InputLocation& where) {
  YAML::Node root;
  try {
    root = parse_yaml(read_yaml_file(base, "a YAML config"), base);
  } catch (const InputError&) {
    return;  // the config reader reports it with its own words
  }
  if (root && root.IsMap() && root["base"] && root["grid"]) {
    throw InputError(
        where, "'" + base +
                   "' is a sweep file (it has base: and grid:), not a tyre config; "
                   "give its base: (" +
                   printable(root["base"].IsScalar() ? root["base"].Scalar() : std::string("?")) +
                   "), or merge the two sweeps");
  }
}

}  // namespace

SweepSpec parse_sweep_spec(const std::string& yaml, const std::string& name,
                           const std::vector<std::string>& overrides) {
  YAML::Node root = parse_yaml(yaml, name);
  if (!root || root.IsNull()) {
    throw InputError({name, 1, ""}, "empty sweep file: expected base:, grid: and output:");
  }
  if (!root.IsMap()) throw InputError({name, 1, ""}, "top level must be a mapping of keys");
  const fs::path folder = fs::path(name).parent_path();
  auto resolve = [&](const std::string& p) {
    const fs::path path(p);
    return (path.is_absolute() ? path : folder / path).string();
  };

  SweepSpec spec;
  spec.file = name;
  bool have_base = false, have_grid = false;
  for (const auto& kv : root) {
    const std::string key = kv.first.Scalar();
    const InputLocation where{name, line_of(kv.first), key};
    if (key == "base") {
      if (!kv.second.IsScalar() || kv.second.Scalar().empty()) {
        throw InputError(where, "expected the path of a tyre config, e.g. ../sf350.yaml");
      }
      spec.base_config = resolve(kv.second.Scalar());
      spec.base_where = where;
      std::error_code ec;
      if (!fs::exists(spec.base_config, ec)) {
        throw InputError(where, "tyre config '" + spec.base_config + "' not found");
      }
      if (!fs::is_regular_file(spec.base_config, ec)) {
        throw InputError(where, "tyre config '" + spec.base_config +
                                    "' is not a regular file (a folder or device?)");
      }
      refuse_sweep_as_base(spec.base_config, where);
      have_base = true;
    } else if (key == "set") {
      if (kv.second.IsNull()) continue;
      if (!kv.second.IsMap())
        throw InputError(where, "expected a mapping of dotted keys to values");
      flatten_set(kv.second, "", name, spec.set);
    } else if (key == "grid") {
      if (!kv.second.IsMap()) {
        throw InputError(where, "expected a mapping of keys to lists, e.g. load_N: [2000, 4000]");
      }
      flatten_grid(kv.second, "", name, spec.grid);
      if (spec.grid.empty()) throw InputError(where, "empty grid: give at least one key");
      have_grid = true;
    } else if (key == "output") {
      if (!kv.second.IsScalar() || kv.second.Scalar().empty()) {
        throw InputError(where, "expected a CSV path");
      }
      spec.output = resolve(kv.second.Scalar());
      spec.output_where = where;
    } else {
      throw InputError(where, "unknown key (expected base, set, grid, output)");
    }
  }
  if (!have_base) throw InputError({name, 1, "base"}, "required: path of the tyre config");
  if (!have_grid) throw InputError({name, 1, "grid"}, "required: keys with lists of values");

  for (const auto& o : overrides) {
    const auto eq = o.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw InputError({"--set", 0, o}, "expected dotted.key=value");
    }
    SweepAssignment a;
    a.key = o.substr(0, eq);
    a.where = {"--set", 0, a.key};
    const YAML::Node n = parse_set_value(o.substr(eq + 1), a.key);
    if (!n || n.IsNull()) throw InputError(a.where, "missing value");
    a.value = scalar_value(n);
    a.value.line = 0;
    spec.set.push_back(std::move(a));
  }
  for (const auto& a : spec.set) {
    for (const auto& axis : spec.grid) {
      if (axis.key == a.key) {
        throw InputError(a.where, "also swept in grid: (line " + std::to_string(axis.where.line) +
                                      "); give it in one place only");
      }
    }
    if (const ConditionInfo* info = find_condition(a.key)) check_condition(*info, a.value, a.where);
  }
  for (const auto& axis : spec.grid) {
    if (!axis.condition) continue;
    for (const auto& v : axis.values) check_condition(*find_condition(axis.key), v, axis.where);
  }
  return spec;
}

SweepSpec read_sweep_spec(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_sweep_spec(read_yaml_file(path, "a sweep file"), path, overrides);
}

}  // namespace modaltyre::studies
