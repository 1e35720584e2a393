#pragma once
// The predictor's paths (predictor.h), private to contact/: the effects path on the 2D patch
// and its steps (predictor_effects.cc), the 3D patch (predictor_3d.cc). predictor.cc chooses
// between them, the effect-free path, the rigid wheel on a soil and the pneumatic share.
#include <string>

#include "modaltyre/contact/predictor.h"

namespace modaltyre::contact::predictor_paths {

/// A failed prediction with its reason.
Prediction failed(std::string why);
Prediction failed(SolveStatus status, std::string why);

/// dry_friction: the load the elastic tyre carries; false (with `why`) when it carries none.
bool elastic_load(const EffectsConfig& E, const OperatingConditions& c, double& load_N,
                  std::string& why);

/// The carcass compliance factor: the parameters' level against the model's, inflation_pressure
/// and load_stiffening.
double carcass_scale(const TyreModel& m, const TyreParameters& P, const OperatingConditions& c,
                     double elastic_load_N);

/// Whether the row's pressure differs from the model's and the ring fit can move the carcass.
bool pressure_acts(const TyreModel& m, const OperatingConditions& c);

/// The carcass kernels rebuilt for rolling_speed, belt_flattening or the row's pressure.
modal::LagKernels rebuilt_kernels(const TyreModel& m, const EffectsConfig& E, double scale,
                                  bool rolling, bool flattening, double speed_m_per_s,
                                  double pressure_Pa);

/// tread_relaxation's creep factor of the tread while the load is held (1 when off).
double tread_creep(const EffectsConfig& E, const OperatingConditions& c);

/// The mean of the one or two columns nearest the centre plane.
template <class Value>
double centre_line(int columns, Value value) {
  return columns % 2 ? value(columns / 2) : 0.5 * (value(columns / 2 - 1) + value(columns / 2));
}

/// The effects path on the 2D patch, one step per effect.
Prediction effects_path(const TyreModel& m, const TyreParameters& P, const OperatingConditions& c,
                        const PredictOptions& options);

/// The 3D patch (patch3d.h) with the parameters' carcass, tread and soil.
Prediction patch3d_path(const TyreModel& m, const TyreParameters& P, const OperatingConditions& c,
                        const PredictOptions& options);

}  // namespace modaltyre::contact::predictor_paths
