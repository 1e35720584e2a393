#pragma once
// Switchable model effects (section `effects:` of the tyre config); the operating conditions
// they act through are in operating_conditions.h.
//
// Every effect is off by default; `effects.NAME.enabled: true` switches it on. Parameters are
// stored in the units their keys name (kPa, mm, s, N, MPa). What each effect does to the static
// footprint is stated in docs/effects.md and at its use in contact/src/predictor.cc:
//   inflation_pressure  carcass compliance x ((1 + p_test) / (1 + p))^exponent, p in bar
//                       (seed 000 eq. 3, p_W in bar as chosen in docs/rheology.md)
//   tread_relaxation    tread compliance x (1 + creep_ratio (1 - exp(-hold / time_constant)))
//                       (seed 001 eq. 10: Kelvin-Voigt creep of the tread under a held load)
//   dry_friction        Saint-Venant element in parallel: the elastic tyre carries F - F_f on
//                       the loading branch and F + F_f on the unloading one (seed 000 eq. 13-16)
//   load_stiffening     carcass compliance x (F / F_ref)^-exponent (seed 000 eq. 3: h ~ P^3/4
//                       means a secant stiffness growing as P^1/4)
//   tread_coupling      Pasternak tread layer: shear ties neighbouring tread units together
//                       (coupling length l = sqrt(G h_shear / k)), instead of independent springs
//   soil_compliance     Kelvin-Voigt soil layer under rows with surface = soil (seed 000 eq. 23),
//                       static part: Winkler modulus E2 / layer depth
//   rolling_speed       steady-rolling receptance of every mode at the row's speed (seed 001
//                       eq. 2-5), modal damping x damping_scale: asymmetric pressure, rolling
//                       resistance
//   contact_width       patch width from the crown profile: w = min(max_width, 2 sqrt(2 R_c d)),
//                       d the sinking; the tread's stiffness per unit length follows the width
//                       (the 2D patch's approximation; the 3D patch computes the width itself)
//   belt_flattening     extra foundation stiffness kappa of the doubly curved belt against
//                       flattening, acting on harmonic orders >= 2 only:
//                       c_k -> c_k / (1 + pi R kappa c_k)
// With the 3D patch (footprint_3d:) tread_coupling, rolling_speed and contact_width are refused
// (EffectInfo::refused_with_3d says why); the others act on it as on the 2D patch.
//
// Option effects: physics built as an option of the config, outside section effects:, listed,
// switched and fitted through the same catalogue (EffectInfo::option; option_effects.cc):
//   lateral_belt        footprint_3d.lateral_belt: the belt strip bends across the tread (free
//                       strip on the hoop foundation, docs/footprint.md section 7)
//   pneumatic_share     modal.pneumatic_share: beta p A carried over the contact area
//                       (docs/footprint.md section 8)
//   crown_shape         footprint_3d.crown.shape power: z = (y_r^2 / 2R)(|y| / y_r)^n instead of
//                       the circular crown (crown_profile.h)
//   sidewall_softening  footprint_3d.sidewall: the inflated sidewalls' nonlinear loss of radial
//                       stiffness (sidewall_membrane.h, docs/footprint.md section 9)
// A soil law of ground: is registered the same way (its keys ground.*, regime surface or slip).
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "modaltyre/contact/operating_conditions.h"
#include "modaltyre/core/conditions.h"
#include "modaltyre/core/config_tree.h"

namespace modaltyre::contact {

struct TyreConfig;

enum class EffectId {
  inflation_pressure,
  tread_relaxation,
  dry_friction,
  load_stiffening,
  tread_coupling,
  soil_compliance,
  rolling_speed,
  contact_width,
  belt_flattening,
  // option effects (EffectInfo::option)
  lateral_belt,
  pneumatic_share,
  crown_shape,
  sidewall_softening,
};
inline constexpr int kEffectCount = 13;

/// The effects' parameters as the config states them (the unit is in each name): the catalogue
/// (effects.cc) declares every key with its unit and range, calibrations and discover search
/// and print them in these units, and a round trip through SI would move printed digits
/// (issue 17). The physics reads SI through the accessors, the one place each conversion is
/// written.
struct EffectsConfig {
  struct InflationPressure {
    bool enabled = false;
    double exponent = 1.0;                 ///< beta in ((1 + p_test) / (1 + p))^beta
    double modal_test_pressure_kPa = 230;  ///< pressure of the hammer test (not fitted)
    double modal_test_pressure_bar() const { return modal_test_pressure_kPa * 1e-2; }
  } inflation_pressure;
  struct TreadRelaxation {
    bool enabled = false;
    double creep_ratio = 0.5;     ///< long-term / instantaneous tread compliance - 1
    double time_constant_s = 30;  ///< tau = tan(delta) / Omega of seed 001 eq. (10)
  } tread_relaxation;
  struct DryFriction {
    bool enabled = false;
    double friction_force_N = 200;  ///< Saint-Venant limit force F_f
  } dry_friction;
  struct LoadStiffening {
    bool enabled = false;
    double exponent = 0.25;          ///< gamma; seed 000 eq. (3) implies 1/4
    double reference_load_N = 4000;  ///< load where the modal test's stiffness holds (not fitted)
  } load_stiffening;
  struct TreadCoupling {
    bool enabled = false;
    double coupling_length_mm = 10;  ///< Pasternak length sqrt(G_shear h / k)
    double coupling_length_m() const { return coupling_length_mm * 1e-3; }
  } tread_coupling;
  struct SoilCompliance {
    bool enabled = false;
    double modulus_MPa = 2;  ///< deformation modulus E2 of the soil (seed 000 eq. 23)
    double layer_mm = 200;   ///< depth of the deformable layer (not fitted: only E2/layer acts)
    double modulus_Pa() const { return modulus_MPa * 1e6; }
    double layer_m() const { return layer_mm * 1e-3; }
  } soil_compliance;
  struct RollingSpeed {
    bool enabled = false;
    double damping_scale = 1;  ///< multiplies the measured modal damping ratios when rolling
  } rolling_speed;
  struct ContactWidth {
    bool enabled = false;
    double crown_radius_mm = 150;  ///< transverse radius R_c of the loaded crown profile
    double max_width_mm = 160;     ///< tread width: the patch cannot grow wider (not fitted)
    double crown_radius_m() const { return crown_radius_mm * 1e-3; }
    double max_width_m() const { return max_width_mm * 1e-3; }
  } contact_width;
  struct BeltFlattening {
    bool enabled = false;
    double stiffness_MPa = 1;  ///< kappa, N/mm per mm of circumference, on orders >= 2
    double stiffness_Pa() const { return stiffness_MPa * 1e6; }
  } belt_flattening;

  /// The flag effects.NAME.enabled (std::logic_error for an option effect: effect_enabled()).
  bool enabled(EffectId id) const;
  bool& enabled(EffectId id);
  /// Any effect of section effects: on.
  bool any() const;
};

/// Where an effect parameter lives in an EffectsConfig, for reading (const) and writing.
struct EffectParameterRef {
  double& (*field)(EffectsConfig&) = nullptr;
  const double& (*const_field)(const EffectsConfig&) = nullptr;
  double& operator()(EffectsConfig& e) const { return field(e); }
  const double& operator()(const EffectsConfig& e) const { return const_field(e); }
};

/// The EffectParameterRef of member `Parameter` of effect member `Effect`, e.g.
/// parameter_ref<&EffectsConfig::dry_friction, &EffectsConfig::DryFriction::friction_force_N>().
template <auto Effect, auto Parameter>
EffectParameterRef parameter_ref() {
  return {[](EffectsConfig& e) -> double& { return (e.*Effect).*Parameter; },
          [](const EffectsConfig& e) -> const double& { return (e.*Effect).*Parameter; }};
}

/// A parameter of an option effect: its config key and value (in the key's unit) in a
/// TyreConfig that has the option (InputError naming the key otherwise, as parameter_spec.h).
struct OptionParameterRef {
  std::string key;  ///< e.g. "footprint_3d.lateral_belt.foundation_MPa_per_m"
  double (*get)(const TyreConfig&) = nullptr;
  void (*set)(TyreConfig&, double) = nullptr;
};

/// One parameter of an effect as listed by `modaltyre effects`. Its fit range for discover and
/// its transform are in the parameter specification (parameter_spec.h), built from this entry.
struct EffectParameterInfo {
  std::string name;  ///< e.g. "exponent"; the config key is effects.EFFECT.name
  std::string unit;  ///< "-" for dimensionless
  /// [min, max]: what the config reader accepts (an option effect's: what discover searches;
  /// its option's reader accepts a wider range)
  double default_value = 0, min = 0, max = 0;
  bool fitted = true;  ///< false: a stated reference value that `discover` does not fit
  std::string meaning;
  EffectParameterRef ref;          ///< an effects.NAME parameter (null for an option effect)
  OptionParameterRef option = {};  ///< an option effect's parameter (empty key otherwise)
};

/// How the strength of an effect (its first fitted parameter) switches it off, for the
/// detection limits (discover/detection_limit.h).
enum class EffectStrength {
  from_neutral,  ///< vanishes at EffectInfo::neutral, grows away from it towards the default
  inverse,       ///< vanishes as the parameter grows without bound (a modulus, a foundation)
  none,          ///< no value switches it off (EffectInfo::no_strength says why)
};

/// An option effect: a config option outside section effects: that the catalogue switches.
struct EffectOption {
  std::string keys;  ///< what switches it on, e.g. "footprint_3d.lateral_belt.enabled=true"
  bool (*is_on)(const TyreConfig&) = nullptr;
  /// Switches it on: the stated parameters are the config's where it states them (an option
  /// section with enabled: false), else the catalogue's defaults; fitted ones the defaults.
  void (*switch_on)(TyreConfig&) = nullptr;
  /// key=value overrides that make a config file carry the option as `config` has it.
  std::vector<std::string> (*overrides)(const TyreConfig& config) = nullptr;
  /// Why a config cannot take it ("" when it can), e.g. a 2D config for a 3D option.
  std::string (*refusal)(const TyreConfig&) = nullptr;
  bool needs_3d = false;  ///< an option of the 3D patch (footprint_3d:)
};

struct EffectInfo {
  EffectId id;
  std::string name;
  std::string description;
  std::vector<std::string> observables;  ///< what it changes
  ConditionId regime;                    ///< condition it acts through (core/conditions.h)
  std::vector<EffectParameterInfo> parameters;
  std::string acts_on = {};  ///< what it changes in the model: carcass, tread, applied load, road
  /// Empty when it composes with the 3D patch (footprint_3d); else why it is refused there.
  std::string refused_with_3d = {};
  EffectStrength strength = EffectStrength::from_neutral;
  double neutral = 0;                       ///< from_neutral: where the strength switches it off
  std::string no_strength = {};             ///< none: why no value switches it off
  std::optional<EffectOption> option = {};  ///< an option effect (not in section effects:)

  bool is_option() const { return option.has_value(); }
  std::string key(const EffectParameterInfo& p) const {
    return is_option() ? p.option.key : "effects." + name + "." + p.name;
  }
  /// What switches it on: effects.NAME.enabled=true, or the option's keys.
  std::string switch_keys() const {
    return is_option() ? option->keys : "effects." + name + ".enabled=true";
  }
};

/// Every effect, in EffectId order.
const std::vector<EffectInfo>& effect_catalogue();
const EffectInfo& effect_info(EffectId id);
/// nullptr if no effect has that name.
const EffectInfo* find_effect(const std::string& name);

/// Reads section `effects:` (unknown effect or parameter names, values outside the catalogue's
/// [min, max] -> InputError naming file, line and key).
EffectsConfig read_effects(const ConfigSection& effects);

/// The option effects' catalogue entries (option_effects.cc), in EffectId order.
std::vector<EffectInfo> option_effect_catalogue();

/// Whether an effect is on in a config (its effects.NAME flag or its option).
bool effect_enabled(const TyreConfig& config, EffectId id);
/// Switches it on (EffectOption::switch_on for an option effect).
void enable_effect(TyreConfig& config, EffectId id);
/// Why the config cannot take the effect ("" when it can): refused by the 3D patch, an option
/// the config's patch or crown does not have.
std::string effect_refusal(const TyreConfig& config, EffectId id);
/// key=value overrides that switch the effect on in a config file as `config` has it
/// (effects.NAME.enabled=true, or the option's keys with its stated values).
std::vector<std::string> effect_switch_overrides(const TyreConfig& config, EffectId id);
/// The same for the catalogue's stated values (on a 3D config without the option): what
/// `modaltyre effects --json` lists as the switch.
std::vector<std::string> effect_catalogue_switch(EffectId id);

}  // namespace modaltyre::contact
