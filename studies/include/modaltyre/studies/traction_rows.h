#pragma once
// Rows of a traction test in a measurement file (measurements.h): the soil-bin engineer's
// drawbar-pull, sinkage and torque against slip at a load, which `discover` compares with the
// model's `traction` (contact/traction.h) as it compares footprints with `footprint`.
//
// Columns (header names, any order, beside the footprint's):
//   slip             ISTVS slip against the rolling radius r_e of the same tyre at the same load
//                    free-rolling on the rigid road, as `modaltyre traction` takes it: driven
//                    s = 1 - V / (omega r_e) > 0, braked s = omega r_e / V - 1 < 0; [-0.99, 1]
//                    (a braked wheel locks at -1, a driven one spins in place at 1)
//   pass             optional, 1-20: the pass over the same track (1 when absent or empty)
//   drawbar_pull_N   [-1e7, 1e7]; soil_sinkage_mm (0, 1e4]; torque_Nm [-1e7, 1e7]
// Any observable may be empty or NA in a row; a row needs one. load_N is the row's load and
// speed_kmh the speed of the tyre's flexing loss (the config's transient.rolling.speed_km_h when
// the file has no speed_kmh column, as `traction` takes it). A row with a slip must leave the
// footprint observables empty and one without must leave the traction observables empty: a
// mixed-up row is an InputError naming file, line and column.
#include <string>
#include <vector>

#include "modaltyre/core/csv.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::studies {

/// drawbar_pull_N, soil_sinkage_mm, torque_Nm.
const std::vector<std::string>& traction_observable_names();
bool is_traction_observable(const std::string& name);

/// Adds the traction columns to a measurement file's schema.
void add_traction_columns(CsvSchema& schema);

/// Refuses a file whose traction columns cannot make rows: observables without a slip column,
/// a slip or pass column without a traction observable (InputError at line 1 naming the column).
void check_traction_columns(const CsvTable& table);

/// slip and pass: read with a traction row (an empty slip is a footprint row), not as conditions.
bool is_traction_column(const std::string& name);

/// Whether data row i of the table is a traction row (its slip cell is given).
bool is_traction_row(const CsvTable& table, std::size_t i);

/// Reads the traction part of data row i into `row` (conditions already read): slip, pass and
/// the observables, each checked against its range. `rolling_speed_kmh`: the row's speed when
/// the file has no speed_kmh column.
void read_traction_row(const CsvTable& table, std::size_t i,
                       const std::vector<std::string>& observables, double rolling_speed_kmh,
                       MeasuredRow& row);

/// Refuses the traction observables in a footprint row (no slip) and the footprint
/// observables in a traction row, naming the first such cell.
void refuse_mixed_row(const CsvTable& table, std::size_t i, bool traction_row);

}  // namespace modaltyre::studies
