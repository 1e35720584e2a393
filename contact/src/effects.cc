#include "modaltyre/contact/effects.h"

#include <stdexcept>

#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::contact {
namespace {

using E = EffectsConfig;

// What each effect acts on and whether the 3D patch (patch3d.h) takes it: an effect on the
// carcass (its kernels or their level), on the tread cells, on the applied load or under the
// cells composes with it exactly; one that needs what its section reduction excludes is refused.
void with_3d_patch(EffectInfo& e) {
  switch (e.id) {
    case EffectId::inflation_pressure:
    case EffectId::load_stiffening:
      e.acts_on = "carcass (compliance level)";
      return;
    case EffectId::belt_flattening:
      e.acts_on = "carcass (kernels of orders >= 2)";
      return;
    case EffectId::tread_relaxation:
      e.acts_on = "tread (each cell's spring)";
      return;
    case EffectId::dry_friction:
      e.acts_on = "applied load";
      return;
    case EffectId::soil_compliance:
      e.acts_on = "road (a Winkler layer under each cell)";
      e.strength = EffectStrength::inverse;  // vanishes as the soil's modulus grows
      return;
    case EffectId::tread_coupling:
      // On the 3D patch the layer couples the cells along and across the road: every cell an
      // unknown (patch3d_coupled.cc) instead of the section reduction.
      e.acts_on = "tread (couples units along the road; 3D cells along and across it)";
      return;
    case EffectId::rolling_speed:
      // On the 3D patch a non-symmetric section problem (Josephy-Newton steps, patch3d.h).
      e.acts_on = "carcass (steady-rolling kernels)";
      return;
    case EffectId::contact_width:
      e.acts_on = "patch width (2D approximation)";
      e.refused_with_3d =
          "superseded: the 3D patch computes the width from the crown profile "
          "(footprint_3d.crown, its radius a baseline scalar); contact_width is the 2D patch's "
          "approximation of it, crown_shape its 3D counterpart";
      e.strength = EffectStrength::none;
      e.no_strength = "its width replaces the config's";
      return;
    default:  // option effects: their entries say it (option_effects.cc)
      return;
  }
}

std::vector<EffectInfo> make_effect_catalogue() {
  std::vector<EffectInfo> c;
  c.push_back({EffectId::inflation_pressure,
               "inflation_pressure",
               "carcass compliance scales as ((1 + p_test) / (1 + p))^exponent with the row's "
               "inflation pressure p (bar), seed 000 eq. (3)",
               {"sinking_mm", "length_mm"},
               ConditionId::pressure_kPa,
               {{"exponent", "-", 1.0, 0.0, 4.0, true, "1 = seed 000 eq. (3)",
                 parameter_ref<&E::inflation_pressure, &E::InflationPressure::exponent>()},
                {"modal_test_pressure_kPa", "kPa", 230, 10, 2000, false,
                 "pressure at which the hammer test was made",
                 parameter_ref<&E::inflation_pressure,
                               &E::InflationPressure::modal_test_pressure_kPa>()}}});
  c.push_back(
      {EffectId::tread_relaxation,
       "tread_relaxation",
       "tread creep while the load is held: tread compliance x (1 + creep_ratio "
       "(1 - exp(-hold_s / time_constant_s))), seed 001 eq. (10)",
       {"sinking_mm", "length_mm"},
       ConditionId::hold_s,
       {{"creep_ratio", "-", 0.5, 0.0, 5.0, true, "long-term over instantaneous compliance - 1",
         parameter_ref<&E::tread_relaxation, &E::TreadRelaxation::creep_ratio>()},
        {"time_constant_s", "s", 30, 0.1, 1e4, true, "retardation time tan(delta)/Omega",
         parameter_ref<&E::tread_relaxation, &E::TreadRelaxation::time_constant_s>()}}});
  c.push_back({EffectId::dry_friction,
               "dry_friction",
               "Saint-Venant dry friction in parallel with the tyre: the elastic part carries "
               "F - F_f when loading and F + F_f when unloading, seed 000 three-element model",
               {"sinking_mm", "length_mm"},
               ConditionId::branch,
               {{"friction_force_N", "N", 200, 0, 5000, true, "internal friction force F_f",
                 parameter_ref<&E::dry_friction, &E::DryFriction::friction_force_N>()}}});
  c.push_back({EffectId::load_stiffening,
               "load_stiffening",
               "nonlinear sidewall: carcass compliance x (F / F_ref)^-exponent, seed 000 eq. (3) "
               "(h ~ P^3/4: exponent 1/4)",
               {"sinking_mm", "length_mm"},
               ConditionId::load_N,
               {{"exponent", "-", 0.25, -0.9, 0.9, true, "gamma; > 0 stiffens with load",
                 parameter_ref<&E::load_stiffening, &E::LoadStiffening::exponent>()},
                {"reference_load_N", "N", 4000, 1, 1e6, false,
                 "load at which the carcass has its modal-test compliance",
                 parameter_ref<&E::load_stiffening, &E::LoadStiffening::reference_load_N>()}}});
  c.push_back({EffectId::tread_coupling,
               "tread_coupling",
               "shear coupling of neighbouring tread units (Pasternak layer) instead of "
               "independent springs",
               {"length_mm", "sinking_mm"},
               ConditionId::load_N,
               {{"coupling_length_mm", "mm", 10, 0, 100, true, "Pasternak length sqrt(G h / k)",
                 parameter_ref<&E::tread_coupling, &E::TreadCoupling::coupling_length_mm>()}}});
  c.push_back({EffectId::soil_compliance,
               "soil_compliance",
               "Kelvin-Voigt soil under rows with surface = soil (static part: Winkler modulus "
               "E2 / layer), seed 000 eq. (23)-(28)",
               {"sinking_mm", "length_mm"},
               ConditionId::surface,
               {{"modulus_MPa", "MPa", 2, 0.01, 1000, true, "soil deformation modulus E2",
                 parameter_ref<&E::soil_compliance, &E::SoilCompliance::modulus_MPa>()},
                {"layer_mm", "mm", 200, 1, 5000, false, "depth of the deformable layer",
                 parameter_ref<&E::soil_compliance, &E::SoilCompliance::layer_mm>()}}});
  c.push_back({EffectId::rolling_speed,
               "rolling_speed",
               "steady-rolling modal receptance at the row's speed, seed 001 eq. (2)-(5): "
               "asymmetric pressure and rolling resistance from modal damping",
               {"rolling_resistance_N", "sinking_mm", "length_mm"},
               ConditionId::speed_kmh,
               {{"damping_scale", "-", 1, 0, 20, true, "multiplies the measured modal damping",
                 parameter_ref<&E::rolling_speed, &E::RollingSpeed::damping_scale>()}}});
  c.push_back({EffectId::contact_width,
               "contact_width",
               "2D approximation of the patch width from the crown profile, w = min(max_width, "
               "2 sqrt(2 R_c sinking)); the tread stiffness per unit length follows the width "
               "(superseded by the 3D patch, footprint_3d:, which computes the width)",
               {"width_mm", "length_mm", "sinking_mm"},
               ConditionId::load_N,
               {{"crown_radius_mm", "mm", 150, 10, 5000, true, "transverse crown radius R_c",
                 parameter_ref<&E::contact_width, &E::ContactWidth::crown_radius_mm>()},
                {"max_width_mm", "mm", 160, 1, 2000, false, "tread width",
                 parameter_ref<&E::contact_width, &E::ContactWidth::max_width_mm>()}}});
  c.push_back(
      {EffectId::belt_flattening,
       "belt_flattening",
       "stiffness of the doubly curved belt against flattening that in-plane modes do "
       "not carry: foundation kappa on harmonic orders >= 2, c_k / (1 + pi R kappa c_k)",
       {"length_mm", "sinking_mm"},
       ConditionId::load_N,
       {{"stiffness_MPa", "MPa", 1, 0.0, 1000, true, "kappa in N/mm per mm of circumference",
         parameter_ref<&E::belt_flattening, &E::BeltFlattening::stiffness_MPa>()}}});
  for (auto& e : c) with_3d_patch(e);
  for (auto& e : option_effect_catalogue()) c.push_back(std::move(e));
  return c;
}

}  // namespace

bool EffectsConfig::enabled(EffectId id) const {
  return const_cast<EffectsConfig*>(this)->enabled(id);
}

bool& EffectsConfig::enabled(EffectId id) {
  switch (id) {
    case EffectId::inflation_pressure:
      return inflation_pressure.enabled;
    case EffectId::tread_relaxation:
      return tread_relaxation.enabled;
    case EffectId::dry_friction:
      return dry_friction.enabled;
    case EffectId::load_stiffening:
      return load_stiffening.enabled;
    case EffectId::tread_coupling:
      return tread_coupling.enabled;
    case EffectId::soil_compliance:
      return soil_compliance.enabled;
    case EffectId::rolling_speed:
      return rolling_speed.enabled;
    case EffectId::contact_width:
      return contact_width.enabled;
    case EffectId::belt_flattening:
      return belt_flattening.enabled;
    default:
      break;
  }
  throw std::logic_error("effect " + effect_info(id).name +
                         " is an option of the config, not a flag of section effects:");
}

bool EffectsConfig::any() const {
  for (const auto& e : effect_catalogue()) {
    if (!e.is_option() && enabled(e.id)) return true;
  }
  return false;
}

const std::vector<EffectInfo>& effect_catalogue() {
  static const std::vector<EffectInfo> c = make_effect_catalogue();
  return c;
}

const EffectInfo& effect_info(EffectId id) { return effect_catalogue().at(static_cast<int>(id)); }

const EffectInfo* find_effect(const std::string& name) {
  for (const auto& e : effect_catalogue()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

EffectsConfig read_effects(const ConfigSection& section) {
  EffectsConfig out;
  for (const auto& info : effect_catalogue()) {
    if (info.is_option()) continue;  // read where its option lives
    const ConfigSection s = section.section(info.name);
    out.enabled(info.id) = s.boolean("enabled", false);
    for (const auto& p : info.parameters) {
      double& v = p.ref(out);
      v = s.number(p.name, p.default_value, p.min, p.max);
    }
  }
  return out;
}

bool effect_enabled(const TyreConfig& config, EffectId id) {
  const EffectInfo& e = effect_info(id);
  return e.is_option() ? e.option->is_on(config) : config.effects.enabled(id);
}

void enable_effect(TyreConfig& config, EffectId id) {
  const EffectInfo& e = effect_info(id);
  if (e.is_option()) {
    e.option->switch_on(config);
  } else {
    config.effects.enabled(id) = true;
  }
}

std::string effect_refusal(const TyreConfig& config, EffectId id) {
  const EffectInfo& e = effect_info(id);
  if (config.footprint_3d && !e.refused_with_3d.empty()) {
    return "not on the 3D patch: " + e.refused_with_3d;
  }
  return e.is_option() ? e.option->refusal(config) : "";
}

std::vector<std::string> effect_switch_overrides(const TyreConfig& config, EffectId id) {
  const EffectInfo& e = effect_info(id);
  if (e.is_option()) return e.option->overrides(config);
  return {e.switch_keys()};
}

std::vector<std::string> effect_catalogue_switch(EffectId id) {
  TyreConfig c;
  c.footprint_3d.emplace();  // the options of the 3D patch have their settings there
  enable_effect(c, id);
  return effect_switch_overrides(c, id);
}

}  // namespace modaltyre::contact
