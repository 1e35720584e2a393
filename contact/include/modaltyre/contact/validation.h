#pragma once
// Measured versus predicted footprints (seed 001 Table 3 style data).
//
// Measured file: CSV with load_N and any of sinking_mm, length_mm, width_mm.
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
};

/// Reads a footprint measurement file; loads must be > 0, lengths and sinkings >= 0.
std::vector<MeasuredFootprint> read_footprint_measurements(const std::string& path);

struct ValidationRow {
  MeasuredFootprint measured;
  bool calibration = false;
  double sinking_mm = 0;  ///< predicted
  double length_mm = 0;   ///< predicted
  std::optional<double> sinking_rel_error, length_rel_error;  ///< (pred - meas) / meas
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
};

struct ValidationReport {
  std::vector<ValidationRow> rows;
  std::map<std::string, double> rms_rel_error;  ///< per observable, predicted rows only
  std::map<std::string, int> predicted_rows;    ///< count per observable
  Calibration calibration;
  std::vector<FootprintResult> footprints;      ///< final model, one per row
  TyreModel model;
};

/// Validates the config at `config_path` (with overrides) against measurements, calibrating the
/// parameters the config's `validation:` section names on the rows it names.
ValidationReport validate_footprints(const std::string& config_path,
                                     const std::vector<std::string>& overrides,
                                     const std::vector<MeasuredFootprint>& measured);

}  // namespace modaltyre::contact
