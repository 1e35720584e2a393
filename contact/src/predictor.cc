#include "modaltyre/contact/predictor.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "modaltyre/contact/pneumatic_share.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ground/rigid_wheel.h"
#include "predictor_paths.h"

namespace modaltyre::contact {
namespace predictor_paths {

Prediction failed(std::string why) {
  Prediction p;
  p.message = std::move(why);
  return p;
}

Prediction failed(SolveStatus status, std::string why) {
  Prediction p = failed(std::move(why));
  p.status = status;
  return p;
}

}  // namespace predictor_paths

using predictor_paths::centre_line;
using predictor_paths::effects_path;
using predictor_paths::failed;
using predictor_paths::patch3d_path;
using predictor_paths::pressure_acts;

namespace {

// ---- the effect-free path: the model's own operator -------------------------------------------

// A plain solve_footprint() result as a Prediction: the config's width, no rolling resistance.
Prediction from_footprint(FootprintResult result, const TyreConfig& config) {
  Prediction p;
  p.status = result.status;
  p.message = result.message;
  p.sinking_mm = result.sinking_m * 1e3;
  p.length_mm = result.contact_length_m * 1e3;
  p.width_mm = config.tread.width_m * 1e3;
  p.elastic_load_N = result.load.load_N;
  p.footprint = std::move(result);
  return p;
}

Prediction effect_free(const TyreModel& model, const OperatingConditions& c,
                       std::span<const char> warm) {
  return from_footprint(solve_footprint(model, {c.load_N, c.horizontal_force_N}, warm),
                        model.config);
}

/// Below it a row's pressure is refused when the ring's terms act (the config reader's bound).
constexpr double kMinRingPressure_kPa = 10;

}  // namespace

TyreParameters parameters_of(const TyreConfig& config) {
  return {config.compliance_scale, config.tread, config.effects, config.footprint_3d,
          config.pneumatic_share};
}

const std::vector<std::string>& observable_names() {
  static const std::vector<std::string> names = {"sinking_mm", "length_mm", "width_mm",
                                                 "rolling_resistance_N"};
  return names;
}

double Prediction::observable(const std::string& name) const {
  if (name == "sinking_mm") return sinking_mm;
  if (name == "length_mm") return length_mm;
  if (name == "width_mm") return width_mm;
  if (name == "rolling_resistance_N") return rolling_resistance_N;
  throw std::invalid_argument("unknown observable " + name);
}

// The row's pressure acts through the pneumatic share too (pneumatic_share.h).
bool conditions_act(const TyreConfig& config) {
  return config.effects.any() || config.pneumatic_share > 0;
}

Prediction predict(const TyreModel& model, const OperatingConditions& c,
                   const PredictOptions& options) {
  const bool flat_road =
      model.config.ground.model == ground::GroundModel::rigid && !model.config.rigid;
  if (!conditions_act(model.config) && c.load_N > 0 && !model.config.footprint_3d && flat_road &&
      !pressure_acts(model, c)) {
    return effect_free(model, c, options.warm_active);
  }
  return predict(model, parameters_of(model.config), c, options);
}

std::vector<Prediction> predict_all(const TyreModel& model,
                                    const std::vector<OperatingConditions>& conditions) {
  std::vector<Prediction> out;
  const bool chain = !conditions_act(model.config);
  std::vector<char> warm;
  for (const auto& c : conditions) {
    PredictOptions o;
    if (chain) o.warm_active = warm;
    out.push_back(predict(model, c, o));
    if (chain && out.back().footprint.ok()) warm = out.back().footprint.active;
  }
  return out;
}

namespace {

// tyre.rigid on a soil: the rigid cylinder of the outer radius pressed into the soil
// (ground/rigid_wheel.h, the static symmetric contact), as wide as the tread (3D) or the contact
// width (2D). Sinking = soil sinkage; no tyre deflection.
Prediction rigid_wheel_path(const TyreModel& m, const TyreParameters& P,
                            const OperatingConditions& c) {
  const double width = P.footprint_3d ? P.footprint_3d->tread_width_m : P.tread.width_m;
  const ground::RigidWheelResult w =
      ground::rigid_wheel_static(m.config.ground, {m.config.outer_radius_m, width}, c.load_N);
  if (!w.ok()) return failed(w.status, w.message);
  Prediction p;
  p.status = SolveStatus::converged;
  p.message = "the rigid wheel (tyre.rigid): " + w.message;
  p.sinking_mm = p.soil_sinkage_mm = w.sinkage_m * 1e3;
  p.length_mm = w.contact_length_m * 1e3;
  p.width_mm = width * 1e3;
  p.bekker_width_mm = w.bekker_width_m * 1e3;
  p.on_soil = true;
  p.elastic_load_N = c.load_N;
  FootprintResult& f = p.footprint;
  f.status = SolveStatus::converged;
  f.message = p.message;
  f.sinking_m = w.sinkage_m;
  f.contact_length_m = w.contact_length_m;
  f.rear_edge_x_m = -0.5 * w.contact_length_m;
  f.front_edge_x_m = 0.5 * w.contact_length_m;
  f.equilibrium_residual = std::abs(w.vertical_N - c.load_N) / c.load_N;
  f.on_soil = true;
  f.soil_sinkage_m = w.sinkage_m;
  f.bekker_width_m = w.bekker_width_m;
  return p;
}

Prediction structural(const TyreModel& model, const TyreParameters& parameters,
                      const OperatingConditions& c, const PredictOptions& options) {
  if (model.config.rigid && model.config.ground.soil() && c.load_N > 0)
    return rigid_wheel_path(model, parameters, c);
  return parameters.footprint_3d ? patch3d_path(model, parameters, c, options)
                                 : effects_path(model, parameters, c, options);
}

// modal.pneumatic_share (pneumatic_share.h, docs/footprint.md section 8): the structural tyre
// carries F_s, the pressure beta p over its contact area the rest; the horizontal force stays on
// the structural tyre (the pressure acts normal to the road).
Prediction pneumatic_split(const TyreModel& model, const TyreParameters& parameters,
                           const OperatingConditions& c, const PredictOptions& options,
                           double pressure_Pa) {
  std::vector<char> warm(options.warm_active.begin(), options.warm_active.end());
  std::vector<double> warm_cells;  // the 3D patch's lateral patterns of the last solve
  std::vector<std::pair<double, Prediction>> solved;
  Prediction failure;
  auto area_at = [&](double F, double& area) {
    OperatingConditions cs = c;
    cs.load_N = F;
    PredictOptions o;
    o.warm_active = warm;
    o.warm_cells = warm_cells;
    Prediction p = structural(model, parameters, cs, o);
    if (!p.ok()) {
      failure = std::move(p);
      return false;
    }
    warm = p.footprint.active;
    if (p.patch3d) warm_cells = p.patch3d->cell_force_N;
    area =
        p.patch3d ? contact_area_m2(*p.patch3d) : contact_area_m2(p.footprint, p.width_mm * 1e-3);
    solved.emplace_back(F, std::move(p));
    return true;
  };
  const LoadSplit split = split_pneumatic_load(c.load_N, pressure_Pa, area_at);
  if (!split.ok()) {
    if (!failure.ok() && !failure.message.empty()) return failure;
    std::ostringstream msg;
    msg.precision(12);
    msg << "pneumatic share: no load split F_s + p A = " << c.load_N << " N after " << split.solves
        << " solves (" << to_string(split.status) << "; last F_s " << split.structural_load_N
        << " N, residual " << split.residual_N << " N)";
    return failed(msg.str());
  }
  Prediction p;
  for (auto& [F, q] : solved) {
    if (F == split.structural_load_N) p = std::move(q);
  }
  const double pneumatic_N = pressure_Pa * split.area_m2;
  p.elastic_load_N += pneumatic_N;
  FootprintResult& f = p.footprint;
  if (p.patch3d) {
    Patch3dResult r = *p.patch3d;
    add_pneumatic_pressure(r, pressure_Pa, r.load_N + pneumatic_N);
    // The units are the sections in contact, in order (from_patch3d): their resultants and
    // centre-line pressures gain the pneumatic part.
    std::size_t k = 0;
    for (int i = 0; i < r.sections && k < f.units.size(); ++i) {
      if (!(r.section_force_N[i] > 0)) continue;
      f.units[k].fz_N = r.section_force_N[i];
      f.units[k].pressure_Pa = centre_line(r.columns, [&](int j) { return r.pressure_Pa(i, j); });
      ++k;
    }
    f.equilibrium_residual = r.equilibrium_residual;
    p.patch3d = std::make_shared<const Patch3dResult>(std::move(r));
  } else {
    add_pneumatic_pressure(f, pressure_Pa, p.width_mm * 1e-3, f.load.load_N + pneumatic_N);
  }
  return p;
}

}  // namespace

Prediction predict(const TyreModel& model, const TyreParameters& parameters,
                   const OperatingConditions& c, const PredictOptions& options) {
  if (pressure_acts(model, c) && c.pressure_kPa < kMinRingPressure_kPa) {
    Prediction p = failed("pressure " + std::to_string(c.pressure_kPa) +
                          " kPa: below 10 kPa the ring's hoop tension and sidewall foundation "
                          "vanish (an uninflated tyre is not a modal carcass)");
    p.footprint.load = {c.load_N, c.horizontal_force_N};
    return p;
  }
  const double pneumatic_Pa = parameters.pneumatic_share * c.pressure_Pa();
  Prediction p = pneumatic_Pa > 0 && c.load_N > 0
                     ? pneumatic_split(model, parameters, c, options, pneumatic_Pa)
                     : structural(model, parameters, c, options);
  p.footprint.load = {c.load_N, c.horizontal_force_N};  // the applied load, failed or not
  return p;
}

}  // namespace modaltyre::contact
