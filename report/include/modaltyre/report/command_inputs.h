#pragma once
// The input files a tyre config brings to a command (the config itself and the hammer data it
// names), for core/command_files.h's check that no output is written over an input.
#include <string>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/command_files.h"

namespace modaltyre::report {

/// Adds the config file (as `role`, e.g. "CONFIG") and its modal.hammer_csv to `files`.
void add_config_inputs(CommandFiles& files, const contact::TyreConfig& config,
                       const std::string& role = "CONFIG");

}  // namespace modaltyre::report
