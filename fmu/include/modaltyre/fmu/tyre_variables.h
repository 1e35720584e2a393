#pragma once
// The tyre FMU's variables, named as Project Chrono's tyre FMU (FMU_ForceElementTire) names
// them so that a Chrono vehicle FMU can drive it: the wheel state in, the wheel load out, a
// single-point terrain query, and the parameters step_size and road_profile. ISO frame (x
// forward, y left, z up), spin axis the wheel's y: forward rolling has ang_vel.y > 0. Value
// references are fixed here (the host reads them from modelDescription.xml).
#include <string>

#include "modaltyre/fmu/model_description.h"
#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::fmu {

/// Real value references.
namespace vr {
inline constexpr unsigned pos_x = 0, pos_y = 1, pos_z = 2;
inline constexpr unsigned rot_e0 = 3, rot_e1 = 4, rot_e2 = 5, rot_e3 = 6;
inline constexpr unsigned lin_vel_x = 7, lin_vel_y = 8, lin_vel_z = 9;
inline constexpr unsigned ang_vel_x = 10, ang_vel_y = 11, ang_vel_z = 12;
inline constexpr unsigned terrain_height = 13;
inline constexpr unsigned terrain_normal_x = 14, terrain_normal_y = 15, terrain_normal_z = 16;
inline constexpr unsigned terrain_mu = 17;
inline constexpr unsigned load_point_x = 20, load_point_y = 21, load_point_z = 22;
inline constexpr unsigned force_x = 23, force_y = 24, force_z = 25;
inline constexpr unsigned moment_x = 26, moment_y = 27, moment_z = 28;
inline constexpr unsigned query_x = 29, query_y = 30, query_z = 31;
/// Diagnostics of the in-plane model (outputs beyond Chrono's set).
inline constexpr unsigned deflection = 32, contact_length = 33, slip_ratio = 34;
/// A soil FMU's outputs (soil_parameters.h).
inline constexpr unsigned soil_sinkage = 35, compaction_resistance = 36;
inline constexpr unsigned step_size = 40;
/// A soil FMU's parameters, in soil_parameters()'s order from here.
inline constexpr unsigned first_soil_parameter = 50;
/// String value references.
inline constexpr unsigned road_profile = 0;
/// Boolean value references.
inline constexpr unsigned rim_contact = 0;
}  // namespace vr

/// The range of step_size [s]: the transient resolves the carcass modes (100-300 Hz) with its
/// own steps, so step_size bounds only the hub's carried motion; below 10 us a millisecond would
/// take a hundred sub-steps for nothing, above a second the hub's motion is no longer resolved.
inline constexpr double kMinStepSize_s = 1e-5, kMaxStepSize_s = 1.0;
/// Friction coefficients accepted (ground::CoulombFriction's range).
inline constexpr double kMaxFriction = 10;

/// What a packaged FMU's description is built from.
struct TyreDescriptionInfo {
  std::string tyre_name;              ///< the config's tyre.name
  std::string guid;                   ///< of this FMU (its config and data)
  double outer_radius_m = 0.3;        ///< start of wheel_state.pos.z: touching a road at z = 0
  double friction_coefficient = 0.8;  ///< start of terrain_mu
  double step_size_s = 1e-3;          ///< start of step_size and the default experiment's step
  double section_height_m = 0;        ///< the rim's check (tyre_wheel.h); 0: not known
  /// A soil FMU: the packed soil (its keys become parameters) and whether the tyre runs its 3D
  /// patch (which models the Kelvin-Voigt soil's elastic law only). Null: a road FMU.
  const ground::GroundSettings* soil = nullptr;
  bool patch_3d = false;
};

/// The model identifier: the name of the shared library under binaries/linux64/.
inline constexpr const char* kModelIdentifier = "ModalTyre";

/// The description of the tyre FMU (valid: validate() returns nothing; tested).
ModelDescription tyre_model_description(const TyreDescriptionInfo& info);

}  // namespace modaltyre::fmu
