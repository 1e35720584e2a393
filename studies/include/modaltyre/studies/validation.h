#pragma once
// Measured versus predicted footprints (seed 001 Table 3 style data).
//
// Measured file (measurements.h): CSV with load_N and any of sinking_mm, length_mm, width_mm,
// optionally operating-condition columns (pressure_kPa, hold_s, speed_kmh, horizontal_force_N,
// branch, surface, e.g. the output of `modaltyre sweep`). With condition columns, or with an
// effect on in the config, each row is predicted at its own conditions (missing ones: the
// config's).
// Rows are predicted by contact::predict_all (predictor.h): the effect-free path with no effect
// on, the effects path at each row's conditions otherwise.
// Calibration is always declared: at most three scalar config keys fitted on at most two rows;
// those rows are marked as calibration rows and every other row is a prediction. RMS errors are
// reported over the predicted rows only.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::studies {

/// Reads the measured file for validating `config` (read_measurements()) and checks what
/// validate needs: an observable it compares (sinking_mm, length_mm, width_mm) and, when the rows
/// are predicted at the config's conditions (rows_at_own_conditions() false), one row per load.
/// InputError naming file, line and column on any problem.
MeasurementSet read_validation_measurements(const std::string& path,
                                            const contact::TyreConfig& config);

/// Whether the rows are predicted at conditions of their own: the file states some (a condition
/// column besides load_N, or a sweep's output), or an effect is on (conditions act only through
/// effects; rows without condition columns then take the config's).
bool rows_at_own_conditions(const MeasurementSet& set, const contact::TyreConfig& config);

/// The observables validate compares (and may calibrate on): sinking_mm, length_mm, width_mm.
const std::vector<std::string>& validation_observables();

struct ValidationRow {
  MeasuredRow measured;
  bool calibration = false;
  double sinking_mm = 0;  ///< predicted
  double length_mm = 0;   ///< predicted
  double width_mm = 0;    ///< predicted: the 3D patch's, the config's (2D), or contact_width's
  std::optional<double> sinking_rel_error, length_rel_error,
      width_rel_error;  ///< (pred - meas) / meas, where measured
};

struct Calibration {
  std::vector<std::string> keys;
  std::vector<double> values;
  std::vector<double> initial_values;
  std::vector<int> rows;
  std::vector<std::string> observables;
  double rms_rel_residual = 0;  ///< on the calibration rows
  int evaluations = 0;
  SolveStatus status = SolveStatus::failed;  ///< the Levenberg-Marquardt fit's
  bool ok() const { return modaltyre::ok(status); }
  /// Per key: "lower" or "upper" when the value ended within 0.1 % of its search range's bound
  /// (the rows only bound it from one side, or a better optimum lies across the range), else "".
  std::vector<std::string> at_bound;
  /// The calibrated scalars' standard errors (issue 35; docs/uncertainty.md section 4): from
  /// the Jacobian J of the relative residuals in ln(value) at the fit, Cov(ln x) =
  /// s^2 (J^T J)^-1 with s^2 = |r|^2 / (m - n) the residual variance of the m calibration
  /// residuals (n scalars); std = value sqrt(Cov_kk) (delta method). Empty when there is no
  /// residual degree of freedom (m <= n): `covariance_note` says so.
  std::vector<double> std_errors;
  std::vector<std::vector<double>> correlation;  ///< n x n, when std_errors are given
  std::string covariance_note;
  /// Every calibration residual had a stated noise (*_std columns > 0): the fit weighed each by
  /// it (chi-square) and the covariance is (J^T J)^-1 of the weighted residuals, s^2 = 1.
  bool noise_weighted = false;
};

struct ValidationReport {
  std::vector<ValidationRow> rows;
  std::map<std::string, double> rms_rel_error;  ///< per observable, predicted rows only
  std::map<std::string, int> predicted_rows;    ///< count per observable
  Calibration calibration;
  std::vector<contact::FootprintResult> footprints;  ///< final model, one per row
  contact::TyreModel model;
  bool with_conditions = false;  ///< rows predicted at their own conditions
};

/// "lower" or "upper" when a fitted value lies within 1e-3 of its search range's span (of the
/// logarithms when `log_scale`) from that bound, else "": the data then bound the parameter from
/// one side only, or a better optimum lies across the range. Used by validate and discover.
std::string range_bound_side(double value, double min, double max, bool log_scale);

/// Validates `config` against measurements, calibrating the parameters its `validation:` section
/// names on the rows it names (each trial value set on a copy of the config and a model built on
/// the hammer modes identified once).
ValidationReport validate_footprints(const contact::TyreConfig& config,
                                     const MeasurementSet& measured);

}  // namespace modaltyre::studies
