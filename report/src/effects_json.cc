#include "modaltyre/report/effects_json.h"

#include "modaltyre/core/number_format.h"

namespace modaltyre::report {

using contact::EffectInfo;
using contact::EffectParameterInfo;

std::string enabled_key(const EffectInfo& e) {
  return e.is_option() ? e.option->keys : "effects." + e.name + ".enabled";
}

namespace {

nlohmann::json parameter_json(const EffectInfo& e, const EffectParameterInfo& p) {
  return {{"key", e.key(p)}, {"unit", p.unit},     {"default", p.default_value}, {"min", p.min},
          {"max", p.max},    {"fitted", p.fitted}, {"meaning", p.meaning}};
}

nlohmann::json effect_json(const EffectInfo& e) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : e.parameters) params.push_back(parameter_json(e, p));
  return {{"name", e.name},
          {"description", e.description},
          {"observables", e.observables},
          {"regime", condition_info(e.regime).name},
          {"enabled_key", enabled_key(e)},
          {"acts_on", e.acts_on},
          {"with_footprint_3d",
           {{"composes", e.refused_with_3d.empty()}, {"refused_because", e.refused_with_3d}}},
          {"option", e.is_option()},
          {"switch", contact::effect_catalogue_switch(e.id)},
          {"needs_footprint_3d", e.is_option() && e.option->needs_3d},
          {"strength", e.strength == contact::EffectStrength::inverse ? "vanishes as it grows"
                       : e.strength == contact::EffectStrength::none
                           ? "none"
                           : "from " + number_text(e.neutral)},
          {"parameters", params}};
}

}  // namespace

nlohmann::json effects_json() {
  nlohmann::json effects = nlohmann::json::array();
  for (const auto& e : contact::effect_catalogue()) effects.push_back(effect_json(e));
  return {{"effects", effects}};
}

}  // namespace modaltyre::report
