#pragma once
// The transient command's outputs as data: the JSON summary of `modaltyre transient --json` and
// the time series of its --csv (the Python module's transient returns both).
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "modaltyre/transient/transient.h"

namespace modaltyre::report {

/// scenario, simulated and wall time, steps, the final state, contact switches, solver
/// counters and the model's size.
nlohmann::json transient_json(const transient::TransientModel& model,
                              const transient::TransientResult& r);

/// The sampled time series, column name (with unit) and values, in the order of the CSV:
/// t_s, load_N, hub_displacement_mm, sinking_mm, contact_length_mm, longitudinal_force_N, and on
/// the 3D patch width_mm, contact_area_mm2.
std::vector<std::pair<std::string, std::vector<double>>> transient_series(
    const transient::TransientResult& r);

}  // namespace modaltyre::report
