#pragma once
// The footprint command's library half: its load cases from the command-level inputs (loads,
// horizontal force) with their checks, and its JSON document (`modaltyre footprint --json`, the
// Python module's Tyre.footprint).
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/footprint_measures.h"
#include "modaltyre/contact/predictor.h"

namespace modaltyre::report {

/// One case per load at the config's default conditions, with `horizontal_force_N` (the
/// config's when absent). InputError (naming --load or --fx) for a load outside
/// [kMinLoad_N, kMaxLoad_N], a horizontal force on the 3D patch, or |F_x| > 1.5 F_z (no adhesion
/// carries more).
std::vector<contact::OperatingConditions> footprint_cases(const contact::TyreConfig& config,
                                                          const std::vector<double>& loads_N,
                                                          std::optional<double> horizontal_force_N);

/// Throws ComputationError naming the first load case that did not converge.
void require_converged(const std::vector<contact::Prediction>& cases);

/// The document of `footprint --json`: tyre, config, effects, model, and per case the load,
/// validity, sinking, length, width, pressures per unit (and the 3D map), residuals.
nlohmann::json footprint_json(const contact::TyreModel& model,
                              const std::vector<contact::Prediction>& cases);

/// `map: {x_mm: [...], y_mm: [...], pressure_kPa: [[... one row per y ...]]}` of a 3D case:
/// the sections in contact and two either side, every column of the tread.
nlohmann::json pressure_map_json(const contact::Patch3dResult& r);

/// The footprint's measures (contact/footprint_measures.h), as the JSON prints them.
using contact::cell_area_in_contact_m2;
using contact::peak_pressure_Pa;

/// Names of the effects switched on, in catalogue order.
std::vector<std::string> enabled_effects(const contact::EffectsConfig& effects);

}  // namespace modaltyre::report
