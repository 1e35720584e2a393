#pragma once
// Measured footprint data with operating conditions: the input of `validate` and `discover`.
//
// CSV columns (header names, any order):
//   conditions   load_N (required), optional pressure_kPa, hold_s, speed_kmh,
//                horizontal_force_N, branch (load | unload), surface (rigid | soil): units,
//                ranges and words of the condition catalogue (core/conditions.h)
//   observables  any of sinking_mm, length_mm, width_mm (> 0), rolling_resistance_N
//   their noise  optional standard deviations named with _std before the unit (sinking_std_mm,
//                length_std_mm, width_std_mm, rolling_resistance_std_N; >= 0, empty or NA
//                where not known), beside the observable's column (docs/uncertainty.md section 7)
//   traction     rows of a traction test (steady rolling at slip on the soil, `modaltyre
//                traction`): slip (ISTVS, against the rolling radius: contact/traction.h), optional
//                pass (1-20), and any of drawbar_pull_N, soil_sinkage_mm, torque_Nm
//                (studies/traction_rows.h). A row with a slip is a traction row, one without a
//                footprint row; each takes only its own observables.
// Missing optional condition columns take the config's values (TyreConfig::default_conditions).
// Columns `modaltyre sweep` writes beside them (vertical_stiffness_N_mm, peak_pressure_kPa,
// iterations, status, message and dotted config keys such as tread.modulus_MPa) are accepted
// and ignored, so that a sweep's output can be used as measured data; a row whose status is
// not "ok" is refused. Any other column is an error (a typo must not silently drop data).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::studies {

/// What a traction row states besides its load and speed (studies/traction_rows.h).
struct TractionPoint {
  double slip = 0;  ///< ISTVS slip against the rolling radius, [-0.99, 1]
  int pass = 1;     ///< the pass over the same track, 1-20
};

struct MeasuredRow {
  int row = 0;                                 ///< 1-based data row
  int line = 0;                                ///< line in the file
  contact::OperatingConditions conditions;     ///< the file's, the config's where it has none
  std::optional<TractionPoint> traction;       ///< a traction row (else a footprint row)
  std::map<std::string, double> observed;      ///< observable name -> measured value
  std::map<std::string, double> observed_std;  ///< observable name -> its stated std, where given

  /// A measured observable by name (nullopt when this row does not measure it).
  std::optional<double> value(const std::string& observable) const;
};

struct MeasurementSet {
  std::string path;
  std::vector<MeasuredRow> rows;
  /// Observable columns present: the footprint's in observable_names() order, then the
  /// traction's in traction_observable_names() order.
  std::vector<std::string> observables;
  std::vector<std::string> conditions;  ///< condition columns present in the file
  /// The file has no column but load_N and sinking_mm, length_mm, width_mm (the shape of seed
  /// 001 Table 3): its rows state no condition besides the load.
  bool loads_only = false;
  /// Rows of each kind.
  int traction_rows() const;
  int footprint_rows() const { return static_cast<int>(rows.size()) - traction_rows(); }
};

/// The column of an observable's standard deviation: "sinking_mm" -> "sinking_std_mm".
std::string std_column(const std::string& observable);

/// The condition column names (the catalogue's, core/conditions.h), in the order discover
/// reports them.
const std::vector<std::string>& condition_names();

/// Value of a condition as a number (branch: 0 load / 1 unload; surface: 0 rigid / 1 soil).
double condition_value(const contact::OperatingConditions& c, const std::string& name);

/// Reads a measurement file; every problem is an InputError naming file, line and column.
MeasurementSet read_measurements(const std::string& path, const contact::TyreConfig& defaults);

}  // namespace modaltyre::studies
