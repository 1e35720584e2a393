#pragma once
// Each subcommand registers itself on the top-level CLI11 app; its callback parses nothing by
// hand, validates through the library, calls it and prints.
#include <CLI/CLI.hpp>

namespace modaltyre::app {

void register_fit_modes(CLI::App& app);
void register_footprint(CLI::App& app);
void register_identify(CLI::App& app);
void register_validate(CLI::App& app);
void register_sweep(CLI::App& app);
void register_transient(CLI::App& app);
void register_effects(CLI::App& app);
void register_discover(CLI::App& app);
void register_ema(CLI::App& app);
void register_tir(CLI::App& app);
void register_init(CLI::App& app);
void register_traction(CLI::App& app);
void register_fmu(CLI::App& app);

}  // namespace modaltyre::app
