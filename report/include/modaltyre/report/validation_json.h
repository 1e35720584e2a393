#pragma once
// The JSON document of `modaltyre validate --json` (and the Python module's validate).
#include <nlohmann/json.hpp>

#include "modaltyre/contact/validity.h"
#include "modaltyre/studies/validation.h"

namespace modaltyre::report {

/// config, effects, per row (measured, predicted, relative errors, calibration role,
/// conditions, validity), RMS over the predicted rows, the declared calibration's result.
nlohmann::json validation_json(const studies::ValidationReport& rep);

/// One row's or run's conditions by catalogue name (core/conditions.h), words as words:
/// {"load_N": .., "horizontal_force_N": .., "pressure_kPa": .., "hold_s": .., "speed_kmh": ..,
/// "branch": "load", "surface": "rigid"}.
nlohmann::json conditions_json(const contact::OperatingConditions& c);

/// A predicted row outside the model's validity range (contact/validity.h) is flagged.
contact::Validity row_validity(const contact::TyreConfig& config, const studies::ValidationRow& r);

}  // namespace modaltyre::report
