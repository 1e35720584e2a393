#pragma once
// The JSON document of `modaltyre validate --json` (and the Python module's validate).
#include <nlohmann/json.hpp>

#include "modaltyre/contact/validity.h"
#include "modaltyre/studies/validation.h"

namespace modaltyre::report {

/// config, effects, per row (measured, predicted, relative errors, calibration role,
/// conditions, validity), RMS over the predicted rows, the declared calibration's result.
nlohmann::json validation_json(const studies::ValidationReport& rep);

/// A predicted row outside the model's validity range (contact/validity.h) is flagged.
contact::Validity row_validity(const contact::TyreConfig& config, const studies::ValidationRow& r);

}  // namespace modaltyre::report
