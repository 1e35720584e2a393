// Sampling the model's footprints for the .tir bridge (model_curve.h).
#include "modaltyre/tir/model_curve.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::tir {

std::string model_width_reason(const contact::TyreConfig& config) {
  // The 3D patch predicts the width; the 2D patch carries the config's fixed width, and only the
  // crown-profile width of the contact_width effect is a prediction there.
  if (config.footprint_3d || config.effects.contact_width.enabled) return "";
  return "the config's patch has a fixed width (tread.contact_width_mm), not a predicted one; "
         "a footprint_3d: section or effects.contact_width makes predictions carry a width";
}

double model_fnomin_N(const contact::TyreConfig& config, std::optional<double> fnomin_N) {
  // FNOMIN is the tyre's rated load (a passenger tyre's ~4000 N): below 100 N (10 kg) no road
  // tyre, and the sinking-load fit around it degenerates (1 N: exit 1).
  constexpr double kMin_N = 100, kMax_N = 1e7;
  if (fnomin_N) {
    if (!(*fnomin_N >= kMin_N) || !(*fnomin_N <= kMax_N)) {
      throw InputError({"--fnomin", 0, ""}, "the nominal load must be a number in [100, 1e7] N");
    }
    return *fnomin_N;
  }
  const auto [lo, hi] = std::minmax_element(config.loads_N.begin(), config.loads_N.end());
  if (lo == config.loads_N.end()) {
    throw InputError({config.source, 0, "loads_N"}, "no loads: give --fnomin");
  }
  const double middle_N = 0.5 * (*lo + *hi);
  if (middle_N < kMin_N) {
    throw InputError({config.source, 0, "loads_N"},
                     "the nominal load (the middle of loads_N) is below 100 N: give --fnomin");
  }
  return middle_N;
}

std::vector<double> load_grid(double fnomin_N, double lo, double hi, int count) {
  std::vector<double> loads;
  for (int i = 0; i < count; ++i) {
    loads.push_back(fnomin_N * (lo + (hi - lo) * i / std::max(count - 1, 1)));
  }
  return loads;
}

ModelCurve sample_model(const contact::TyreModel& model, const std::vector<double>& loads_N,
                        double pressure_Pa) {
  if (loads_N.empty() || loads_N.size() > static_cast<std::size_t>(kMaxModelLoads)) {
    throw InputError({"--loads", 0, ""}, "give 1 to " + std::to_string(kMaxModelLoads) + " loads");
  }
  std::vector<contact::OperatingConditions> cases;
  for (double f : loads_N) {
    if (!(f > 0) || !std::isfinite(f) || f > 1e7) {
      throw InputError({"--loads", 0, ""}, "every load must be a number in (0, 1e7] N");
    }
    contact::OperatingConditions c = model.config.default_conditions(f);
    if (pressure_Pa > 0) c.pressure_kPa = pressure_Pa * 1e-3;
    cases.push_back(c);
  }
  const auto predictions = contact::predict_all(model, cases);
  ModelCurve curve;
  curve.width_reason = model_width_reason(model.config);
  for (std::size_t i = 0; i < predictions.size(); ++i) {
    const auto& p = predictions[i];
    if (!p.ok()) {
      throw ComputationError("footprint at " + std::to_string(loads_N[i]) +
                             " N did not converge: " + p.message);
    }
    ModelPoint point{loads_N[i], p.sinking_mm * 1e-3, p.length_mm * 1e-3, std::nullopt};
    if (curve.width_reason.empty()) point.width_m = p.width_mm * 1e-3;
    curve.points.push_back(point);
  }
  std::sort(curve.points.begin(), curve.points.end(),
            [](const ModelPoint& a, const ModelPoint& b) { return a.load_N < b.load_N; });
  return curve;
}

double model_tangent_stiffness_N_m(const contact::TyreModel& model, double load_N,
                                   double pressure_Pa) {
  constexpr double kStep = 0.02;
  const ModelCurve c =
      sample_model(model, {load_N * (1 - kStep), load_N * (1 + kStep)}, pressure_Pa);
  const double d = c.points[1].sinking_m - c.points[0].sinking_m;
  if (!(d > 0)) {
    throw ComputationError("the model's sinking does not grow with the load near " +
                           std::to_string(load_N) + " N");
  }
  return 2 * kStep * load_N / d;
}

}  // namespace modaltyre::tir
