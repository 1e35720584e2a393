#pragma once
// Roving-hammer modal test data: one record per (mode, measurement point).
//
// File format (long CSV, one row per mode and point):
//   mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential
// Shape values are mass-normalised, unit kg^-1/2, so that sum_k phi_i phi_j / omega_k^2 is a
// compliance in m/N (see carcass_kernel.h). Points must be N >= 6, equally spaced on the
// circumference, the same count for every mode. An optional last column `scaling` says how the
// shapes are scaled, the same word on every row: `mass_normalised` (the default when the column
// is absent) or `unscaled` (`modaltyre ema --unscaled`: largest value 1, no physical scale).
// Optional columns freq_std_hz, damping_std, radial_std, tangential_std (written by `ema`,
// docs/uncertainty.md section 5): standard deviations of the row's values, all four or none.
#include <string>
#include <vector>

namespace modaltyre::modal {

struct MeasuredMode {
  int id = 0;                      ///< mode number as in the file
  double freq_hz = 0.0;            ///< natural frequency [Hz], > 0
  double damping_ratio = 0.0;      ///< modal damping ratio [-], 0 <= zeta < 1
  std::vector<double> angle_rad;   ///< measurement angles [rad], sorted ascending
  std::vector<double> radial;      ///< radial shape values [kg^-1/2]
  std::vector<double> tangential;  ///< tangential shape values [kg^-1/2]
  /// Standard deviations from the file's optional columns; 0 and empty when it has none.
  double freq_std_hz = 0.0, damping_std = 0.0;
  std::vector<double> radial_std, tangential_std;  ///< per point, as radial / tangential
  int first_line = 0;                              ///< line of its first row (for messages)
};

struct HammerData {
  std::string path;
  int points = 0;                   ///< N, points per mode
  std::vector<MeasuredMode> modes;  ///< in the order they first appear
  /// The shapes carry no mass normalisation (column `scaling` = `unscaled`): their scale, and so
  /// any compliance or footprint built on them, is arbitrary. What the model does with them is
  /// the caller's decision; the reader only reports it.
  bool unscaled = false;
  bool has_std = false;  ///< the file carries the standard-deviation columns
};

/// Minimum number of points a mode needs (orders 0..2 resolvable).
inline constexpr int kMinHammerPoints = 6;

/// Reads and validates a hammer file; every problem is an InputError with file, line, column.
HammerData read_hammer_csv(const std::string& path);

}  // namespace modaltyre::modal
