#pragma once
// Operating conditions stated by name for a whole run (`--set hold_s=60`, `--set surface=soil`):
// the names, ranges and words of the catalogue (core/conditions.h) that a sweep case takes, for
// `footprint`, `validate` and `transient`. Other `--set` assignments stay config keys.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/contact/operating_conditions.h"
#include "modaltyre/core/conditions.h"

namespace modaltyre::app {

/// One condition stated with --set.
struct ConditionSetting {
  ConditionId id = ConditionId::load_N;
  double value = 0;  ///< as condition_value() gives it (branch, surface: the word's index)
  std::string text;  ///< as written
};

/// Takes the assignments "name=value" whose name is a condition of the catalogue out of
/// `overrides`, checks each value against the catalogue and returns them in order; config keys
/// stay in `overrides`. InputError at "--set", name (exit 2): a key given twice (both values
/// named, refuse_repeated_overrides), a value out of range (the message states the range) or
/// not one of the words.
std::vector<ConditionSetting> take_condition_settings(std::vector<std::string>& overrides);

/// InputError at "--set", the condition's name, "does not apply here: " + why, when `settings`
/// state condition `id` (a command that takes it from elsewhere, e.g. the load from --load).
void refuse_condition_setting(const std::vector<ConditionSetting>& settings, ConditionId id,
                              const std::string& why);

/// Sets every condition of `settings` in `c`.
void apply_condition_settings(const std::vector<ConditionSetting>& settings,
                              contact::OperatingConditions& c);

/// "230 kPa, no hold, standing, loading branch, rigid road" (the load and horizontal force are
/// stated per case).
std::string describe_conditions(const contact::OperatingConditions& c);

/// "hold_s=60, surface=soil" (as written), for a header.
std::string settings_text(const std::vector<ConditionSetting>& settings);

/// {"hold_s": 60, "surface": "soil"}: the settings by catalogue name (words as words).
nlohmann::json settings_json(const std::vector<ConditionSetting>& settings);

}  // namespace modaltyre::app
