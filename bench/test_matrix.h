#pragma once
// A measured test matrix for the discover benchmark and study: loads x pressures x hold times,
// sinking and length with 1.5 % relative noise (seeded), predicted on the config's mesh with a
// creeping tread (creep ratio 0.8, 40 s) and, when `two_effects`, the pressure effect
// (exponent 1.2) hidden.
#include <random>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::bench {

// loads x pressures x holds rows (load fastest), predicted with the hidden effects.
inline studies::MeasurementSet test_matrix(const contact::TyreConfig& cfg, int loads, int pressures,
                                           int holds, bool two_effects = true, unsigned seed = 11) {
  contact::TyreConfig truth = cfg;
  truth.effects.tread_relaxation.enabled = true;
  truth.effects.tread_relaxation.creep_ratio = 0.8;
  truth.effects.tread_relaxation.time_constant_s = 40;
  truth.effects.inflation_pressure.enabled = two_effects;
  truth.effects.inflation_pressure.exponent = 1.2;
  const contact::TyreModel model = contact::build_tyre_model(truth);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.015);
  studies::MeasurementSet set;
  set.path = "test matrix";
  set.observables = {"sinking_mm", "length_mm"};
  set.conditions = {"load_N", "pressure_kPa", "hold_s"};
  for (int h = 0; h < holds; ++h) {
    for (int p = 0; p < pressures; ++p) {
      for (int l = 0; l < loads; ++l) {
        studies::MeasuredRow r;
        r.row = r.line = static_cast<int>(set.rows.size()) + 1;
        r.conditions = cfg.default_conditions(2000 + 5700.0 * l / (loads - 1));
        r.conditions.pressure_kPa = 180 + 80.0 * p / (pressures - 1);
        r.conditions.hold_s = 180.0 * h * h / ((holds - 1) * (holds - 1));
        const auto pr = contact::predict(model, contact::parameters_of(truth), r.conditions);
        r.observed = {{"sinking_mm", pr.sinking_mm * (1 + noise(rng))},
                      {"length_mm", pr.length_mm * (1 + noise(rng))}};
        set.rows.push_back(r);
      }
    }
  }
  return set;
}

}  // namespace modaltyre::bench
