#pragma once
// Presentation of footprint results (table, JSON, plot), shared by footprint and validate.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"

namespace modaltyre::app {

/// Throws ComputationError naming the first load case that did not converge.
void require_converged(const std::vector<contact::FootprintResult>& results);
nlohmann::json footprint_json(const contact::TyreModel& model,
                              const std::vector<contact::FootprintResult>& results);
void print_footprint_table(const contact::TyreModel& model,
                           const std::vector<contact::FootprintResult>& results);
void plot_pressures(const std::vector<contact::FootprintResult>& results,
                    const contact::TyreConfig& config, const std::string& path);

}  // namespace modaltyre::app
