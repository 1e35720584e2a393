#pragma once
// Presentation of footprint results (table, plot) of `footprint`; the JSON document is
// report/footprint_json.h.
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/predictor.h"

namespace modaltyre::app {

/// Every case outside the model's validity range (contact/validity.h) as a warning on stderr.
void warn_outside_validity(const contact::TyreConfig& config,
                           const std::vector<contact::Prediction>& cases);
/// The header states `conditions` (every case's but its load and horizontal force).
void print_footprint_table(const contact::TyreModel& model,
                           const std::vector<contact::Prediction>& cases,
                           const contact::OperatingConditions& conditions);
void plot_pressures(const std::vector<contact::Prediction>& cases,
                    const contact::TyreConfig& config, const std::string& path);

}  // namespace modaltyre::app
