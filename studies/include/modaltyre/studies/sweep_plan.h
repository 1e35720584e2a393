#pragma once
// The plan of a sweep: every case of the grid, its conditions and the config of its model
// (one per distinct parameter combination), checked before anything is computed.
#include <cstddef>
#include <string>
#include <vector>

#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/studies/sweep_spec.h"

namespace modaltyre::studies {

struct SweepCase {
  std::vector<std::size_t> value_index;     ///< per grid axis
  std::size_t model = 0;                    ///< index into SweepPlan::models
  contact::OperatingConditions conditions;  ///< given ones, the rest from the model's config
  contact::LoadCase load;                   ///< conditions.load_N and .horizontal_force_N
};

struct SweepPlan {
  SweepSpec spec;
  std::vector<std::string> columns;  ///< condition/parameter columns of the CSV
  /// Per column: grid axis index, or -1 for a condition that comes from set:.
  std::vector<int> column_axis;
  /// Per column: the CSV cell of a condition from set: (empty for grid columns).
  std::vector<std::string> set_cells;
  std::vector<contact::TyreConfig> models;  ///< one per distinct parameter combination
  std::vector<std::vector<std::string>> model_overrides;  ///< "key=value" list per model
  std::vector<SweepCase> cases;                           ///< grid order, last axis fastest

  /// Cells of the condition/parameter columns of case i (formatted as in the CSV).
  std::vector<std::string> cells(std::size_t i) const;
};

/// Expands the grid, builds and validates the config of every distinct parameter combination
/// (cheap: no model is built) and checks every condition value. InputError on any problem.
SweepPlan plan_sweep(const SweepSpec& spec);

}  // namespace modaltyre::studies
