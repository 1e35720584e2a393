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
#include <optional>
#include <sstream>
#include <utility>

#include "modaltyre/contact/predictor.h"
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

// Text conditions and their accepted values (the names branch_name()/surface_name() give, which
// read_measurements() reads back).
std::optional<Branch> branch_of(const std::string& text) {
  for (Branch b : {Branch::loading, Branch::unloading}) {
    if (text == branch_name(b)) return b;
  }
  return std::nullopt;
}

std::optional<Surface> surface_of(const std::string& text) {
  for (Surface s : {Surface::rigid, Surface::soil}) {
    if (text == surface_name(s)) return s;
  }
  return std::nullopt;
}

// A numeric condition: a finite number within the range read_measurements() accepts, so that a
// sweep never writes a file that cannot be read back as measured data.
void check_number(const std::string& key, const SweepValue& v, const InputLocation& at) {
  if (!v.number) throw InputError(at, "expected a finite number, got '" + v.text + "'");
  const double x = *v.number;
  if (key == "load_N" && !(x > 0)) {
    throw InputError(at, "every load must be greater than 0 N, got " + v.text);
  }
  if (key == "pressure_kPa" && !(x > 0 && x <= 2000)) {
    throw InputError(at, "inflation pressure must be in (0, 2000] kPa, got " + v.text);
  }
  if (key == "hold_s" && !(x >= 0)) throw InputError(at, "hold time must be >= 0 s, got " + v.text);
  if (key == "speed_kmh" && !(x >= 0 && x <= 400)) {
    throw InputError(at, "speed must be in [0, 400] km/h, got " + v.text);
  }
  if (std::abs(x) > 1e7) {
    throw InputError(at, "value " + v.text + " is out of range [-1e7, 1e7]");
  }
}

// A condition value, named at the line of the value itself when it has one.
void check_condition(const std::string& key, const SweepValue& v, const InputLocation& where) {
  const InputLocation at{where.file, v.line > 0 ? v.line : where.line, where.key};
  if (key == "branch") {
    if (!branch_of(v.text)) throw InputError(at, "'" + v.text + "' is not one of: load, unload");
  } else if (key == "surface") {
    if (!surface_of(v.text)) throw InputError(at, "'" + v.text + "' is not one of: rigid, soil");
  } else {
    check_number(key, v, at);
  }
}

// Sets one (checked) condition of a case.
void apply_condition(const std::string& key, const SweepValue& v, OperatingConditions& c) {
  if (key == "branch") {
    c.branch = *branch_of(v.text);
  } else if (key == "surface") {
    c.surface = *surface_of(v.text);
  } else if (key == "load_N") {
    c.load_N = *v.number;
  } else if (key == "horizontal_force_N") {
    c.horizontal_force_N = *v.number;
  } else if (key == "pressure_kPa") {
    c.pressure_kPa = *v.number;
  } else if (key == "hold_s") {
    c.hold_s = *v.number;
  } else if (key == "speed_kmh") {
    c.speed_kmh = *v.number;
  }
}

// A cell of the CSV as read_measurements() reads it back: numbers with %.10g, text as written.
std::string cell_of(const SweepValue& v) {
  return v.number ? sweep_number(*v.number) : csv_field(v.text);
}

// The message of an InputError without its "file:line: key: " prefix.
std::string bare_message(const InputError& e) {
  const std::string prefix = format_location(e.where(), "");
  const std::string all = e.what();
  return all.rfind(prefix, 0) == 0 ? all.substr(prefix.size()) : all;
}

}  // namespace

bool is_sweep_condition(const std::string& key) {
  static const std::vector<std::string> keys = {
      "load_N", "horizontal_force_N", "pressure_kPa", "hold_s", "speed_kmh", "branch", "surface"};
  return std::find(keys.begin(), keys.end(), key) != keys.end();
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
    if (is_sweep_condition(a.key)) check_condition(a.key, a.value, a.where);
  }
  for (const auto& axis : spec.grid) {
    if (!axis.condition) continue;
    for (const auto& v : axis.values) check_condition(axis.key, v, axis.where);
  }
  return spec;
}

SweepSpec read_sweep_spec(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_sweep_spec(read_yaml_file(path, "a sweep file"), path, overrides);
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

  // Conditions given once for every case: one column each, where first written; the last
  // assignment wins (the file's set:, then --set).
  std::vector<std::pair<std::string, SweepValue>> set_conditions;
  std::vector<const SweepAssignment*> params;  // config overrides for every case
  for (const auto& a : spec.set) {
    if (!is_sweep_condition(a.key)) {
      params.push_back(&a);
      continue;
    }
    const auto same = std::find_if(set_conditions.begin(), set_conditions.end(),
                                   [&](const auto& c) { return c.first == a.key; });
    if (same == set_conditions.end()) {
      set_conditions.emplace_back(a.key, a.value);
    } else {
      same->second = a.value;
    }
  }
  std::vector<int> condition_axes, param_axes;
  bool load_given = false;
  for (const auto& c : set_conditions) load_given = load_given || c.first == "load_N";
  for (std::size_t k = 0; k < n_axes; ++k) {
    (spec.grid[k].condition ? condition_axes : param_axes).push_back(static_cast<int>(k));
    load_given = load_given || spec.grid[k].key == "load_N";
  }
  if (!load_given) {
    throw InputError({spec.file, spec.grid.front().where.line, "load_N"},
                     "required: give the vertical load load_N in grid: or set:");
  }

  // Every condition given is a column, so that the CSV states what each row was computed at.
  for (const auto& [key, value] : set_conditions) {
    plan.columns.push_back(key);
    plan.column_axis.push_back(-1);
    plan.set_cells.push_back(cell_of(value));
  }
  for (std::size_t k = 0; k < n_axes; ++k) {
    plan.columns.push_back(spec.grid[k].key);
    plan.column_axis.push_back(static_cast<int>(k));
    plan.set_cells.emplace_back();
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
    // Conditions not given are the case's own config's (its horizontal force and pressure).
    OperatingConditions& c = sc.conditions;
    c = plan.models[sc.model].default_conditions(0);
    for (const auto& [key, value] : set_conditions) apply_condition(key, value, c);
    for (int k : condition_axes) {
      apply_condition(spec.grid[k].key, spec.grid[k].values[sc.value_index[k]], c);
    }
    sc.load = {c.load_N, c.horizontal_force_N};
  }
  return plan;
}

std::vector<std::string> SweepPlan::cells(std::size_t i) const {
  const SweepCase& sc = cases.at(i);
  std::vector<std::string> out;
  out.reserve(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const int k = column_axis[c];
    out.push_back(k < 0 ? set_cells[c] : cell_of(spec.grid[k].values[sc.value_index[k]]));
  }
  return out;
}

namespace {

SweepRow failed_row(const std::string& why) {
  SweepRow row;
  row.message = why;
  return row;
}

SweepRow row_from(const Prediction& p, const OperatingConditions& c) {
  SweepRow row;
  row.iterations = p.footprint.iterations;
  if (!p.ok) {
    row.message = p.message.empty() ? "did not converge" : p.message;
    return row;
  }
  row.ok = true;
  // Never empty: read_measurements() refuses empty text cells, and an ok row must read back.
  row.message = p.footprint.message.empty() ? "converged" : p.footprint.message;
  row.sinking_mm = p.sinking_mm;
  row.length_mm = p.length_mm;
  row.width_mm = p.width_mm;
  row.rolling_resistance_N = p.rolling_resistance_N;
  // Secant stiffness of the applied load (dry friction moves the elastic tyre's load, not F).
  row.vertical_stiffness_N_mm = c.load_N / row.sinking_mm;
  double peak = 0;
  for (const auto& u : p.footprint.units) peak = std::max(peak, u.pressure_Pa);
  row.peak_pressure_kPa = peak * 1e-3;
  return row;
}

// The model's own operator as a Prediction (what predict() computes when no effect is on).
Prediction static_prediction(const TyreModel& model, const LoadCase& load,
                             const std::vector<char>* warm) {
  Prediction p;
  p.footprint = solve_footprint(model, load, warm);
  p.ok = p.footprint.converged;
  p.message = p.ok ? "" : p.footprint.message;
  p.sinking_mm = p.footprint.sinking_m * 1e3;
  p.length_mm = p.footprint.contact_length_m * 1e3;
  p.width_mm = model.config.tread.width_m * 1e3;
  p.elastic_load_N = load.load_N;
  return p;
}

// One case. With no effect on, the conditions other than the loads act on nothing and the
// model's prebuilt operator (solve_footprint) gives the same footprint as predict() without
// assembling an m x m operator per case: the values of `modaltyre footprint`, bit for bit.
Prediction solve_case(const FootprintPredictor& predictor, const TyreConfig& config,
                      const SweepCase& sc, const std::vector<char>* warm) {
  if (!config.effects.any()) return static_prediction(predictor.model(), sc.load, warm);
  return predictor.predict(config, sc.conditions, warm);
}

// One distinct model, built for one batch and released after it.
struct ModelSlot {
  std::unique_ptr<FootprintPredictor> predictor;  // read-only once built: shared by threads
  std::vector<char> warm;                         // reference contact set (empty: cold starts)
  std::string error;                              // reason the model could not be built
  std::exception_ptr input_error;
};

// Fixed warm-start reference of a model: its median-load case (ties: plan order), solved cold,
// so that the reference does not depend on which thread gets there first.
std::vector<char> reference_contact_set(const SweepPlan& plan,
                                        const std::vector<std::size_t>& cases,
                                        const FootprintPredictor& predictor,
                                        const TyreConfig& config) {
  std::vector<std::size_t> by_load = cases;
  std::sort(by_load.begin(), by_load.end(), [&](std::size_t a, std::size_t b) {
    const double la = plan.cases[a].conditions.load_N, lb = plan.cases[b].conditions.load_N;
    return la != lb ? la < lb : a < b;
  });
  const Prediction ref =
      solve_case(predictor, config, plan.cases[by_load[by_load.size() / 2]], nullptr);
  return ref.ok ? ref.footprint.active : std::vector<char>{};
}

void build_slot(const SweepPlan& plan, std::size_t mi, const std::vector<std::size_t>& cases,
                bool warm_start, ModelSlot& slot) {
  try {
    slot.predictor = std::make_unique<FootprintPredictor>(build_tyre_model(plan.models[mi]));
    if (warm_start && !cases.empty()) {
      slot.warm = reference_contact_set(plan, cases, *slot.predictor, plan.models[mi]);
    }
  } catch (const InputError&) {
    slot.input_error = std::current_exception();
  } catch (const std::bad_alloc&) {
    slot.predictor.reset();
    slot.error = "model not built: out of memory";
  } catch (const std::exception& e) {
    slot.predictor.reset();
    slot.error = std::string("model not built: ") + e.what();
  }
}

SweepRow run_case(const SweepPlan& plan, const SweepCase& sc, const ModelSlot& slot) {
  if (!slot.predictor) return failed_row(slot.error);
  try {
    const std::vector<char>* warm = slot.warm.empty() ? nullptr : &slot.warm;
    return row_from(solve_case(*slot.predictor, plan.models[sc.model], sc, warm), sc.conditions);
  } catch (const std::bad_alloc&) {
    return failed_row("out of memory");
  } catch (const std::exception& e) {
    return failed_row(e.what());
  }
}

}  // namespace

SweepResult run_sweep(const SweepPlan& plan, const SweepOptions& options) {
  SweepResult result;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  result.threads = threads;
  result.rows.resize(plan.cases.size());

  // all_of: every case of a model (the warm-start reference is chosen among them, so that a
  // distributed share starts from the same reference as the whole sweep); run_of: the cases
  // to compute here.
  std::vector<std::vector<std::size_t>> all_of(plan.models.size()), run_of(plan.models.size());
  for (std::size_t i = 0; i < plan.cases.size(); ++i) all_of[plan.cases[i].model].push_back(i);
  if (options.only_cases) {
    for (std::size_t i : *options.only_cases) {
      MODALTYRE_CHECK(i < plan.cases.size(), "sweep share names a case outside the plan");
      run_of[plan.cases[i].model].push_back(i);
    }
  } else {
    run_of = all_of;
  }
  std::vector<std::size_t> models;  // those with something to compute
  for (std::size_t mi = 0; mi < plan.models.size(); ++mi) {
    if (!run_of[mi].empty()) models.push_back(mi);
  }

  // Models are built and used in batches of `threads` (each holds dense m x m matrices: only a
  // few are alive at once, however many parameter combinations the grid has).
  const std::size_t batch = static_cast<std::size_t>(std::max(threads, 1));
  for (std::size_t first = 0; first < models.size(); first += batch) {
    const std::size_t count = std::min(batch, models.size() - first);
    std::vector<ModelSlot> slots(count);
    std::vector<std::size_t> slot_of(plan.models.size(), 0);

#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (std::size_t s = 0; s < count; ++s) {
      const std::size_t mi = models[first + s];
      build_slot(plan, mi, all_of[mi], options.warm_start, slots[s]);
    }
    for (const auto& slot : slots) {
      if (slot.input_error) std::rethrow_exception(slot.input_error);
    }

    std::vector<std::size_t> pending;
    for (std::size_t s = 0; s < count; ++s) {
      const std::size_t mi = models[first + s];
      slot_of[mi] = s;
      pending.insert(pending.end(), run_of[mi].begin(), run_of[mi].end());
    }
    const long n_pending = static_cast<long>(pending.size());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (long t = 0; t < n_pending; ++t) {
      const std::size_t i = pending[t];
      const SweepCase& sc = plan.cases[i];
      result.rows[i] = run_case(plan, sc, slots[slot_of[sc.model]]);
      if (options.progress) options.progress(1);
    }
  }
  for (const auto& cases : run_of) {
    for (std::size_t i : cases) result.failed += result.rows[i].ok ? 0 : 1;
  }
  return result;
}

std::vector<std::size_t> sweep_share(const SweepPlan& plan, int rank, int ranks) {
  MODALTYRE_CHECK(ranks >= 1 && rank >= 0 && rank < ranks, "sweep share: bad rank");
  std::vector<std::size_t> by_model(plan.cases.size());
  for (std::size_t i = 0; i < by_model.size(); ++i) by_model[i] = i;
  std::stable_sort(by_model.begin(), by_model.end(), [&](std::size_t a, std::size_t b) {
    return plan.cases[a].model < plan.cases[b].model;
  });
  // Chunk r is [r n / K, (r + 1) n / K): sizes differ by at most one.
  const std::size_t n = by_model.size(), k = static_cast<std::size_t>(ranks);
  const std::size_t r = static_cast<std::size_t>(rank);
  std::vector<std::size_t> share(by_model.begin() + static_cast<long>(r * n / k),
                                 by_model.begin() + static_cast<long>((r + 1) * n / k));
  std::sort(share.begin(), share.end());
  return share;
}

const std::vector<std::string>& sweep_observable_columns() {
  // The observables of predictor.h first (the columns read_measurements() reads), then the
  // solver's by-products (which it ignores).
  static const std::vector<std::string> cols = {"sinking_mm",
                                                "length_mm",
                                                "width_mm",
                                                "rolling_resistance_N",
                                                "vertical_stiffness_N_mm",
                                                "peak_pressure_kPa",
                                                "iterations",
                                                "status",
                                                "message"};
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

std::string sweep_csv_header(const SweepPlan& plan) {
  std::string out;
  bool first = true;
  for (const auto& c : plan.columns) {
    out += (first ? "" : ",") + csv_field(c);
    first = false;
  }
  for (const auto& c : sweep_observable_columns()) out += "," + c;
  out += "\n";
  return out;
}

std::string sweep_csv_row(const SweepPlan& plan, const SweepRow& r, std::size_t i) {
  std::string out;
  bool first = true;
  for (const auto& cell : plan.cells(i)) {
    if (!first) out += ",";
    out += cell;
    first = false;
  }
  if (r.ok) {
    for (double v : {r.sinking_mm, r.length_mm, r.width_mm, r.rolling_resistance_N,
                     r.vertical_stiffness_N_mm, r.peak_pressure_kPa}) {
      out += "," + sweep_number(v);
    }
    out += "," + std::to_string(r.iterations) + ",ok," + csv_field(r.message) + "\n";
  } else {
    out += ",,,,,,,,failed," + csv_field(r.message) + "\n";
  }
  return out;
}

std::string sweep_csv(const SweepPlan& plan, const SweepResult& result) {
  MODALTYRE_CHECK(result.rows.size() == plan.cases.size(), "sweep rows and cases disagree");
  std::string out = sweep_csv_header(plan);
  out.reserve(plan.cases.size() * 96);
  for (std::size_t i = 0; i < plan.cases.size(); ++i) out += sweep_csv_row(plan, result.rows[i], i);
  return out;
}

}  // namespace modaltyre::contact
