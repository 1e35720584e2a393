#include "condition_settings.h"

#include <algorithm>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::app {

std::vector<ConditionSetting> take_condition_settings(std::vector<std::string>& overrides) {
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
    const InputLocation at{"--set", 0, info->name};
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
                                 printable(s.text) + "'");
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
                              const std::string& why) {
  for (const auto& s : settings) {
    if (s.id == id) {
      throw InputError({"--set", 0, condition_info(id).name}, "does not apply here: " + why);
    }
  }
}

void apply_condition_settings(const std::vector<ConditionSetting>& settings,
                              contact::OperatingConditions& c) {
  for (const auto& s : settings) contact::set_condition(c, s.id, s.value);
}

std::string describe_conditions(const contact::OperatingConditions& c) {
  std::string s = number_text(c.pressure_kPa) + " kPa, ";
  s += c.hold_s > 0 ? "held " + number_text(c.hold_s) + " s, " : std::string("no hold, ");
  s += c.speed_kmh > 0 ? "rolling at " + number_text(c.speed_kmh) + " km/h, "
                       : std::string("standing, ");
  s += c.branch == contact::Branch::loading ? "loading branch, " : "unloading branch, ";
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

}  // namespace modaltyre::app
