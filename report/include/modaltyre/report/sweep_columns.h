#pragma once
// A sweep's result as named columns (the Python module's sweep): the columns of its CSV
// (studies/sweep_output.h), in the CSV's order, numbers as numbers.
#include <string>
#include <vector>

#include "modaltyre/studies/sweep_plan.h"
#include "modaltyre/studies/sweep_run.h"

namespace modaltyre::report {

struct SweepColumn {
  std::string name;
  bool numeric = false;
  std::vector<double> numbers;     ///< numeric columns; NaN where a failed case has no value
  std::vector<std::string> texts;  ///< the other columns, as the CSV cells (unquoted)
};

/// Every column of sweep_csv(): the condition/parameter columns (numeric when every cell is a
/// number), then the observables; `valid` and `status` are text as in the CSV.
std::vector<SweepColumn> sweep_columns(const studies::SweepPlan& plan,
                                       const studies::SweepResult& result);

}  // namespace modaltyre::report
