#pragma once
// The tyre configuration: what a YAML file such as configs/sf350.yaml describes, in SI units.
// Config keys carry their unit in the name (outer_radius_mm, modulus_MPa); conversion to SI
// happens here and nowhere else.
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/patch3d_settings.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::contact {

struct TreadParams {
  double modulus_Pa = 6e6;     ///< storage (elastic) modulus E_tr of the tread rubber, > 0
  double tan_delta = 0.15;     ///< loss factor G_tr / E_tr (seed 001 eq. 8), 0 or >= 0.01
  double thickness_m = 0.008;  ///< radial thickness of the tread layer, > 0
  double width_m = 0.14;       ///< contact width of the 2D model's patch, > 0
  double poisson = 0.49;       ///< rubber Poisson ratio, shear modulus G = E / (2 (1 + nu))
};

struct Discretisation {
  double unit_length_m = 0.5e-3;  ///< arc length of one patch unit (seed 001 eq. 11)
  double window_m = 0.36;         ///< arc length of the candidate region around the contact centre
  int max_order = 0;              ///< highest harmonic order in the kernel, 0 = mesh Nyquist
};

struct SolverSettings {
  int max_iterations = 200;      ///< active-set iterations per load case
  double gap_tolerance = 1e-10;  ///< relative gap tolerance of the complementarity check
};

struct ValidationSettings {
  std::vector<std::string> calibrate;  ///< dotted config keys to fit (at most three)
  std::vector<int> calibration_rows;   ///< 1-based rows of the measured file (at most two)
  /// Fitted on those rows: sinking_mm, length_mm, width_mm.
  std::vector<std::string> observables = {"sinking_mm"};
};

/// Scenarios and model settings of the transient simulation (section `transient:`, see
/// transient/transient.h and docs/transient.md). Speeds in m/s, lengths in m, times in s.
struct TransientSettings {
  double hub_mass_kg = 20;     ///< reduced mass on the hub DOF (tyre + rim + fixture), >= 0.1
  int dynamic_max_order = 40;  ///< orders above it respond quasi-statically (residual)
  bool relaxation = true;      ///< Kelvin-Voigt tread (seed 001 eq. 10); false: eq. (6)
  double tread_reference_frequency_hz = 10;   ///< Omega of c = K tan(delta) / Omega (eq. 9)
  double instantaneous_stiffness_ratio = 20;  ///< glassy / relaxed tread stiffness, > 1
  double modal_damping_scale = 1;  ///< multiplies every modal damping ratio (0 = undamped)
  /// The output grid's step; 0 (the key absent or `auto`): chosen per scenario to resolve the
  /// hub bounce and a cleat (transient/output_grid.h).
  double output_step_s = 0;
  /// The smallest ramp with an automatic output step (its grid's largest step, 2 ms).
  static constexpr double kAutoOutputStepCap_s = 0.002;
  double relative_tolerance = 1e-5;
  /// Absolute error tolerance of the tread's Kelvin-Voigt states [m] (the carcass and hub
  /// displacements have 0.1 um). One unit's state moves one unit's force (k_g de), where the
  /// hub's moves every unit's in contact; docs/transient.md section 2 gives the measurements.
  double tread_tolerance_m = 1e-6;
  /// Singular values of the units' shapes [psi V] kept in the contact basis (transient/model.h):
  /// those above this fraction of the largest. Numerical, not a config key: 1e-9 drops
  /// displacements of ~1e-11 m (the default's rank 41 -> 36; its outputs move by < 1e-7
  /// relative, test ContactBasisCutoffMovesNoOutput); 1e-13 keeps every shape to rounding.
  double contact_basis_cutoff = 1e-9;
  struct LoadHold {
    double load_N = 4000, ramp_rate_N_s = 4000, hold_s = 120;
  } load_hold;
  struct FreeVibration {
    double load_N = 4000, initial_load_N = 5000, duration_s = 1;
  } free_vibration;
  struct Rolling {
    double load_N = 4000, speed_m_s = 60 / 3.6, ramp_s = 1, duration_s = 3;
  } rolling;
  struct Cleat {
    double load_N = 4000, speed_m_s = 30 / 3.6, height_m = 0.01, length_m = 0.02, ramp_s = 0.5;
    /// Across the tread, centred [m]; 0 = the whole width. The 3D patch only (cell_model.h).
    double width_m = 0;
  } cleat;
};

/// The vertical loads every input takes [N] (loads_N, --load, measured and swept load_N): below
/// 1e-6 N a footprint is numerically no contact (the 3D patch's equilibrium fails under ~1e-12 N:
/// a mean pressure of inf), above 1e7 N (1000 t on one wheel) no tyre.
constexpr double kMinLoad_N = 1e-6;
constexpr double kMaxLoad_N = 1e7;
/// The transient scenarios' loads [N]: at least the weight of 1 kg (a patch 13 mm long on the
/// SF-350); a near-zero load ramps up in a denormal time that the integrator refuses.
constexpr double kMinTransientLoad_N = 10;

/// Uncertainties a config states where no data give them (docs/uncertainty.md): relative
/// standard deviations, 0 = not stated.
struct StatedUncertainty {
  double frequency_rel_std = 0;      ///< modal.frequency_std_percent / 100, every mode
  double tread_modulus_rel_std = 0;  ///< tread.modulus_std_percent / 100
  double belt_width_rel_std = 0;     ///< modal.belt_width_std_percent / 100 (ring mass)
  /// tread.contact_width_std_percent / 100: the tread width (2D contact width and the 3D patch's
  /// tread width together)
  double tread_width_rel_std = 0;
};

struct TyreConfig {
  std::string source;  ///< config file path
  std::string name = "tyre";
  double outer_radius_m = 0.2948;
  double inflation_pressure_Pa = 230e3;
  /// From the tyre's size designation (e.g. 195/60R14), for the .tir bridge's [DIMENSION]
  /// (tir/); 0 = not stated.
  double section_width_m = 0;
  double aspect_ratio = 0;
  double rim_radius_m = 0;
  std::string hammer_csv;  ///< resolved path of the hammer data ("" with a frequency list)
  /// The rest of modal:: a frequency list, the normalisation, the modal test's pressure and
  /// boundary, the mass scale (carcass_source.h, docs/ring_model.md).
  CarcassSettings carcass;
  StatedUncertainty uncertainty;
  bool extend_orders = true;
  double compliance_scale = 1.0;
  /// Bending term s2 of the dispersion extension [rad^2/s^2]; negative = as fitted to the
  /// resolved orders. Stating it lets a config add belt bending stiffness the hammer test cannot
  /// resolve (it acts on unmeasured orders only).
  double extension_s2 = -1.0;
  /// modal.pneumatic_share: fraction beta of the inflation pressure carried over the contact
  /// area in parallel with the modal carcass (pneumatic_share.h, docs/footprint.md section 8);
  /// 0 = the modal carcass alone.
  double pneumatic_share = 0;
  TreadParams tread;
  Discretisation mesh;
  SolverSettings solver;
  std::vector<double> loads_N;
  double horizontal_force_N = 0;
  ValidationSettings validation;
  TransientSettings transient;
  EffectsConfig effects;  ///< section effects:, every effect off by default
  /// Section footprint_3d: when present the footprint is predicted on the 3D patch (width,
  /// contour and pressure map; patch3d.h); absent: the 2D patch of width tread.width_m.
  std::optional<Patch3dSettings> footprint_3d;
  /// tyre.rigid: the tyre is a rigid cylinder of the outer radius (terramechanics' reference
  /// wheel, ground/rigid_wheel.h) where a command offers it (traction).
  bool rigid = false;
  /// Section ground: (ground/ground_settings.h): the flat rigid road by default.
  ground::GroundSettings ground;

  /// The conditions a row takes when it does not state them: the config's load, horizontal
  /// force and inflation pressure, no hold, standing, loading branch, rigid road.
  OperatingConditions default_conditions(double load_N) const;
};

/// Reads every key of the tree into a TyreConfig; unknown keys, wrong types and out-of-range
/// values are InputErrors naming file, line and key. With `footprint_3d:` the effects that the
/// 3D patch cannot take (effect_refused_with_3d) and a horizontal force are refused too.
TyreConfig read_tyre_config(const ConfigTree& tree);

/// Why the config's ground cannot be run with the rest of the config (the 3D patch on a road
/// profile, the lateral belt or the soil_compliance or rolling_speed effect on a soil, a
/// horizontal force off the flat road), or "" when it can (docs/soil.md section 4).
std::string ground_refusal(const TyreConfig& config);

/// Convenience: load a YAML file with --set overrides and read it.
TyreConfig load_tyre_config(const std::string& path,
                            const std::vector<std::string>& overrides = {});

}  // namespace modaltyre::contact
