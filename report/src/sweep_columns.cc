#include "modaltyre/report/sweep_columns.h"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/studies/sweep_output.h"

namespace modaltyre::report {
namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// A cell that is a whole number as written (the sweep file's scalar text).
bool parse_number(const std::string& cell, double& value) {
  const auto v = parse_finite_double(cell);
  if (v) value = *v;
  return v.has_value();
}

}  // namespace

std::vector<SweepColumn> sweep_columns(const studies::SweepPlan& plan,
                                       const studies::SweepResult& result) {
  MODALTYRE_CHECK(result.rows.size() == plan.cases.size(), "sweep rows and cases disagree");
  const std::size_t n = plan.cases.size();
  std::vector<SweepColumn> cols;
  for (const auto& name : plan.columns) cols.push_back({name, true, {}, {}});
  for (std::size_t i = 0; i < n; ++i) {
    const auto cells = plan.cells(i);
    for (std::size_t c = 0; c < cells.size(); ++c) cols[c].texts.push_back(cells[c]);
  }
  for (auto& col : cols) {
    for (const auto& cell : col.texts) {
      double v = 0;
      col.numeric = col.numeric && parse_number(cell, v);
      col.numbers.push_back(v);
    }
    if (col.numeric) col.texts.clear();
    if (!col.numeric) col.numbers.clear();
  }
  // sweep_observable_columns(): six numbers, iterations, status, message, valid.
  const auto& names = studies::sweep_observable_columns();
  MODALTYRE_CHECK(names.size() == 10, "sweep observable columns changed");
  for (std::size_t k = 0; k < names.size(); ++k) {
    cols.push_back({names[k], k < 7, {}, {}});
    auto& col = cols.back();
    for (const auto& r : result.rows) {
      const double numbers[] = {r.sinking_mm,
                                r.length_mm,
                                r.width_mm,
                                r.rolling_resistance_N,
                                r.vertical_stiffness_N_mm,
                                r.peak_pressure_kPa,
                                static_cast<double>(r.iterations)};
      if (k < 7) {
        col.numbers.push_back(r.ok ? numbers[k] : kNone);
      } else if (k == 7) {
        col.texts.push_back(r.ok ? "ok" : "failed");
      } else if (k == 8) {
        col.texts.push_back(r.message);
      } else {
        col.texts.push_back(r.ok ? (r.valid ? "true" : "false") : "");
      }
    }
  }
  return cols;
}

}  // namespace modaltyre::report
