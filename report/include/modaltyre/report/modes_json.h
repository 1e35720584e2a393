#pragma once
// The JSON document of `modaltyre fit-modes --json` (and the Python module's fit_modes).
#include <nlohmann/json.hpp>

#include "modaltyre/modal/mode_identification.h"

namespace modaltyre::report {

/// points, per mode (frequency, damping, kind, order, aliasing, R2, harmonic coefficients,
/// amplitude, phase, note) and the dispersion fit of the resolved radial orders.
nlohmann::json modes_json(const modal::ModeIdentification& id);

}  // namespace modaltyre::report
