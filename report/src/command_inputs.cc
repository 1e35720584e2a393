#include "modaltyre/report/command_inputs.h"

namespace modaltyre::report {

void add_config_inputs(CommandFiles& files, const contact::TyreConfig& config,
                       const std::string& role) {
  files.input(config.source, role);
  files.input(config.hammer_csv, role + "'s modal.hammer_csv");
}

}  // namespace modaltyre::report
