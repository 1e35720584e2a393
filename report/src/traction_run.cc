// What `modaltyre traction` runs (report/traction_json.h): the tyre config on its soil, the cases,
// the candidate window grown where the sinkage needs it (contact/traction.h), failed slips kept
// as rows.
#include <sstream>

#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/report/ground_input.h"
#include "modaltyre/report/traction_flexing.h"
#include "modaltyre/report/traction_json.h"

namespace modaltyre::report {

void require_traction_converged(const std::vector<contact::TractionResult>& results) {
  // A failed slip is a row with its reason; the run fails only when no case converged.
  for (const auto& r : results)
    if (r.ok()) return;
  std::ostringstream msg;
  msg << "traction: no case converged";
  if (!results.empty()) {
    const auto& r = results.front();
    msg << "; at load " << r.load_N << " N, slip " << r.slip << ", pass " << r.pass << ": "
        << r.message;
  }
  throw ComputationError(msg.str());
}

TractionSetup traction_setup(const std::string& config_path, const std::string& ground_path,
                             const std::vector<std::string>& overrides) {
  TractionSetup s;
  s.config = config_on_ground(config_path, ground_path, overrides);
  s.rigid = s.config.rigid;
  s.ground = s.config.ground;
  s.ground_source = ground_path.empty() ? config_path : ground_path;
  if (!s.ground.soil())
    throw InputError({s.ground_source, 0, "ground.model"},
                     "traction needs a soil: model bekker or kelvin_voigt");
  // The drawbar pull is the soil's shear: no default stands in for it (issue 44).
  if (!s.ground.shear_stated) {
    const std::string block =
        s.ground.model == ground::GroundModel::bekker ? "ground.bekker." : "ground.kelvin_voigt.";
    throw InputError({s.ground_source, 0, block + "cohesion_kPa"},
                     "traction needs the soil's shear keys stated: " + block +
                         "{cohesion_kPa, friction_angle_deg, shear_modulus_K_mm} (identify "
                         "shear SHEAR.csv --into-ground SOIL.yaml --write-ground OUT.yaml, or "
                         "configs/soils/ for published values)");
  }
  return s;
}

void use_2d_patch_of_3d(contact::TyreConfig& config) {
  if (!config.footprint_3d) return;
  config.tread.width_m = config.footprint_3d->tread_width_m;
  config.footprint_3d.reset();
}

double traction_speed_km_h(const TractionSetup& setup) {
  const double v =
      setup.speed_km_h >= 0 ? setup.speed_km_h : setup.config.transient.rolling.speed_m_s * 3.6;
  if (!(v >= 0 && v <= 100))
    throw InputError({"--speed-km-h", 0, ""},
                     "the flexing loss's speed " + number_text(v) +
                         " km/h is outside [0, 100] (steady traction on soil is a slow "
                         "process; transient.rolling.speed_km_h gives the default)");
  return v;
}

std::vector<contact::TractionResult> run_traction(const TractionSetup& setup,
                                                  const std::vector<double>& loads_N,
                                                  const std::vector<double>& slips, int passes) {
  if (loads_N.empty()) throw InputError({"loads_N", 0, ""}, "give at least one load [N]");
  if (slips.empty()) throw InputError({"slips", 0, ""}, "give at least one slip");
  // The command's ranges (app/cmd_traction.cc): a braked wheel locks at s = -1, a driven one
  // spins in place at s = 1; 1e7 N exceeds any tyre; passes 1-20.
  for (double s : slips)
    if (!(s >= -0.99 && s <= 1))
      throw InputError({"slips", 0, ""}, "slip " + std::to_string(s) + " outside [-0.99, 1]");
  for (double F : loads_N)
    if (!(F >= contact::kMinLoad_N && F <= contact::kMaxLoad_N))
      throw InputError({"loads_N", 0, ""}, "load " + std::to_string(F) + " N outside [1e-6, 1e7]");
  if (passes < 1 || passes > 20) throw InputError({"passes", 0, ""}, "passes must be 1-20");
  contact::TyreConfig config = setup.config;
  if (setup.patch_2d || setup.rigid) use_2d_patch_of_3d(config);
  config.ground = setup.ground;
  contact::TractionOptions opt;
  opt.rigid = setup.rigid;
  opt.passes = passes;
  opt.slip_reference = setup.slip_reference;
  opt.speed_m_per_s = traction_speed_km_h(setup) / 3.6;  // a viscous soil's rate term
  std::vector<contact::TractionCase> cases;
  for (double load : loads_N)
    for (double s : slips) cases.push_back({load, s});
  const modal::ModeIdentification modes = contact::config_modes(config);
  const contact::TyreModel model = contact::build_tyre_model(config, modes);
  // The tyre's flexing loss on the rigid road at each load (report/traction_flexing.h).
  if (!setup.rigid)
    opt.flexing_resistance_N =
        flexing_resistance_N(model, loads_N, traction_speed_km_h(setup) / 3.6);
  // The candidate window grows where the sinkage needs it (contact/traction.h).
  std::vector<contact::TractionResult> results =
      contact::steady_traction_growing_window(model, modes, setup.ground, cases, opt);
  require_traction_converged(results);
  return results;
}

}  // namespace modaltyre::report
