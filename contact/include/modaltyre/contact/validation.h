#pragma once
// Measured versus predicted footprints (seed 001 Table 3 style data).
//
// Measured file: CSV with load_N and any of sinking_mm, length_mm, width_mm. A file with
// operating-condition columns (pressure_kPa, hold_s, speed_kmh, horizontal_force_N, branch,
// surface: measurements.h, e.g. the output of `modaltyre sweep`) is read with
// read_measurements(), and so is any file when the config switches an effect on; each row is
// then predicted at its own conditions (missing ones: the config's).
// With an effect on (effects.h) rows are predicted by FootprintPredictor, otherwise by the
// model's own operator (solve_footprints), as before effects existed.
// Calibration is always declared: at most two scalar config keys fitted on at most two rows;
// those rows are marked as calibration rows and every other row is a prediction. RMS errors are
// reported over the predicted rows only.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"

namespace modaltyre::contact {

struct MeasuredFootprint {
  int row = 0;   ///< 1-based data row in the file
  int line = 0;  ///< line in the file
  double load_N = 0;
  std::optional<double> sinking_mm, length_mm, width_mm;
  /// The row's operating conditions when the file was read with them (see above); without,
  /// the config's default conditions at load_N apply.
  std::optional<OperatingConditions> conditions;
};

/// Reads a footprint measurement file; loads must be > 0, lengths and sinkings >= 0.
std::vector<MeasuredFootprint> read_footprint_measurements(const std::string& path);

/// Reads the measured file for validating `config`: with read_measurements() (every row with
/// its conditions) when the file has a condition column besides load_N or the config has an
/// effect on, otherwise with read_footprint_measurements(). InputError naming file, line and
/// column on any problem.
std::vector<MeasuredFootprint> read_validation_measurements(const std::string& path,
                                                            const TyreConfig& config);

/// The observables validate compares (and may calibrate on): sinking_mm, length_mm, width_mm.
const std::vector<std::string>& validation_observables();
/// A measured observable of a row by name (nullopt when not measured).
std::optional<double> measured_value(const MeasuredFootprint& m, const std::string& observable);

struct ValidationRow {
  MeasuredFootprint measured;
  bool calibration = false;
  double sinking_mm = 0;  ///< predicted
  double length_mm = 0;   ///< predicted
  double width_mm = 0;    ///< predicted: the config's, or the crown-profile width (contact_width)
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
  bool converged = false;
  /// Per key: "lower" or "upper" when the value ended within 0.1 % of its search range's bound
  /// (the rows only bound it from one side, or a better optimum lies across the range), else "".
  std::vector<std::string> at_bound;
};

struct ValidationReport {
  std::vector<ValidationRow> rows;
  std::map<std::string, double> rms_rel_error;  ///< per observable, predicted rows only
  std::map<std::string, int> predicted_rows;    ///< count per observable
  Calibration calibration;
  std::vector<FootprintResult> footprints;  ///< final model, one per row
  TyreModel model;
  bool with_conditions = false;  ///< rows carry their own conditions (read_measurements())
};

/// "lower" or "upper" when a fitted value lies within 1e-3 of its search range's span (of the
/// logarithms when `log_scale`) from that bound, else "": the data then bound the parameter from
/// one side only, or a better optimum lies across the range. Used by validate and discover.
std::string range_bound_side(double value, double min, double max, bool log_scale);

/// Validates the config at `config_path` (with overrides) against measurements, calibrating the
/// parameters the config's `validation:` section names on the rows it names.
ValidationReport validate_footprints(const std::string& config_path,
                                     const std::vector<std::string>& overrides,
                                     const std::vector<MeasuredFootprint>& measured);

}  // namespace modaltyre::contact
