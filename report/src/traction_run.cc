// What `modaltyre traction` runs (report/traction_json.h): the tyre config on its soil, the cases,
// the candidate window grown where the sinkage needs it, failed slips kept as rows.
#include <sstream>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"
#include "modaltyre/report/ground_input.h"
#include "modaltyre/report/traction_flexing.h"
#include "modaltyre/report/traction_json.h"

namespace modaltyre::report {
namespace {

// steady_traction's rows split per case (each case's rows start with pass 1).
std::vector<std::vector<contact::TractionResult>> by_case(
    std::vector<contact::TractionResult> results) {
  std::vector<std::vector<contact::TractionResult>> out;
  for (auto& r : results) {
    if (r.pass == 1 || out.empty()) out.emplace_back();
    out.back().push_back(std::move(r));
  }
  return out;
}

bool window_exceeded(const std::vector<contact::TractionResult>& rows) {
  for (const auto& r : rows)
    if (r.window_exceeded) return true;
  return false;
}

}  // namespace

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
  std::vector<contact::TractionCase> cases;
  for (double load : loads_N)
    for (double s : slips) cases.push_back({load, s});
  contact::TyreModel model = contact::build_tyre_model(config);
  // The tyre's flexing loss on the rigid road at each load (report/traction_flexing.h).
  if (!setup.rigid)
    opt.flexing_resistance_N =
        flexing_resistance_N(model, loads_N, traction_speed_km_h(setup) / 3.6);
  std::vector<std::vector<contact::TractionResult>> per_case =
      by_case(contact::steady_traction(model, setup.ground, cases, opt));
  // The candidate window grows where the sinkage needs it: the cases whose contact reached its
  // edge run again on a window 1.5 times longer, up to the largest the config reader accepts
  // (half the circumference, 20000 units).
  const double first_window_m = config.mesh.window_m;
  for (int growth = 0; growth < 20; ++growth) {
    std::vector<std::size_t> again;
    for (std::size_t k = 0; k < per_case.size(); ++k)
      if (window_exceeded(per_case[k])) again.push_back(k);
    if (again.empty() || config.mesh.window_m >= contact::max_window_m(config) * (1 - 1e-9)) break;
    config.mesh.window_m = contact::suggested_window_mm(config) * 1e-3;
    model = contact::build_tyre_model(config);
    std::vector<contact::TractionCase> redo;
    for (std::size_t k : again) redo.push_back(cases[k]);
    std::vector<std::vector<contact::TractionResult>> rerun =
        by_case(contact::steady_traction(model, setup.ground, redo, opt));
    for (std::size_t n = 0; n < again.size() && n < rerun.size(); ++n)
      per_case[again[n]] = std::move(rerun[n]);
  }
  std::vector<contact::TractionResult> results;
  for (auto& rows : per_case)
    for (auto& r : rows) {
      if (r.window_exceeded && config.mesh.window_m > first_window_m)
        r.message += " (the window grew from " + number_text(first_window_m * 1e3) + " to " +
                     number_text(config.mesh.window_m * 1e3) + " mm, the largest allowed)";
      results.push_back(std::move(r));
    }
  require_traction_converged(results);
  return results;
}

}  // namespace modaltyre::report
