#pragma once
// The CSV of a sweep: the condition/parameter columns of the plan, then the observables; read
// back unchanged as measured data by read_measurements() (measurements.h).
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "modaltyre/studies/sweep_plan.h"
#include "modaltyre/studies/sweep_run.h"

namespace modaltyre::studies {

/// Per case, the standard deviations of sinking, length and width (`sweep --uncertainty`,
/// docs/uncertainty.md section 8); NaN where not computed (an empty cell).
using SweepStd = std::array<double, 3>;

/// One CSV line of case i (with its trailing newline), as in sweep_csv(); with `std`, the
/// columns of sweep_std_columns() at its end.
std::string sweep_csv_row(const SweepPlan& plan, const SweepRow& row, std::size_t i,
                          const SweepStd* std = nullptr);
/// The CSV header line (with its trailing newline), as in sweep_csv().
std::string sweep_csv_header(const SweepPlan& plan, bool with_std = false);

/// sinking_std_mm, length_std_mm, width_std_mm: read back by read_measurements() as the
/// observables' noise.
const std::vector<std::string>& sweep_std_columns();

/// Observable columns, after the condition/parameter columns: sinking_mm, length_mm, width_mm,
/// rolling_resistance_N (predictor.h's observables, read back by read_measurements()), then
/// vertical_stiffness_N_mm, peak_pressure_kPa, iterations, status (ok | failed), message.
const std::vector<std::string>& sweep_observable_columns();

/// The CSV text: header, then one line per case; numbers with %.10g, text fields quoted when
/// they hold a comma or a quote. Byte-identical for identical rows.
/// With `stds` (one per case), the standard-deviation columns last.
std::string sweep_csv(const SweepPlan& plan, const SweepResult& result,
                      const std::vector<SweepStd>* stds = nullptr);

/// Formats a number as in the sweep CSV (%.10g).
std::string sweep_number(double v);
/// Quotes a CSV field if needed (comma, quote; newlines become spaces).
std::string csv_field(const std::string& text);

}  // namespace modaltyre::studies
