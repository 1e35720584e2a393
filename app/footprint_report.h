#pragma once
// Presentation of footprint results (table, plot) of `footprint`; the JSON document is
// report/footprint_json.h.
#include <string>
#include <vector>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::app {

/// Every case outside the model's validity range (contact/validity.h) as a warning on stderr.
void warn_outside_validity(const contact::TyreConfig& config,
                           const std::vector<contact::Prediction>& cases);
/// The header states `conditions` (every case's but its load and horizontal force).
void print_footprint_table(const contact::TyreModel& model,
                           const std::vector<contact::Prediction>& cases,
                           const contact::OperatingConditions& conditions);
/// The bands of `footprint --uncertainty`: each output as its value and 2.5-97.5 % band
/// (report::band_text: the JSON's value, p025, p975) to the digits the band supports, the method
/// and its check, the inputs.
void print_uncertainty_table(const uncertainty::PropagationResult& r);

/// One row's bands as `name  value [p025, p975]` lines (names in the bands' order), after the
/// method and its check, then the inputs: tir export's and transient's --uncertainty.
void print_named_bands(const std::vector<std::string>& names,
                       const uncertainty::PropagationResult& r);
/// What a footprint plot shows, for its title: the tyre, the ground it stands on and the loads,
/// e.g. "SF-350 195/60R14 on LETE sand (bekker), 2.13-8.32 kN" (issue 44 item 4).
std::string footprint_plot_subject(const contact::TyreConfig& config,
                                   const std::vector<contact::Prediction>& cases);

void plot_pressures(const std::vector<contact::Prediction>& cases,
                    const contact::TyreConfig& config, const std::string& path);

}  // namespace modaltyre::app
