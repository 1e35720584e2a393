#include "modaltyre/report/condition_settings.h"

#include <algorithm>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/report/validation_json.h"

namespace modaltyre::report {

std::vector<ConditionSetting> take_condition_settings(std::vector<std::string>& overrides,
                                                      const std::string& origin) {
  refuse_repeated_overrides(overrides);
  std::vector<ConditionSetting> out;
  std::vector<std::string> config_keys;
  for (const auto& o : overrides) {
    const auto eq = o.find('=');
    const ConditionInfo* info = eq == std::string::npos ? nullptr : find_condition(o.substr(0, eq));
    if (info == nullptr) {
      config_keys.push_back(o);
      continue;
    }
    const InputLocation at{origin, 0, info->name};
    if (info->id == ConditionId::slip)
      throw InputError(at, "a traction row's condition: `traction --slip` takes the slips");
    const YAML::Node n = parse_set_value(o.substr(eq + 1), info->name);
    if (!n || !n.IsScalar()) {
      throw InputError(at, "expected one value, e.g. " + info->name + "=" +
                               (info->is_text() ? info->words.front().front() : std::string("0")));
    }
    ConditionSetting s{info->id, 0, n.Scalar()};
    if (info->is_text()) {
      const auto v = info->value_of(s.text);
      if (!v) throw InputError(at, info->refusal(s.text));
      s.value = *v;
    } else {
      const auto v = parse_finite_double(s.text);
      if (!v) {
        throw InputError(at, "expected a finite number in " + info->range_text() + ", got '" +
                                 printable(s.text) + "'" + decimal_hint(s.text));
      }
      if (!info->in_range(*v)) throw InputError(at, info->refusal(s.text));
      s.value = *v;
    }
    out.push_back(std::move(s));
  }
  overrides = std::move(config_keys);
  return out;
}

void refuse_condition_setting(const std::vector<ConditionSetting>& settings, ConditionId id,
                              const std::string& why, const std::string& origin) {
  for (const auto& s : settings) {
    if (s.id == id) {
      throw InputError({origin, 0, condition_info(id).name}, "does not apply here: " + why);
    }
  }
}

void refuse_footprint_settings(const std::vector<ConditionSetting>& settings,
                               const std::string& load_arg, const std::string& fx_arg,
                               const std::string& origin) {
  refuse_condition_setting(settings, ConditionId::load_N,
                           "footprint takes its loads from " + load_arg, origin);
  refuse_condition_setting(settings, ConditionId::horizontal_force_N,
                           "footprint takes the horizontal force from " + fx_arg, origin);
}

contact::OperatingConditions apply_to_footprint_cases(
    const std::vector<ConditionSetting>& settings, const contact::TyreConfig& config,
    std::vector<contact::OperatingConditions>& cases) {
  // At the config's default conditions (its pressure, standing, loading branch, rigid road)
  // but those stated: effects act on what is printed exactly as they do in `sweep` and
  // `validate`.
  for (auto& c : cases) apply_condition_settings(settings, c);
  auto shown = config.default_conditions(0);
  apply_condition_settings(settings, shown);
  return shown;
}

nlohmann::json footprint_conditions_json(const contact::OperatingConditions& shown) {
  nlohmann::json j = conditions_json(shown);
  j.erase("load_N");
  j.erase("horizontal_force_N");
  return j;
}

void apply_to_measurements(const std::vector<ConditionSetting>& settings,
                           studies::MeasurementSet& measured, const std::string& measured_path,
                           const std::string& origin) {
  refuse_condition_setting(settings, ConditionId::load_N, "each row states its load", origin);
  for (const auto& s : settings) {
    const auto& name = condition_info(s.id).name;
    if (std::find(measured.conditions.begin(), measured.conditions.end(), name) !=
        measured.conditions.end()) {
      refuse_condition_setting(
          settings, s.id, "the file '" + measured_path + "' has a " + name + " column", origin);
    }
  }
  for (auto& row : measured.rows) apply_condition_settings(settings, row.conditions);
  if (!settings.empty()) measured.loads_only = false;  // the rows now state conditions
}

void apply_condition_settings(const std::vector<ConditionSetting>& settings,
                              contact::OperatingConditions& c) {
  for (const auto& s : settings) contact::set_condition(c, s.id, s.value);
}

std::string describe_conditions(const contact::OperatingConditions& c,
                                const ground::GroundSettings& ground) {
  std::string s = number_text(c.pressure_kPa) + " kPa, ";
  s += c.hold_s > 0 ? "held " + number_text(c.hold_s) + " s, " : std::string("no hold, ");
  s += c.speed_kmh > 0 ? "rolling at " + number_text(c.speed_kmh) + " km/h, "
                       : std::string("standing, ");
  s += c.branch == contact::Branch::loading ? "loading branch, " : "unloading branch, ";
  const std::string model = ground::to_string(ground.model);
  if (ground.soil())
    s += "on the soil " + (ground.name.empty() ? model : ground.name + " (" + model + ")");
  else if (ground.model == ground::GroundModel::profile)
    s += "on the road profile " + ground.profile_csv;
  else
    s += c.surface == contact::Surface::rigid ? "rigid road" : "soil";
  return s;
}

std::string settings_text(const std::vector<ConditionSetting>& settings) {
  std::string s;
  for (const auto& e : settings) {
    s += (s.empty() ? "" : ", ") + condition_info(e.id).name + "=" + printable(e.text);
  }
  return s;
}

nlohmann::json settings_json(const std::vector<ConditionSetting>& settings) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& e : settings) {
    const auto& info = condition_info(e.id);
    if (info.is_text()) {
      j[info.name] = info.words[static_cast<std::size_t>(e.value)].front();
    } else {
      j[info.name] = e.value;
    }
  }
  return j;
}

void map_transient_conditions(const std::vector<ConditionSetting>& settings,
                              transient::Scenario scenario, std::vector<std::string>& overrides,
                              const std::string& origin) {
  using transient::Scenario;
  const std::string section = scenario == Scenario::load_hold        ? "load_hold"
                              : scenario == Scenario::free_vibration ? "free_vibration"
                              : scenario == Scenario::rolling        ? "rolling"
                                                                     : "cleat";
  const std::string sc = transient::to_string(scenario);
  for (const auto& c : settings) {
    std::string key;
    if (c.id == ConditionId::load_N) key = "load_N";
    if (c.id == ConditionId::hold_s && scenario == Scenario::load_hold) key = "hold_s";
    if (c.id == ConditionId::speed_kmh &&
        (scenario == Scenario::rolling || scenario == Scenario::cleat)) {
      key = "speed_km_h";
    }
    if (key.empty()) {
      refuse_condition_setting(
          {c}, c.id,
          c.id == ConditionId::pressure_kPa
              ? "transient runs at the tyre's pressure: set tyre.inflation_pressure_kPa"
              : "scenario " + sc + " takes load_N" +
                    (scenario == Scenario::load_hold ? ", hold_s" : "") +
                    (scenario == Scenario::rolling || scenario == Scenario::cleat ? ", speed_kmh"
                                                                                  : "") +
                    " (the transient model runs on a rigid road, loading, without effects)",
          origin);
    }
    overrides.push_back("transient." + section + "." + key + "=" + c.text);
  }
}

}  // namespace modaltyre::report
