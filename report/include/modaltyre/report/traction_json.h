#pragma once
// The JSON document of `modaltyre traction --json` (docs/soil.md section 5).
#include <nlohmann/json.hpp>
#include <vector>

#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::report {

/// One case's fields (slip, load_N, soil_sinkage_mm, rut_depth_mm, drawbar_pull_N, thrust_N,
/// motion_resistance_N, torque_Nm, entry_angle_deg, exit_angle_deg, bekker_width_mm, ...), with
/// `pass` when passes > 1.
nlohmann::json traction_case_json(const contact::TractionResult& r, bool with_pass);

/// The document: tyre, ground, model (flexible 2D patch or rigid cylinder), cases.
nlohmann::json traction_json(const contact::TyreConfig& config,
                             const ground::GroundSettings& ground,
                             const std::vector<contact::TractionResult>& results, bool rigid,
                             int passes);

/// ComputationError naming the first failed case with its reason.
void require_traction_converged(const std::vector<contact::TractionResult>& results);

}  // namespace modaltyre::report
