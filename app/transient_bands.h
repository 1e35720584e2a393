#pragma once
// `transient --uncertainty` (issue 35, docs/uncertainty.md section 8): the config's uncertain
// inputs propagated to a scenario's summary (the final sinking, length, width and area; the
// rolling resistance of rolling and cleat; the free vibration's period and logarithmic
// decrement; the soil's sinkage and compaction resistance), by re-running the scenario at every
// perturbation (uncertainty::propagate_outputs).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/transient/driver.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::app {

struct TransientBands {
  std::vector<std::string> names;  ///< the summary's JSON names (final.* and free_vibration.*)
  uncertainty::PropagationResult result;  ///< one row
};

/// The summary values of a completed run, in the order of `names` (the names are filled when
/// empty, and a run whose summary has other names is refused by the caller).
std::vector<double> transient_summary(const transient::TransientResult& r,
                                      std::vector<std::string>* names = nullptr);

TransientBands transient_bands(const contact::TyreConfig& config, transient::Scenario scenario,
                               const transient::TransientResult& nominal,
                               const uncertainty::PropagationOptions& propagation);

/// `uncertainty: {name: {value, std, p025, p975}}` and the method, check and inputs.
void add_transient_bands_json(nlohmann::json& document, const TransientBands& bands);

void print_transient_bands(const TransientBands& bands);

}  // namespace modaltyre::app
