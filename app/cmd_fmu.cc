// modaltyre fmu CONFIG [--ground SOIL.yaml] --output TYRE.fmu [--set k=v]...
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
  std::string config, ground, output;
  std::vector<std::string> overrides;
};

void run_fmu(const FmuArgs& a) {
  refuse_repeated_overrides(a.overrides);
  std::vector<std::string> tyre_sets;
  for (const std::string& s : a.overrides)
    if (a.ground.empty() || s.rfind("ground.", 0) != 0) tyre_sets.push_back(s);
  const auto config = contact::load_tyre_config(a.config, tyre_sets);
  CommandFiles files;
  report::add_config_inputs(files, config);
  if (!a.ground.empty()) files.input(a.ground, "--ground");
  files.output(a.output, "--output");
  files.check();
  fmu::PackageOptions o;
  o.config_path = a.config;
  o.ground_path = a.ground;
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
  cmd->add_option("--ground", args->ground,
                  "soil file (YAML with a ground: section, e.g. configs/soils/lete_sand.yaml): "
                  "the tyre runs on it, its keys FMU parameters; default: the config's ground");
  cmd->add_option("--output", args->output, "the .fmu to write")->required();
  cmd->add_option("--set", args->overrides,
                  "override a config key: key=value (repeatable); with --ground, ground.KEY "
                  "overrides the soil file's");
  cmd->callback([args] { run_fmu(*args); });
}

}  // namespace modaltyre::app
