#pragma once
// The JSON document of `modaltyre traction --json` (docs/soil.md section 5).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::report {

/// One case's fields (slip, load_N, soil_sinkage_mm, rut_depth_mm, drawbar_pull_N, thrust_N,
/// motion_resistance_N, torque_Nm, entry_angle_deg, exit_angle_deg, bekker_width_mm, ...), with
/// `pass` when passes > 1.
nlohmann::json traction_case_json(const contact::TractionResult& r, bool with_pass);

/// Per curve (load and pass): load_N, pass, towed_point {slip, drawbar_pull_N} and
/// self_propelled_point {slip, torque_Nm} (null where the curve does not cross zero).
nlohmann::json traction_curves_json(const std::vector<contact::TractionResult>& results);

/// The document: tyre, ground, model (flexible tyre on the 2D or the 3D patch, as the results
/// were computed, or the rigid cylinder), the slip's definition, cases, and per curve (load and
/// pass) its towed and self-propelled points (`curves`; with one curve also at the top level).
nlohmann::json traction_json(const contact::TyreConfig& config,
                             const ground::GroundSettings& ground,
                             const std::vector<contact::TractionResult>& results, bool rigid,
                             int passes,
                             contact::SlipReference reference = contact::SlipReference::rolling,
                             double speed_km_h = 0);

/// ComputationError naming the first failed case with its reason.
void require_traction_converged(const std::vector<contact::TractionResult>& results);

/// What `modaltyre traction` runs on (shared by the command and Python's modaltyre.traction).
struct TractionSetup {
  contact::TyreConfig config;  ///< as read: a 3D config runs its 3D patch unless patch_2d
  ground::GroundSettings ground;
  bool rigid = false;  ///< tyre.rigid: the rigid cylinder of the outer radius
  /// A 3D config's 2D patch at its 3D tread width (`traction --patch 2d`, the fast variant;
  /// docs/soil.md section 9); the rigid cylinder takes the tread width either way.
  bool patch_2d = false;
  /// The slip's reference radius (`traction --slip-reference`): the rolling radius r_e on the
  /// rigid road at the same load (ISTVS, the default) or the outer radius R0.
  contact::SlipReference slip_reference = contact::SlipReference::rolling;
  /// The rolling speed of the tyre's flexing loss [km/h] (`traction --speed-km-h`, [0, 100];
  /// 0: none); negative: the config's transient.rolling.speed_km_h.
  double speed_km_h = -1;
  std::string ground_source;  ///< the file that gave the ground (for its messages)
};

/// Reads the tyre config and the soil: `ground_path` (a soil file; empty: the config's ground:
/// section). With a soil file the ground.* overrides go to it, the rest to the config;
/// tyre.rigid is applied after the ground (the config reader refuses a rigid tyre on a road).
/// InputError when the ground is not a soil, naming the file and ground.model.
TractionSetup traction_setup(const std::string& config_path, const std::string& ground_path,
                             const std::vector<std::string>& overrides);

/// The 3D config's 2D patch (docs/soil.md sections 5, 9): the 3D tread width as contact width.
void use_2d_patch_of_3d(contact::TyreConfig& config);

/// The speed of the flexing loss [km/h]: setup.speed_km_h, or the config's rolling scenario's.
double traction_speed_km_h(const TractionSetup& setup);

/// Steady rolling for every load and slip (case by case, pass by pass): failed slips are rows
/// with their reason (ComputationError only when every case failed).
std::vector<contact::TractionResult> run_traction(const TractionSetup& setup,
                                                  const std::vector<double>& loads_N,
                                                  const std::vector<double>& slips, int passes);

}  // namespace modaltyre::report
