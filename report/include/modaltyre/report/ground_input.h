#pragma once
// A tyre config on a ground given beside it (`--ground SOIL.yaml` of footprint and traction):
// the ground.* overrides go to the ground file, tyre.rigid is applied after the ground (the
// config reader alone refuses a rigid tyre on a road), the rest goes to the config.
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::report {

/// `ground_path` empty: the config's own ground: section. InputError (exit 2) naming the ground
/// file and ground.model when the config cannot run on that ground (contact::ground_refusal),
/// and naming tyre.rigid when a rigid tyre would stand on a road.
contact::TyreConfig config_on_ground(const std::string& config_path, const std::string& ground_path,
                                     const std::vector<std::string>& overrides);

}  // namespace modaltyre::report
