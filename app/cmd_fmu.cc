// modaltyre fmu CONFIG --output TYRE.fmu [--set k=v]...
// The transient tyre as an FMI 2.0 co-simulation FMU (fmu/, docs/fmu.md).
#include <iostream>

#include "cli_support.h"
#include "commands.h"
#include "modaltyre/core/command_files.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/fmu/package.h"
#include "modaltyre/report/command_inputs.h"

namespace modaltyre::app {
namespace {

struct FmuArgs {
  std::string config, output;
  std::vector<std::string> overrides;
};

void run_fmu(const FmuArgs& a) {
  refuse_repeated_overrides(a.overrides);
  const auto config = contact::load_tyre_config(a.config, a.overrides);
  CommandFiles files;
  report::add_config_inputs(files, config);
  files.output(a.output, "--output");
  files.check();
  fmu::PackageOptions o;
  o.config_path = a.config;
  o.overrides = a.overrides;
  o.output_path = a.output;
  o.binary_path = fmu::find_fmu_binary();
  const fmu::PackageResult r = fmu::write_fmu(o);
  std::cout << "wrote " << a.output << " (FMI 2.0 co-simulation, model identifier ModalTyre, GUID "
            << r.guid << ")\n";
  for (const std::string& e : r.entries) std::cout << "  " << e << "\n";
}

}  // namespace

void register_fmu(CLI::App& app) {
  auto args = std::make_shared<FmuArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fmu",
      "the transient tyre as an FMI 2.0 co-simulation FMU (zip: modelDescription.xml, "
      "binaries/linux64/ModalTyre.so, resources/ with the config and its data)");
  cmd->add_option("config", args->config, "tyre config (YAML)")->required();
  cmd->add_option("--output", args->output, "the .fmu to write")->required();
  cmd->add_option("--set", args->overrides, "override a config key: key=value (repeatable)");
  cmd->callback([args] { run_fmu(*args); });
}

}  // namespace modaltyre::app
