// The soil effects of the catalogue (effects.h): laws of the ground: section built as switches of
// the terramechanics work (ground/soil_options.h, docs/soil.md sections 1.1, 3.1, 5.3, 5.4),
// listed, switched and fitted like the option effects (option_effects.cc). Each switches exactly
// the ground keys the soil's file states; it acts on steady rolling (`traction`) and is refused
// where the config's ground has no soil of its model. Sources of the values: docs/effects.md.

#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::contact {
namespace {

using ground::GroundModel;

// Catalogue values (docs/effects.md, "Soil effects").
constexpr double kLyaskoK1 = 1.0;  // Lyasko 2010, soil-independent (docs/soil.md 5.3)
constexpr double kLyaskoK2 = 0.5;
constexpr double kWongReeceC1 = 0.43;  // Wong & Reece 1967: compact sand (loose: 0.18)
constexpr double kWongReeceC2 = 0.32;
constexpr double kUnitWeight_kN_m3 = 15.7;  // a dry sand's 1.6 t/m^3 (Wong's Table 2.3: none)
constexpr double kUnloadingAu_kN_m4 = 5e5;  // Wong section 2.4.2's order for sand, k0 = 0
constexpr double kEta2_kPa_s = 50;          // identify soil-rolling's planted value (tau 25 ms)

const char* model_word(GroundModel m) { return ground::to_string(m); }

// Why a config's ground cannot take a law of a Bekker soil ("" when it can).
std::string needs_bekker(const TyreConfig& c, const std::string& what) {
  if (c.ground.model == GroundModel::bekker) return "";
  return what + " is a law of a Bekker soil (ground.model: bekker); the config's ground is " +
         (c.ground.soil() ? std::string("the ") + model_word(c.ground.model) + " soil"
                          : std::string("a rigid road (") + model_word(c.ground.model) + ")") +
         " (traction --ground SOIL.yaml, configs/soils/)";
}

OptionParameterRef ground_key(const char* key, double (*get)(const TyreConfig&),
                              void (*set)(TyreConfig&, double)) {
  return {key, get, set};
}

// ---- slip_sinkage: ground.bekker.slip_sinkage (Lyasko 2010; docs/soil.md 5.3) ----------------

EffectInfo slip_sinkage() {
  EffectOption o;
  o.keys = "ground.bekker.slip_sinkage.enabled=true";
  o.is_on = [](const TyreConfig& c) {
    return c.ground.model == GroundModel::bekker && c.ground.slip_sinkage.enabled;
  };
  // Stated values (the soil file's k1, k2 with enabled: false) stay; the reader's defaults are
  // Lyasko's, which the catalogue's are.
  o.switch_on = [](TyreConfig& c) { c.ground.slip_sinkage.enabled = true; };
  o.overrides = [](const TyreConfig&) {
    return std::vector<std::string>{"ground.bekker.slip_sinkage.enabled=true"};
  };
  o.refusal = [](const TyreConfig& c) { return needs_bekker(c, "slip sinkage"); };
  EffectInfo e{
      EffectId::slip_sinkage,
      "slip_sinkage",
      "the soil sinks more as slip rises (the shear excavates under the contact): at a pressure "
      "the soil sinks f(s) = (1 + k1 |s|) / (1 - k2 |s|) times its law's sinkage (Lyasko, J. "
      "Terramechanics 47, 2010); f(0) = 1: free rolling unchanged",
      {"soil_sinkage_mm", "drawbar_pull_N", "torque_Nm"},
      ConditionId::slip,
      // Searched where measured slip sinkage lies: 30-100 % between free rolling and 50 % slip
      // in soil-bin tests of tyres (docs/soil.md 5.3) is f(0.5) in [1.3, 2]; the box reaches
      // f(0.5) = 3/0.55 = 5.5.
      {{"k1",
        "-",
        kLyaskoK1,
        0,
        4,
        true,
        "numerator coefficient (Lyasko: 1, soil-independent)",
        {},
        ground_key(
            "ground.bekker.slip_sinkage.k1",
            [](const TyreConfig& c) { return c.ground.slip_sinkage.k1; },
            [](TyreConfig& c, double v) { c.ground.slip_sinkage.k1 = v; })},
       {"k2",
        "-",
        kLyaskoK2,
        0,
        0.9,
        true,
        "denominator coefficient (Lyasko: 0.5)",
        {},
        ground_key(
            "ground.bekker.slip_sinkage.k2",
            [](const TyreConfig& c) { return c.ground.slip_sinkage.k2; },
            [](TyreConfig& c, double v) { c.ground.slip_sinkage.k2 = v; })}},
      "soil (its pressure-sinkage law stretched at the slip rolled)"};
  e.strength = EffectStrength::none;
  e.no_strength = "f = 1 needs k1 = k2 = 0 together: either at 0 leaves the other's growth";
  e.option = o;
  return e;
}

// ---- wong_reece_stress: ground.bekker.wong_reece (Wong & Reece 1967; docs/soil.md 3.1, 10) ---

EffectInfo wong_reece_stress() {
  EffectOption o;
  o.keys = "ground.bekker.wong_reece.enabled=true";
  o.is_on = [](const TyreConfig& c) {
    return c.ground.model == GroundModel::bekker && c.ground.wong_reece.enabled;
  };
  o.switch_on = [](TyreConfig& c) { c.ground.wong_reece.enabled = true; };
  o.overrides = [](const TyreConfig& c) {
    return std::vector<std::string>{
        "ground.bekker.wong_reece.enabled=true",
        "ground.bekker.wong_reece.c3=" + number_text(c.ground.wong_reece.c3)};
  };
  // The rigid wheel's distribution (docs/soil.md 3.1); the flexible tyre's rear soil flows at it
  // (section 10). c1 is searched from 0.1: from 0, discover named it on noise-only traction
  // curves at c1 0.037 (a rear region of one unit moving the fixed point's stopping point).
  o.refusal = [](const TyreConfig& c) { return needs_bekker(c, "the Wong-Reece stress"); };
  EffectInfo e{EffectId::wong_reece_stress,
               "wong_reece_stress",
               "the normal stress peaks behind the entry, at theta_m = (c1 + c2 s) theta1, moving "
               "back with slip (Wong & Reece, J. Terramechanics 4, 1967): the rear region carries "
               "the front's stress mapped onto [theta2, theta_m] (the rigid wheel's stress; on the "
               "flexible tyre the soil there flows at it): deeper sinkage, less pull",
               {"soil_sinkage_mm", "drawbar_pull_N", "torque_Nm"},
               ConditionId::slip,
               {{"c1",
                 "-",
                 kWongReeceC1,
                 0.1,
                 1,
                 true,
                 "theta_m / theta1 at zero slip (compact sand 0.43, loose sand 0.18)",
                 {},
                 ground_key(
                     "ground.bekker.wong_reece.c1",
                     [](const TyreConfig& c) { return c.ground.wong_reece.c1; },
                     [](TyreConfig& c, double v) { c.ground.wong_reece.c1 = v; })},
                {"c2",
                 "-",
                 kWongReeceC2,
                 0,
                 1,
                 true,
                 "growth of theta_m / theta1 with slip (Wong & Reece: 0.32)",
                 {},
                 ground_key(
                     "ground.bekker.wong_reece.c2",
                     [](const TyreConfig& c) { return c.ground.wong_reece.c2; },
                     [](TyreConfig& c, double v) { c.ground.wong_reece.c2 = v; })},
                {"c3",
                 "-",
                 0,
                 0,
                 0.99,
                 false,
                 "rear angle over entry angle (0: no rebound, the rigid-plastic soil's)",
                 {},
                 ground_key(
                     "ground.bekker.wong_reece.c3",
                     [](const TyreConfig& c) { return c.ground.wong_reece.c3; },
                     [](TyreConfig& c, double v) { c.ground.wong_reece.c3 = v; })}},
               "soil (the normal stress's distribution along the contact)"};
  e.strength = EffectStrength::none;
  e.no_strength = "the front-only stress needs c1 = c2 = 0 together";
  e.option = o;
  return e;
}

// ---- bulldozing: ground.bekker.bulldozing (Bekker 1969; docs/soil.md 5.4) ---------------------

EffectInfo bulldozing() {
  EffectOption o;
  o.keys = "ground.bekker.bulldozing.enabled=true";
  o.is_on = [](const TyreConfig& c) {
    return c.ground.model == GroundModel::bekker && c.ground.bulldozing.enabled;
  };
  o.switch_on = [](TyreConfig& c) { c.ground.bulldozing.enabled = true; };
  o.overrides = [](const TyreConfig&) {
    return std::vector<std::string>{"ground.bekker.bulldozing.enabled=true"};
  };
  o.refusal = [](const TyreConfig& c) { return needs_bekker(c, "bulldozing"); };
  // The unit weight is fitted: Wong's Table 2.3 states none for its soils, and it carries the
  // law's own looseness (Bekker's simplified form; Vesic's against Terzaghi's factors differ by
  // 10-25 %). Searched over dry to saturated soils' unit weights.
  EffectInfo e{EffectId::bulldozing,
               "bulldozing",
               "the soil pushed ahead of the sinking contact resists: R_b = b (0.67 c z K_pc + "
               "0.5 gamma z^2 K_pg) added to the motion resistance (Bekker 1969; Vesic's bearing "
               "factors)",
               {"drawbar_pull_N"},
               ConditionId::load_N,
               {{"unit_weight_kN_m3",
                 "kN/m^3",
                 kUnitWeight_kN_m3,
                 12,
                 22,
                 true,
                 "soil unit weight gamma (dry sand ~15.7, saturated soils to ~22)",
                 {},
                 ground_key(
                     "ground.bekker.bulldozing.unit_weight_kN_m3",
                     [](const TyreConfig& c) { return c.ground.bulldozing.unit_weight_kN_m3; },
                     [](TyreConfig& c, double v) { c.ground.bulldozing.unit_weight_kN_m3 = v; })}},
               "motion resistance (the soil ahead of the contact)"};
  e.strength = EffectStrength::none;
  e.no_strength = "gamma = 0 leaves the cohesion's term 0.67 c z K_pc (c > 0 on most soils)";
  e.option = o;
  return e;
}

// ---- soil_unloading: ground.bekker.unloading (Wong section 2.4.2; docs/soil.md 1.1) ----------

const ground::WongUnloading& unloading_values(const TyreConfig& c) {
  static const ground::WongUnloading kCatalogue{0, kUnloadingAu_kN_m4};
  return c.ground.bekker.unloading   ? *c.ground.bekker.unloading
         : c.ground.stated_unloading ? *c.ground.stated_unloading
                                     : kCatalogue;
}

// Where a value is written: the law when on, else the stated block (created with the
// catalogue's values), which switching on takes.
ground::WongUnloading& unloading_to_set(TyreConfig& c) {
  auto& u = c.ground.bekker.unloading ? c.ground.bekker.unloading : c.ground.stated_unloading;
  if (!u) u = unloading_values(c);
  return *u;
}

EffectInfo soil_unloading() {
  EffectOption o;
  o.keys = "ground.bekker.unloading.enabled=true (k0, Au)";
  o.is_on = [](const TyreConfig& c) {
    return c.ground.model == GroundModel::bekker && c.ground.bekker.unloading.has_value();
  };
  o.switch_on = [](TyreConfig& c) {
    if (!c.ground.bekker.unloading) c.ground.bekker.unloading = unloading_values(c);
  };
  o.overrides = [](const TyreConfig& c) {
    const ground::WongUnloading& u = unloading_values(c);
    return std::vector<std::string>{"ground.bekker.unloading.enabled=true",
                                    "ground.bekker.unloading.k0=" + number_text(u.k0_kN_m3),
                                    "ground.bekker.unloading.Au=" + number_text(u.Au_kN_m4)};
  };
  o.refusal = [](const TyreConfig& c) { return needs_bekker(c, "Wong's elastic unloading"); };
  EffectInfo e{
      EffectId::soil_unloading,
      "soil_unloading",
      "the soil rebounds elastically behind the deepest point, p = p_max - k_u (z_max - z), "
      "k_u = k0 + Au z_max (Wong, Theory of Ground Vehicles, section 2.4.2), instead of the "
      "rigid-plastic soil: the rear carries load, the rut is shallower",
      {"soil_sinkage_mm", "drawbar_pull_N", "torque_Nm"},
      ConditionId::load_N,
      {{"Au",
        "kN/m^4",
        kUnloadingAu_kN_m4,
        1e4,
        1e8,
        true,
        "growth of the unloading stiffness with z_max",
        {},
        ground_key(
            "ground.bekker.unloading.Au",
            [](const TyreConfig& c) { return unloading_values(c).Au_kN_m4; },
            [](TyreConfig& c, double v) { unloading_to_set(c).Au_kN_m4 = v; })},
       {"k0",
        "kN/m^3",
        0,
        0,
        1e6,
        false,
        "unloading stiffness at z_max = 0 (0 for sand, Wong section 2.4.2)",
        {},
        ground_key(
            "ground.bekker.unloading.k0",
            [](const TyreConfig& c) { return unloading_values(c).k0_kN_m3; },
            [](TyreConfig& c, double v) { unloading_to_set(c).k0_kN_m3 = v; })}},
      "soil (its unloading and reloading branches)"};
  e.strength = EffectStrength::inverse;  // k_u -> infinity: no rebound, the rigid-plastic soil
  e.option = o;
  return e;
}

// ---- soil_viscosity: ground.kelvin_voigt.eta2_kPa_s (seed 000 eq. 23; docs/soil.md 3.2) ------

constexpr const char* kEta2Key = "ground.kelvin_voigt.eta2_kPa_s";

EffectInfo soil_viscosity() {
  EffectOption o;
  o.keys =
      "ground.kelvin_voigt.eta2_kPa_s > 0 (rolled at the speed: --speed-km-h or "
      "transient.rolling.speed_km_h)";
  o.is_on = [](const TyreConfig& c) {
    return c.ground.model == GroundModel::kelvin_voigt && c.ground.kelvin_voigt.eta2_kPa_s > 0;
  };
  o.switch_on = [](TyreConfig& c) {
    if (!(c.ground.kelvin_voigt.eta2_kPa_s > 0)) c.ground.kelvin_voigt.eta2_kPa_s = kEta2_kPa_s;
  };
  o.overrides = [](const TyreConfig&) { return std::vector<std::string>{}; };  // its value
  o.refusal = [](const TyreConfig& c) -> std::string {
    if (c.ground.model != GroundModel::kelvin_voigt)
      return "the rate term of the Kelvin-Voigt soil (ground.model: kelvin_voigt); the config's "
             "ground is " +
             std::string(c.ground.soil() ? "the " : "a rigid road, ") + model_word(c.ground.model) +
             (c.ground.soil() ? " soil" : "");
    return "";
  };
  EffectInfo e{
      EffectId::soil_viscosity,
      "soil_viscosity",
      "the Kelvin-Voigt soil's rate term: sigma = k_E (E2 z + eta2 dz/dt) / H with dz/dt "
      "= -V dz/dx under the rolling tyre or wheel (seed 000 eq. 23; V tan(theta) under the "
      "rigid wheel): the soil stiffens and resists more with speed",
      {"soil_sinkage_mm", "drawbar_pull_N", "torque_Nm"},
      ConditionId::speed_kmh,
      // Searched over tau = eta2 / E2 from 0.5 ms to 1 s at E2 = 2 MPa.
      {{"eta2_kPa_s",
        "kPa s",
        kEta2_kPa_s,
        1,
        2000,
        true,
        "viscosity factor eta2 (no published soil value at hand: identify soil-rolling "
        "measures it)",
        {},
        ground_key(
            kEta2Key, [](const TyreConfig& c) { return c.ground.kelvin_voigt.eta2_kPa_s; },
            [](TyreConfig& c, double v) { c.ground.kelvin_voigt.eta2_kPa_s = v; })}},
      "soil (the rate term of its loading and unloading)"};
  e.option = o;  // strength from eta2 = 0: the elastic law
  return e;
}

}  // namespace

std::vector<EffectInfo> soil_effect_catalogue() {
  return {slip_sinkage(), wong_reece_stress(), bulldozing(), soil_unloading(), soil_viscosity()};
}

}  // namespace modaltyre::contact
