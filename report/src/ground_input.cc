#include "modaltyre/report/ground_input.h"

#include <optional>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::report {

contact::TyreConfig config_on_ground(const std::string& config_path, const std::string& ground_path,
                                     const std::vector<std::string>& overrides) {
  std::vector<std::string> tyre_overrides, ground_overrides;
  std::optional<bool> rigid;
  for (const auto& o : overrides) {
    if (o.rfind("tyre.rigid=", 0) == 0) {
      try {
        rigid = parse_set_value(o.substr(11), "tyre.rigid").as<bool>();
      } catch (const YAML::Exception&) {
        throw InputError({"--set", 0, "tyre.rigid"}, "must be true or false");
      }
      continue;
    }
    (!ground_path.empty() && o.rfind("ground.", 0) == 0 ? ground_overrides : tyre_overrides)
        .push_back(o);
  }
  contact::TyreConfig config = contact::load_tyre_config(config_path, tyre_overrides);
  if (!ground_path.empty()) {
    config.ground = ground::load_ground_file(ground_path, ground_overrides);
    const std::string refusal = contact::ground_refusal(config);
    if (!refusal.empty()) throw InputError({ground_path, 0, "ground.model"}, refusal);
  }
  if (rigid) config.rigid = *rigid;
  if (config.rigid && !config.ground.soil())
    throw InputError({"--set", 0, "tyre.rigid"},
                     "a rigid tyre (the terramechanics reference wheel) needs a soil: "
                     "ground.model bekker or kelvin_voigt (on a road it would not deflect)");
  return config;
}

}  // namespace modaltyre::report
