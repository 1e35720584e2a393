#pragma once
// Operating conditions stated by name for a whole run (`--set hold_s=60`, `--set surface=soil`):
// the names, ranges and words of the catalogue (core/conditions.h) that a sweep case takes, for
// `footprint`, `validate` and `transient`, and for the Python module's `conditions` argument.
// Other `--set` assignments stay config keys.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/contact/operating_conditions.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/conditions.h"
#include "modaltyre/studies/measurements.h"
#include "modaltyre/transient/scenario.h"

namespace modaltyre::report {

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
/// not one of the words. `origin` names where the assignments come from in messages (the
/// Python module: "conditions").
std::vector<ConditionSetting> take_condition_settings(std::vector<std::string>& overrides,
                                                      const std::string& origin = "--set");

/// InputError at `origin`, the condition's name, "does not apply here: " + why, when `settings`
/// state condition `id` (a command that takes it from elsewhere, e.g. the load from --load).
void refuse_condition_setting(const std::vector<ConditionSetting>& settings, ConditionId id,
                              const std::string& why, const std::string& origin = "--set");

/// footprint's conditions: the load comes from the loads and the horizontal force from their
/// own arguments (`load_arg`, `fx_arg`: "--load", "--fx"), refused among `settings`.
void refuse_footprint_settings(const std::vector<ConditionSetting>& settings,
                               const std::string& load_arg, const std::string& fx_arg,
                               const std::string& origin = "--set");

/// Sets `settings` on every footprint case; returns the conditions for the header: the
/// config's defaults with `settings`.
contact::OperatingConditions apply_to_footprint_cases(
    const std::vector<ConditionSetting>& settings, const contact::TyreConfig& config,
    std::vector<contact::OperatingConditions>& cases);

/// The "conditions" object of footprint's JSON: `shown` without the load and the horizontal
/// force (stated per case).
nlohmann::json footprint_conditions_json(const contact::OperatingConditions& shown);

/// validate's rows: each states its load, and a condition the file (`measured_path`) has a
/// column of is refused; the other settings act on every row.
void apply_to_measurements(const std::vector<ConditionSetting>& settings,
                           studies::MeasurementSet& measured, const std::string& measured_path,
                           const std::string& origin = "--set");

/// Sets every condition of `settings` in `c`.
void apply_condition_settings(const std::vector<ConditionSetting>& settings,
                              contact::OperatingConditions& c);

/// "230 kPa, no hold, standing, loading branch, rigid road" (the load and horizontal force are
/// stated per case). On a config's ground other than the flat road the last part names it:
/// "on the soil LETE sand (bekker)", "on the road profile FILE".
std::string describe_conditions(const contact::OperatingConditions& c,
                                const ground::GroundSettings& ground = {});

/// "hold_s=60, surface=soil" (as written), for a header.
std::string settings_text(const std::vector<ConditionSetting>& settings);

/// {"hold_s": 60, "surface": "soil"}: the settings by catalogue name (words as words).
nlohmann::json settings_json(const std::vector<ConditionSetting>& settings);

/// transient's conditions: the scenario key each stands for (load_N, hold_s of load-hold,
/// speed_kmh of rolling and cleat), appended to `overrides` so that the config reader checks it
/// like the key itself. Any other condition: InputError naming it (the transient model runs the
/// config's tyre on a rigid road and has no other condition).
void map_transient_conditions(const std::vector<ConditionSetting>& settings,
                              transient::Scenario scenario, std::vector<std::string>& overrides,
                              const std::string& origin = "--set");

}  // namespace modaltyre::report
