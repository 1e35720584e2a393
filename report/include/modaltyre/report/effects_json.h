#pragma once
// The JSON document of `modaltyre effects --json` (and the Python module's effects).
#include <nlohmann/json.hpp>
#include <string>

#include "modaltyre/contact/effects.h"

namespace modaltyre::report {

/// The config key that switches effect `e` on: effects.NAME.enabled.
std::string enabled_key(const contact::EffectInfo& e);

/// {effects: [{name, description, observables, regime, enabled_key, acts_on,
/// with_footprint_3d, parameters: [{key, unit, default, min, max, fitted, meaning}]}]}.
nlohmann::json effects_json();

}  // namespace modaltyre::report
