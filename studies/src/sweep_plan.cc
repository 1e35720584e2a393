#include "modaltyre/studies/sweep_plan.h"

#include <algorithm>
#include <map>
#include <utility>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/studies/sweep_output.h"

namespace modaltyre::studies {

using namespace contact;

namespace {

// At most this many cases in one sweep (a typo such as a 1e6-long list is caught before the
// machine runs out of memory).
constexpr std::size_t kMaxCases = 10'000'000;

// Sets one (checked) condition of a case.
void apply_condition(const std::string& key, const SweepValue& v, OperatingConditions& c) {
  const ConditionInfo& info = *find_condition(key);
  set_condition(c, info.id, info.is_text() ? *info.value_of(v.text) : *v.number);
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

}  // namespace modaltyre::studies
