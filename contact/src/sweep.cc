#include "modaltyre/contact/sweep.h"

#include <omp.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <new>
#include <sstream>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/csv.h"

namespace modaltyre::contact {
namespace {

namespace fs = std::filesystem;

// At most this many cases in one sweep (a typo such as a 1e6-long list is caught before the
// machine runs out of memory).
constexpr std::size_t kMaxCases = 10'000'000;

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
      throw InputError(where, "sweep the vertical load with load_N (one load per case); "
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

// A condition value: a finite number, and a load must be positive.
void check_condition(const std::string& key, const SweepValue& v, const InputLocation& where) {
  const InputLocation at{where.file, v.line > 0 ? v.line : where.line, where.key};
  if (!v.number) throw InputError(at, "expected a finite number, got '" + v.text + "'");
  if (key == "load_N" && !(*v.number > 0)) {
    throw InputError(at, "every load must be greater than 0 N, got " + v.text);
  }
  if (std::abs(*v.number) > 1e7) throw InputError(at, "value " + v.text + " is out of range");
}

// The message of an InputError without its "file:line: key: " prefix.
std::string bare_message(const InputError& e) {
  const std::string prefix = format_location(e.where(), "");
  const std::string all = e.what();
  return all.rfind(prefix, 0) == 0 ? all.substr(prefix.size()) : all;
}

}  // namespace

bool is_sweep_condition(const std::string& key) {
  return key == "load_N" || key == "horizontal_force_N";
}

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
      if (!fs::is_regular_file(spec.base_config, ec)) {
        throw InputError(where, "tyre config '" + spec.base_config + "' not found");
      }
      have_base = true;
    } else if (key == "set") {
      if (kv.second.IsNull()) continue;
      if (!kv.second.IsMap()) throw InputError(where, "expected a mapping of dotted keys to values");
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
    YAML::Node n;
    try {
      n = YAML::Load(o.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw InputError(a.where, "cannot parse value '" + o.substr(eq + 1) + "': " + e.msg);
    }
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
    if (is_sweep_condition(a.key)) check_condition(a.key, a.value, a.where);
  }
  for (const auto& axis : spec.grid) {
    if (!axis.condition) continue;
    for (const auto& v : axis.values) check_condition(axis.key, v, axis.where);
  }
  return spec;
}

SweepSpec read_sweep_spec(const std::string& path, const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError({path, 0, ""}, "file not found");
  if (fs::is_directory(path, ec)) throw InputError({path, 0, ""}, "is a directory, not a sweep file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "cannot open file for reading");
  std::stringstream buf;
  buf << in.rdbuf();
  return parse_sweep_spec(buf.str(), path, overrides);
}

SweepPlan plan_sweep(const SweepSpec& spec) {
  SweepPlan plan;
  plan.spec = spec;
  const std::size_t n_axes = spec.grid.size();

  std::size_t total = 1;
  for (const auto& axis : spec.grid) {
    if (total > kMaxCases / axis.values.size()) {
      throw InputError(axis.where, "the grid has more than " + std::to_string(kMaxCases) +
                                       " cases; split the sweep");
    }
    total *= axis.values.size();
  }

  // Conditions given once for every case (last assignment wins: the file's set:, then --set).
  std::optional<SweepValue> set_load, set_fx;
  std::vector<const SweepAssignment*> params;  // config overrides for every case
  for (const auto& a : spec.set) {
    if (a.key == "load_N") {
      set_load = a.value;
    } else if (a.key == "horizontal_force_N") {
      set_fx = a.value;
    } else {
      params.push_back(&a);
    }
  }
  int load_axis = -1, fx_axis = -1;
  std::vector<int> param_axes;
  for (std::size_t k = 0; k < n_axes; ++k) {
    if (spec.grid[k].key == "load_N") {
      load_axis = static_cast<int>(k);
    } else if (spec.grid[k].key == "horizontal_force_N") {
      fx_axis = static_cast<int>(k);
    } else {
      param_axes.push_back(static_cast<int>(k));
    }
  }
  if (load_axis < 0 && !set_load) {
    throw InputError({spec.file, spec.grid.front().where.line, "load_N"},
                     "required: give the vertical load load_N in grid: or set:");
  }

  if (load_axis < 0) {
    plan.columns.push_back("load_N");
    plan.column_axis.push_back(-1);
  }
  for (std::size_t k = 0; k < n_axes; ++k) {
    plan.columns.push_back(spec.grid[k].key);
    plan.column_axis.push_back(static_cast<int>(k));
  }

  // Distinct parameter combinations: odometer over the parameter axes, last fastest.
  std::size_t n_combos = 1;
  for (int k : param_axes) n_combos *= spec.grid[k].values.size();
  std::vector<std::size_t> combo_model(n_combos);
  std::map<std::vector<std::string>, std::size_t> seen;
  for (std::size_t c = 0; c < n_combos; ++c) {
    std::vector<std::size_t> digit(param_axes.size());
    std::size_t rest = c;
    for (std::size_t p = param_axes.size(); p-- > 0;) {
      const std::size_t n = spec.grid[param_axes[p]].values.size();
      digit[p] = rest % n;
      rest /= n;
    }
    std::vector<std::string> overrides;
    std::vector<InputLocation> origin;
    for (const auto* a : params) {
      overrides.push_back(a->key + "=" + a->value.yaml);
      origin.push_back(a->where);
    }
    for (std::size_t p = 0; p < param_axes.size(); ++p) {
      const SweepAxis& axis = spec.grid[param_axes[p]];
      const SweepValue& v = axis.values[digit[p]];
      overrides.push_back(axis.key + "=" + v.yaml);
      origin.push_back({axis.where.file, v.line > 0 ? v.line : axis.where.line, axis.where.key});
    }
    const auto [it, inserted] = seen.emplace(overrides, plan.models.size());
    combo_model[c] = it->second;
    if (!inserted) continue;
    try {
      plan.models.push_back(read_tyre_config(ConfigTree::load(spec.base_config, overrides)));
    } catch (const InputError& e) {
      if (e.where().file != "--set") throw;  // a problem of the base config itself
      // Name the sweep line that set the offending key.
      const std::string& bad = e.where().key;
      for (std::size_t i = overrides.size(); i-- > 0;) {
        const std::string key = overrides[i].substr(0, overrides[i].find('='));
        if (key == bad || bad.rfind(key + ".", 0) == 0 || key.rfind(bad + ".", 0) == 0) {
          std::string msg = bare_message(e);
          if (origin[i].file != "--set" && key != bad) msg = bad + ": " + msg;
          throw InputError(origin[i], msg);
        }
      }
      throw;
    }
    plan.model_overrides.push_back(std::move(overrides));
  }

  // Every case: odometer over all axes, last fastest.
  plan.cases.resize(total);
  for (std::size_t i = 0; i < total; ++i) {
    SweepCase& sc = plan.cases[i];
    sc.value_index.resize(n_axes);
    std::size_t rest = i;
    for (std::size_t k = n_axes; k-- > 0;) {
      const std::size_t n = spec.grid[k].values.size();
      sc.value_index[k] = rest % n;
      rest /= n;
    }
    std::size_t combo = 0;
    for (int k : param_axes) combo = combo * spec.grid[k].values.size() + sc.value_index[k];
    sc.model = combo_model[combo];
    sc.load.load_N = load_axis >= 0 ? *spec.grid[load_axis].values[sc.value_index[load_axis]].number
                                    : *set_load->number;
    sc.load.horizontal_force_N =
        fx_axis >= 0 ? *spec.grid[fx_axis].values[sc.value_index[fx_axis]].number
        : set_fx     ? *set_fx->number
                     : plan.models[sc.model].horizontal_force_N;
  }
  return plan;
}

std::vector<std::string> SweepPlan::cells(std::size_t i) const {
  const SweepCase& sc = cases.at(i);
  std::vector<std::string> out;
  out.reserve(columns.size());
  for (int k : column_axis) {
    if (k < 0) {
      out.push_back(sweep_number(sc.load.load_N));
      continue;
    }
    const SweepValue& v = spec.grid[k].values[sc.value_index[k]];
    out.push_back(v.number ? sweep_number(*v.number) : csv_field(v.text));
  }
  return out;
}

namespace {

SweepRow row_from(const FootprintResult& r) {
  SweepRow row;
  row.iterations = r.iterations;
  if (!r.converged) {
    row.message = r.message.empty() ? "did not converge" : r.message;
    return row;
  }
  row.ok = true;
  row.sinking_mm = r.sinking_m * 1e3;
  row.length_mm = r.contact_length_m * 1e3;
  row.vertical_stiffness_N_mm = r.load.load_N / row.sinking_mm;
  double peak = 0;
  for (const auto& u : r.units) peak = std::max(peak, u.pressure_Pa);
  row.peak_pressure_kPa = peak * 1e-3;
  return row;
}

SweepRow failed_row(const std::string& why) {
  SweepRow row;
  row.message = why;
  return row;
}

// One distinct model, built for one batch and released after it.
struct ModelSlot {
  std::unique_ptr<TyreModel> model;
  std::vector<char> warm;       // reference contact set (empty: cold starts)
  std::string error;            // reason the model could not be built
  std::exception_ptr input_error;
};

}  // namespace

SweepResult run_sweep(const SweepPlan& plan, const SweepOptions& options) {
  SweepResult result;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  result.threads = threads;
  result.rows.resize(plan.cases.size());

  std::vector<std::vector<std::size_t>> cases_of(plan.models.size());
  for (std::size_t i = 0; i < plan.cases.size(); ++i) cases_of[plan.cases[i].model].push_back(i);

  // Models are built and used in batches of `threads` (each holds dense m x m matrices: only a
  // few are alive at once, however many parameter combinations the grid has).
  const std::size_t batch = static_cast<std::size_t>(std::max(threads, 1));
  for (std::size_t first = 0; first < plan.models.size(); first += batch) {
    const std::size_t count = std::min(batch, plan.models.size() - first);
    std::vector<ModelSlot> slots(count);

#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (std::size_t s = 0; s < count; ++s) {
      ModelSlot& slot = slots[s];
      const std::size_t mi = first + s;
      try {
        slot.model = std::make_unique<TyreModel>(build_tyre_model(plan.models[mi]));
        if (options.warm_start && !cases_of[mi].empty()) {
          // Fixed reference: the median-load case of this model, solved cold.
          std::vector<std::size_t> by_load = cases_of[mi];
          std::sort(by_load.begin(), by_load.end(), [&](std::size_t a, std::size_t b) {
            const auto& la = plan.cases[a].load;
            const auto& lb = plan.cases[b].load;
            return la.load_N != lb.load_N ? la.load_N < lb.load_N : a < b;
          });
          const auto ref = solve_footprint(*slot.model, plan.cases[by_load[by_load.size() / 2]].load);
          if (ref.converged) slot.warm = ref.active;
        }
      } catch (const InputError&) {
        slot.input_error = std::current_exception();
      } catch (const std::bad_alloc&) {
        slot.model.reset();
        slot.error = "model not built: out of memory";
      } catch (const std::exception& e) {
        slot.model.reset();
        slot.error = std::string("model not built: ") + e.what();
      }
    }
    for (const auto& slot : slots) {
      if (slot.input_error) std::rethrow_exception(slot.input_error);
    }

    std::vector<std::size_t> pending;
    for (std::size_t s = 0; s < count; ++s) {
      pending.insert(pending.end(), cases_of[first + s].begin(), cases_of[first + s].end());
    }
    const long n_pending = static_cast<long>(pending.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (long t = 0; t < n_pending; ++t) {
      const std::size_t i = pending[t];
      const SweepCase& sc = plan.cases[i];
      const ModelSlot& slot = slots[sc.model - first];
      SweepRow row;
      if (!slot.model) {
        row = failed_row(slot.error);
      } else {
        try {
          row = row_from(solve_footprint(*slot.model, sc.load, slot.warm.empty() ? nullptr : &slot.warm));
        } catch (const std::bad_alloc&) {
          row = failed_row("out of memory");
        } catch (const std::exception& e) {
          row = failed_row(e.what());
        }
      }
      result.rows[i] = std::move(row);
      if (options.progress) options.progress(1);
    }
  }
  for (const auto& r : result.rows) result.failed += r.ok ? 0 : 1;
  return result;
}

const std::vector<std::string>& sweep_observable_columns() {
  static const std::vector<std::string> cols = {
      "sinking_mm", "length_mm",  "vertical_stiffness_N_mm", "peak_pressure_kPa",
      "iterations", "status",     "message"};
  return cols;
}

std::string sweep_number(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

std::string csv_field(const std::string& text) {
  std::string t = text;
  for (char& c : t) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  if (t.find_first_of(",\"") == std::string::npos) return t;
  std::string q = "\"";
  for (char c : t) {
    if (c == '"') q.push_back('"');
    q.push_back(c);
  }
  q.push_back('"');
  return q;
}

std::string sweep_csv(const SweepPlan& plan, const SweepResult& result) {
  MODALTYRE_CHECK(result.rows.size() == plan.cases.size(), "sweep rows and cases disagree");
  std::string out;
  out.reserve(plan.cases.size() * 96);
  bool first = true;
  for (const auto& c : plan.columns) {
    out += (first ? "" : ",") + csv_field(c);
    first = false;
  }
  for (const auto& c : sweep_observable_columns()) out += "," + c;
  out += "\n";
  for (std::size_t i = 0; i < plan.cases.size(); ++i) {
    first = true;
    for (const auto& cell : plan.cells(i)) {
      if (!first) out += ",";
      out += cell;
      first = false;
    }
    const SweepRow& r = result.rows[i];
    if (r.ok) {
      out += "," + sweep_number(r.sinking_mm) + "," + sweep_number(r.length_mm) + "," +
             sweep_number(r.vertical_stiffness_N_mm) + "," + sweep_number(r.peak_pressure_kPa) +
             "," + std::to_string(r.iterations) + ",ok," + csv_field(r.message) + "\n";
    } else {
      out += ",,,,,,failed," + csv_field(r.message) + "\n";
    }
  }
  return out;
}

}  // namespace modaltyre::contact
