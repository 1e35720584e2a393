// modaltyre traction CONFIG [--ground SOIL.yaml] --load N... --slip S... [--passes P]
//                   [--patch 3d|2d] [--set key=value]... [--json] [--plot FILE]
// Steady rolling at slip on a soil (docs/soil.md section 5): drawbar pull, thrust, motion
// resistance, torque, sinkage and rut; the library computes (contact/traction.h), this prints.
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>

#include "cli_support.h"
#include "commands.h"
#include "footprint_map.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/command_files.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/gnuplot.h"
#include "modaltyre/report/command_inputs.h"
#include "modaltyre/report/traction_json.h"
#include "traction_report.h"

namespace modaltyre::app {
namespace {

struct TractionArgs {
  std::string config, ground;
  std::vector<double> loads, slips;
  int passes = 1;
  std::string patch;  ///< "3d" (a 3D config's default), "2d"; empty: the config's own
  std::string slip_reference = "rolling";  ///< rolling (r_e, ISTVS) | unloaded (R0)
  double speed_km_h = -1;                  ///< the flexing loss's speed (-1: the config's)
  std::vector<std::string> overrides;
  bool json = false;
  std::string plot;
};

}  // namespace

void register_traction(CLI::App& app) {
  auto a = std::make_shared<TractionArgs>();
  CLI::App* cmd = app.add_subcommand(
      "traction",
      "Steady rolling at slip on a soil (Bekker-Wong or Kelvin-Voigt, Janosi-Hanamoto shear): "
      "drawbar pull, thrust, motion resistance, torque, sinkage and rut per load and slip "
      "(docs/soil.md). --set tyre.rigid=true: the rigid cylinder of the outer radius.");
  cmd->add_option("CONFIG", a->config,
                  "tyre config (YAML); a 3D config (footprint_3d:) runs its 3D patch")
      ->required();
  cmd->add_option("--ground", a->ground,
                  "soil file (YAML with a ground: section, e.g. configs/soils/lete_sand.yaml); "
                  "default: the config's ground: section");
  cmd->add_option("--load", a->loads, "vertical load [N]; repeat for several")
      ->required()
      ->check(physical_range(contact::kMinLoad_N, contact::kMaxLoad_N, "N",
                             "1e7 N (1000 t on one wheel) exceeds any tyre"));
  cmd->add_option("--slip", a->slips,
                  "slip (Wong: driven s = 1 - V/(omega R) > 0, braked s = omega R/V - 1 < 0); "
                  "repeat, or several values after one --slip")
      ->required()
      ->check(physical_range(-0.99, 1, "-",
                             "a braked wheel locks at s = -1, a driven one "
                             "spins in place at s = 1",
                             true));
  cmd->add_option("--passes", a->passes, "passes over the same track (each meets the rut), 1-20")
      ->check(CLI::Range(1, 20));
  cmd->add_option("--patch", a->patch,
                  "3d: the 3D patch (a 3D config's default); 2d: a 3D config's 2D patch at its "
                  "tread width (the fast variant, docs/soil.md section 9)")
      ->check(CLI::IsMember({"3d", "2d"}));
  cmd->add_option("--slip-reference", a->slip_reference,
                  "the radius slip is taken against: rolling (default; r_e of the same tyre at "
                  "the same load free-rolling on the rigid road, ISTVS) or unloaded (R0)")
      ->check(CLI::IsMember({"rolling", "unloaded"}));
  cmd->add_option("--speed-km-h", a->speed_km_h,
                  "rolling speed, 0-100 km/h: of the tyre's flexing (hysteresis) loss on the "
                  "road and a Kelvin-Voigt soil's rate term eta2 (0: neither; default: the "
                  "config's transient.rolling.speed_km_h)")
      ->check(physical_range(0, 100, "km/h",
                             "steady traction on soil is a slow process (soil bins run at "
                             "0.1-3 m/s)",
                             true));
  cmd->add_option("--set", a->overrides,
                  "override a config key (tyre.rigid=true), or a soil key when --ground is "
                  "given (ground.bekker.n=0.8)");
  cmd->add_flag("--json", a->json, "print JSON");
  cmd->add_option("--plot", a->plot, "draw drawbar pull / load against slip (.svg or .png)");
  cmd->callback([a] {
    refuse_repeated_overrides(a->overrides);
    report::TractionSetup setup = report::traction_setup(a->config, a->ground, a->overrides);
    if (a->patch == "3d" && !setup.config.footprint_3d)
      throw InputError({a->config, 0, "footprint_3d"},
                       "--patch 3d needs a 3D config (a footprint_3d: section)");
    setup.patch_2d = a->patch == "2d";
    setup.slip_reference = a->slip_reference == "unloaded" ? contact::SlipReference::unloaded
                                                           : contact::SlipReference::rolling;
    setup.speed_km_h = a->speed_km_h;
    const double speed_km_h = report::traction_speed_km_h(setup);
    CommandFiles files;  // before anything is computed: no output over an input
    report::add_config_inputs(files, setup.config);
    files.input(a->ground, "--ground");
    if (!a->plot.empty()) files.output(a->plot, "--plot");
    files.check();
    // The Kelvin-Voigt soil's rate term eta2 acts at the speed on the rigid wheel and the
    // flexible tyre alike (docs/soil.md sections 3.2, 9.1): the JSON prints that speed.
    const bool viscous = setup.ground.model == ground::GroundModel::kelvin_voigt &&
                         setup.ground.kelvin_voigt.eta2_kPa_s > 0;
    const auto results = report::run_traction(setup, a->loads, a->slips, a->passes);
    for (const auto& r : results) {
      if (r.window_m > setup.config.mesh.window_m) {
        std::cerr << "note: contact.window_mm grew from " << setup.config.mesh.window_m * 1e3
                  << " to " << r.window_m * 1e3
                  << " mm where the contact reached its edge (cases with window_mm in --json)\n";
        break;
      }
    }
    contact::TyreConfig config = setup.config;  // as run
    if (setup.patch_2d || setup.rigid) report::use_2d_patch_of_3d(config);
    const ground::GroundSettings& g = setup.ground;
    const TractionRun run{&config, &g, setup.rigid, a->passes, setup.slip_reference};
    if (!a->plot.empty()) plot_traction(run, results, a->plot);
    if (a->json) {
      print_json(report::traction_json(config, g, results, setup.rigid, a->passes,
                                       setup.slip_reference,
                                       setup.rigid && !viscous ? 0.0 : speed_km_h));
      return;
    }
    print_traction_table(run, results);
  });
}

}  // namespace modaltyre::app
