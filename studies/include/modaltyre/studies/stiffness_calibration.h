#pragma once
// The carcass stiffness level of a tyre config set from a load-deflection test (seed 000 eq. 3)
// instead of the hammer test: the modal.compliance_scale at which the footprint model sinks by a
// target deflection at one operating point.
//
// Sinking grows strictly with the carcass compliance (the tread and soil in series are fixed),
// so the scale is found by bracketing in log(scale) and regula falsi (Illinois) on
// sinking(scale) - target, bracketing outwards from the config's own scale. Below the deflection of
// the tread alone (scale -> 0) no scale fits: the test's tyre is stiffer than this config's tread,
// which is an input problem, not a numerical one.
#include <string>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/solve_status.h"

namespace modaltyre::studies {

struct ScaleCalibration {
  /// converged; max_iterations; failed when a footprint on the way failed (message says why).
  SolveStatus status = SolveStatus::failed;
  double compliance_scale = 1.0;  ///< the config's modal.compliance_scale to write
  double sinking_mm = 0;          ///< the model's sinking at that scale
  double target_mm = 0;
  int evaluations = 0;
  std::string message;  ///< why not converged
  bool ok() const { return modaltyre::ok(status); }
};

/// Finds modal.compliance_scale in [1e-3, 1e3] (the config's range) such that the footprint of
/// `model` with `parameters` (other than the scale) under `at` sinks `target_sinking_mm` to
/// `relative_tolerance`, bracketing from parameters.compliance_scale. InputError when the target
/// lies outside what the range can reach (names the key modal.compliance_scale).
ScaleCalibration calibrate_compliance_scale(const contact::TyreModel& model,
                                            const contact::TyreParameters& parameters,
                                            const contact::OperatingConditions& at,
                                            double target_sinking_mm,
                                            double relative_tolerance = 1e-6);

}  // namespace modaltyre::studies
