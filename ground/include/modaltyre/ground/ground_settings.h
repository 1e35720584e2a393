#pragma once
// The ground under the tyre as configured: section `ground:` of a tyre config, or a soil file
// (a YAML document with a top-level `ground:` section, configs/soils/). Every key can be set
// with --set ground.KEY=VALUE. Keys (units in the names; Bekker's in Wong's units):
//
//   ground:
//     model: bekker                 # rigid | profile | kelvin_voigt | bekker
//     name: LETE sand               # free text, printed with the results
//     source: "Wong, Theory of Ground Vehicles, 4th ed., Table 2.3"
//     friction_coefficient: 0.8     # rigid, profile: Coulomb mu of the road
//     profile_csv: road.csv         # profile: x_m,height_m (relative to this file's folder)
//     bekker:
//       n: 0.79
//       k_c: 102                    # kN/m^(n+1)
//       k_phi: 5301                 # kN/m^(n+2)
//       cohesion_kPa: 1.3           # Janosi-Hanamoto shear (shear.h)
//       friction_angle_deg: 31.1
//       shear_modulus_K_mm: 12
//       unloading: {k0: 0, Au: 5e5} # Wong's k_u = k0 [kN/m^3] + Au [kN/m^4] z_max; absent
//                                   # or enabled: false: rigid-plastic (no rebound)
//       wong_reece: {enabled: false, c1: 0.43, c2: 0.32, c3: 0}   # soil_options.h
//       slip_sinkage: {enabled: false, k1: 1, k2: 0.5}            # soil_options.h
//       bulldozing: {enabled: false, unit_weight_kN_m3: 15.7}     # soil_options.h
//       uncertainty:                # optional: the soil's stated scatter (SoilScatter below)
//         k_phi_std_percent: 10     # also k_c_std_percent, n_std, cohesion_std_percent,
//         friction_angle_std_deg: 1 # shear_modulus_K_std_percent; absent: none
//     kelvin_voigt:                 # seed 000 eq. 23-28 (kelvin_voigt_soil.h)
//       E2_MPa: 2
//       eta2_kPa_s: 0
//       layer_mm: 200
//       elastic_share: 1            # k_E (seed 000 eq. 24)
//       cohesion_kPa: 0             # its Janosi-Hanamoto shear
//       friction_angle_deg: 30
//       shear_modulus_K_mm: 25
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/core/config_tree.h"
#include "modaltyre/ground/bekker_wong.h"
#include "modaltyre/ground/kelvin_voigt_soil.h"
#include "modaltyre/ground/road_profile.h"
#include "modaltyre/ground/shear.h"
#include "modaltyre/ground/soil_options.h"

namespace modaltyre::ground {

enum class GroundModel { rigid, profile, kelvin_voigt, bekker };

const char* to_string(GroundModel model);

/// A Bekker soil's stated scatter (ground.bekker.uncertainty): one standard deviation of each
/// parameter, from repeated bevameter and shear tests on the same soil (docs/uncertainty.md
/// section 9); the uncertain inputs of `--uncertainty` (uncertainty/inputs.h). All 0 (the
/// default): the soil is taken as exact, as Wong's Table 2.3 states it.
struct SoilScatter {
  double k_c_rel_std = 0;             ///< k_c_std_percent / 100
  double k_phi_rel_std = 0;           ///< k_phi_std_percent / 100
  double n_std = 0;                   ///< n_std, absolute (n is dimensionless)
  double cohesion_rel_std = 0;        ///< cohesion_std_percent / 100
  double friction_angle_std_deg = 0;  ///< friction_angle_std_deg
  double shear_modulus_rel_std = 0;   ///< shear_modulus_K_std_percent / 100
};

struct GroundSettings {
  GroundModel model = GroundModel::rigid;
  std::string name, source;
  double friction_coefficient = 0.8;           ///< rigid road and profile: Coulomb mu
  std::string profile_csv;                     ///< resolved path (profile)
  std::shared_ptr<const RoadProfile> profile;  ///< read from profile_csv by the reader
  BekkerParams bekker;
  /// The unloading: block's values whether enabled or not (the soil_unloading effect switches
  /// them on; bekker.unloading holds them only when on).
  std::optional<WongUnloading> stated_unloading;
  JanosiParams bekker_shear{0, 30, 25};
  WongReeceStress wong_reece;  ///< Wong and Reece's stress distribution (soil_options.h)
  SlipSinkage slip_sinkage;    ///< sinkage growing with slip (soil_options.h)
  Bulldozing bulldozing;       ///< the soil pushed ahead of the tyre (soil_options.h)
  SoilScatter bekker_scatter;  ///< the Bekker soil's stated scatter (none by default)
  KelvinVoigtParams kelvin_voigt;
  JanosiParams kelvin_voigt_shear{0, 30, 25};
  /// The soil's three shear keys were stated (read_ground_settings); traction needs them.
  bool shear_stated = false;

  /// A deformable soil (bekker, kelvin_voigt), as opposed to a rigid road.
  bool soil() const { return model == GroundModel::bekker || model == GroundModel::kelvin_voigt; }
  /// The soil's normal law with Bekker's width b (ignored by the Kelvin-Voigt soil), stretched
  /// by the slip sinkage at `slip` (ISTVS; slip_sinkage.h) when that is enabled on a Bekker soil;
  /// std::invalid_argument for a rigid ground.
  std::unique_ptr<PressureSinkage> normal_law(double b_m, double slip = 0) const;
  /// The soil's Janosi-Hanamoto parameters (std::invalid_argument for a rigid ground).
  const JanosiParams& soil_shear() const;
  /// The tangential law: Janosi-Hanamoto on soil, Coulomb with the tread's stick stiffness
  /// [Pa/m] on a rigid road.
  std::unique_ptr<ShearLaw> shear_law(double stick_stiffness_Pa_m) const;
};

/// Reads a `ground:` section; errors name file, line and key (InputError). Relative paths are
/// taken from `tree`'s folder.
GroundSettings read_ground_settings(const ConfigSection& section, const ConfigTree& tree);

/// Reads a soil file (top-level `ground:` and nothing else) with --set overrides of the form
/// "ground.KEY=VALUE"; unknown keys refused.
GroundSettings load_ground_file(const std::string& path,
                                const std::vector<std::string>& overrides = {});

}  // namespace modaltyre::ground
