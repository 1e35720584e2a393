#pragma once
// Presentation of footprint results (table, JSON, plot) of `footprint`, and the conversion that
// lets the model's own operator and the effects' predictor be reported alike.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/predictor.h"

namespace modaltyre::app {

/// Throws ComputationError naming the first load case that did not converge.
void require_converged(const std::vector<contact::Prediction>& cases);
/// Every case outside the model's validity range (contact/validity.h) as a warning on stderr.
void warn_outside_validity(const contact::TyreConfig& config,
                           const std::vector<contact::Prediction>& cases);
/// `footprint.load` of each case is the applied load; "valid" and its reason per case.
nlohmann::json footprint_json(const contact::TyreModel& model,
                              const std::vector<contact::Prediction>& cases);
void print_footprint_table(const contact::TyreModel& model,
                           const std::vector<contact::Prediction>& cases);
void plot_pressures(const std::vector<contact::Prediction>& cases,
                    const contact::TyreConfig& config, const std::string& path);

}  // namespace modaltyre::app
