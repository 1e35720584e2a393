// The option effects of the catalogue (effects.h): physics built and measured as options of the
// tyre config (docs/validation.md, "built, measured, not adopted"), listed, switched and fitted by
// `effects` and `discover` like the effects of section effects:. Each entry names the option's
// keys; switching it on sets them, with the stated values the config gives (an option section
// with enabled: false) or the catalogue's. Sources of the values: docs/effects.md.

#include "modaltyre/contact/effects.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::contact {
namespace {

// Catalogue values (docs/effects.md, "Option effects", and docs/validation.md for the sources).
constexpr double kBeltBending_Nm = 0.27;          // D_y: hammer EI / belt width x tan^4(theta)
constexpr double kBeltFoundation_MPa_per_m = 56;  // 12 N_x / L^2, N_x = p R0, L = 120 mm
constexpr double kPneumaticShare = 0.25;
constexpr double kCrownExponent = 3;       // a flat-centred crown (published contours: n >= 2)
constexpr double kCrownReference_mm = 60;  // y_r inside Table 3's 52-75 mm half-widths
constexpr double kSidewallChord_mm = 117;  // 0.60 x 195 mm: the SF-350's section height
constexpr double kSidewallRatio = 0.80;    // c0 / L: the modes' foundation holds 2F'(c0)

const std::string kNeeds3d =
    "needs the 3D patch (footprint_3d:): the 2D patch has no cells across the tread";

template <class Config>
auto& option_patch(Config& c, const char* key) {
  if (!c.footprint_3d) {
    throw InputError({c.source, 0, key}, std::string(key) + " needs a footprint_3d: section");
  }
  return *c.footprint_3d;
}

// ---- lateral_belt: footprint_3d.lateral_belt (docs/footprint.md section 7) -------------------

constexpr const char* kFoundationKey = "footprint_3d.lateral_belt.foundation_MPa_per_m";
constexpr const char* kBendingKey = "footprint_3d.lateral_belt.bending_stiffness_Nm";

EffectInfo lateral_belt() {
  EffectOption o;
  o.keys = "footprint_3d.lateral_belt.enabled=true (supports: free)";
  o.needs_3d = true;
  o.is_on = [](const TyreConfig& c) {
    return c.footprint_3d && c.footprint_3d->lateral_belt.enabled;
  };
  o.switch_on = [](TyreConfig& c) {
    LateralBelt& b = option_patch(c, kFoundationKey).lateral_belt;
    if (!b.given) {  // the free strip on the hoop foundation, every value the catalogue's
      b = LateralBelt{};
      b.supports = BeltSupports::free;
      b.bending_stiffness_Nm = kBeltBending_Nm;
      b.foundation_Pa_m = kBeltFoundation_MPa_per_m * 1e6;
      b.given = true;
    }
    b.enabled = true;
  };
  o.overrides = [](const TyreConfig& c) {
    const LateralBelt& b = option_patch(c, kFoundationKey).lateral_belt;
    const std::string k = "footprint_3d.lateral_belt.";
    std::vector<std::string> out = {
        k + "enabled=true",
        k + "supports=" + (b.supports == BeltSupports::free ? "free" : "shoulders"),
        k + "bending_stiffness_Nm=" + number_text(b.bending_stiffness_Nm)};
    if (b.tension_N_m > 0) out.push_back(k + "tension_N_per_m=" + number_text(b.tension_N_m));
    if (b.support_span_m > 0)
      out.push_back(k + "support_span_mm=" + number_text(b.support_span_m * 1e3));
    return out;
  };
  o.refusal = [](const TyreConfig& c) -> std::string {
    if (!c.footprint_3d) return kNeeds3d;
    if (c.ground.soil()) return "a soil under a lateral belt is not built (patch3d.h)";
    return "";
  };
  EffectInfo e{EffectId::lateral_belt,
               "lateral_belt",
               "the belt strip of each section bends across the tread (free strip on the hoop "
               "foundation k, bending stiffness D_y): the patch widens with load faster than the "
               "crown alone lets it",
               {"width_mm", "sinking_mm", "length_mm"},
               ConditionId::load_N,
               {{"foundation_MPa_per_m",
                 "MPa/m",
                 kBeltFoundation_MPa_per_m,
                 10,
                 1e4,
                 true,
                 "hoop foundation k = 12 N_x / L^2 (34-113 MPa/m on the SF-350)",
                 {},
                 {kFoundationKey,
                  [](const TyreConfig& c) {
                    return option_patch(c, kFoundationKey).lateral_belt.foundation_Pa_m * 1e-6;
                  },
                  [](TyreConfig& c, double v) {
                    option_patch(c, kFoundationKey).lateral_belt.foundation_Pa_m = v * 1e6;
                  }}},
                {"bending_stiffness_Nm",
                 "N m",
                 kBeltBending_Nm,
                 0.18,
                 1e4,
                 false,
                 "lateral bending stiffness D_y of the belt per unit length",
                 {},
                 {kBendingKey,
                  [](const TyreConfig& c) {
                    return option_patch(c, kBendingKey).lateral_belt.bending_stiffness_Nm;
                  },
                  [](TyreConfig& c, double v) {
                    option_patch(c, kBendingKey).lateral_belt.bending_stiffness_Nm = v;
                  }}}},
               "carcass (each section's belt strip across the tread)"};
  e.strength = EffectStrength::inverse;  // a stiff foundation keeps the strip straight
  e.option = o;
  return e;
}

// ---- pneumatic_share: modal.pneumatic_share (docs/footprint.md section 8) --------------------

EffectInfo pneumatic_share() {
  EffectOption o;
  o.keys = "modal.pneumatic_share > 0";
  o.is_on = [](const TyreConfig& c) { return c.pneumatic_share > 0; };
  o.switch_on = [](TyreConfig& c) {
    if (!(c.pneumatic_share > 0)) c.pneumatic_share = kPneumaticShare;
  };
  o.overrides = [](const TyreConfig&) { return std::vector<std::string>{}; };  // its value
  o.refusal = [](const TyreConfig&) { return std::string(); };
  EffectInfo e{EffectId::pneumatic_share,
               "pneumatic_share",
               "the inflation pressure carries beta p A over the contact area in parallel with "
               "the modal carcass: F_z = F_s + beta p A(F_s) (Clark 1971 eq. 5.9; Rhyne 2005)",
               {"sinking_mm", "length_mm", "width_mm"},
               ConditionId::load_N,
               {{"share",
                 "-",
                 kPneumaticShare,
                 0,
                 1,
                 true,
                 "beta; 0 on the extended carcass, 1 on the measured orders alone",
                 {},
                 {"modal.pneumatic_share", [](const TyreConfig& c) { return c.pneumatic_share; },
                  [](TyreConfig& c, double v) { c.pneumatic_share = v; }}}},
               "load (a pressure membrane in parallel with the carcass and tread)"};
  e.option = o;
  return e;
}

// ---- crown_shape: footprint_3d.crown.shape power (crown_profile.h) ----------------------------

constexpr const char* kExponentKey = "footprint_3d.crown.exponent";
constexpr const char* kReferenceKey = "footprint_3d.crown.reference_half_width_mm";

template <class Config>
auto& option_power_crown(Config& c, const char* key) {
  auto& crown = option_patch(c, key).crown;
  if (crown.shape != CrownShape::power) {
    throw InputError({c.source, 0, key}, std::string(key) + " needs a power crown (shape: power)");
  }
  return crown;
}

EffectInfo crown_shape() {
  EffectOption o;
  o.keys = "footprint_3d.crown.shape=power";
  o.needs_3d = true;
  o.is_on = [](const TyreConfig& c) {
    return c.footprint_3d && c.footprint_3d->crown.shape == CrownShape::power;
  };
  o.switch_on = [](TyreConfig& c) {
    CrownProfile& crown = option_patch(c, kExponentKey).crown;
    if (crown.shape == CrownShape::power) return;
    crown.shape = CrownShape::power;  // the circular crown's radius R stays the baseline's
    crown.exponent = kCrownExponent;
    crown.reference_half_width_m = kCrownReference_mm * 1e-3;
  };
  o.overrides = [](const TyreConfig& c) {
    return std::vector<std::string>{
        "footprint_3d.crown.shape=power",
        std::string(kReferenceKey) + "=" +
            number_text(option_power_crown(c, kReferenceKey).reference_half_width_m * 1e3)};
  };
  o.refusal = [](const TyreConfig& c) -> std::string {
    if (!c.footprint_3d) return kNeeds3d;
    const CrownProfile& crown = c.footprint_3d->crown;
    if (crown.shape != CrownShape::circular) {
      return "the crown is stated (flat or a measured contour), not a circular one to reshape";
    }
    if (crown.shoulder_radius_m > 0) return "the crown has a shoulder arc: its shape is stated";
    return "";
  };
  EffectInfo e{
      EffectId::crown_shape,
      "crown_shape",
      "the crown drops as a power of |y|, z = (y_r^2 / 2R)(|y| / y_r)^n, instead of a "
      "circle: the width grows as sinking^(1/n) (n = 2: the circular crown's parabola)",
      {"width_mm", "sinking_mm", "length_mm"},
      ConditionId::load_N,
      {{"exponent",
        "-",
        kCrownExponent,
        1.05,
        8,
        true,
        "n; > 2 flat centre, steep shoulder; < 2 the reverse",
        {},
        {kExponentKey,
         [](const TyreConfig& c) { return option_power_crown(c, kExponentKey).exponent; },
         [](TyreConfig& c, double v) { option_power_crown(c, kExponentKey).exponent = v; }}},
       {"reference_half_width_mm",
        "mm",
        kCrownReference_mm,
        1,
        1e4,
        false,
        "y_r, where every n has the drop of the parabola of radius R",
        {},
        {kReferenceKey,
         [](const TyreConfig& c) {
           return option_power_crown(c, kReferenceKey).reference_half_width_m * 1e3;
         },
         [](TyreConfig& c, double v) {
           option_power_crown(c, kReferenceKey).reference_half_width_m = v * 1e-3;
         }}}},
      "road geometry (the crown drop of each column)"};
  e.neutral = 2;  // the parabola, within y^4 / 8R^3 of the circular crown
  e.option = o;
  return e;
}

// ---- sidewall_softening: footprint_3d.sidewall (sidewall_membrane.h) --------------------------

constexpr const char* kRatioKey = "footprint_3d.sidewall.chord_over_length";
constexpr const char* kChordKey = "footprint_3d.sidewall.meridian_chord_mm";

EffectInfo sidewall_softening() {
  EffectOption o;
  o.keys = "footprint_3d.sidewall.enabled=true";
  o.needs_3d = true;
  o.is_on = [](const TyreConfig& c) { return c.footprint_3d && c.footprint_3d->sidewall.enabled; };
  o.switch_on = [](TyreConfig& c) {
    SidewallMembrane& w = option_patch(c, kRatioKey).sidewall;
    if (!w.given) {
      w.chord_m = kSidewallChord_mm * 1e-3;
      w.length_m = w.chord_m / kSidewallRatio;
      w.given = true;
    }
    w.enabled = true;
  };
  o.overrides = [](const TyreConfig& c) {
    return std::vector<std::string>{
        "footprint_3d.sidewall.enabled=true",
        std::string(kChordKey) + "=" +
            number_text(option_patch(c, kChordKey).sidewall.chord_m * 1e3)};
  };
  o.refusal = [](const TyreConfig& c) { return c.footprint_3d ? std::string() : kNeeds3d; };
  EffectInfo e{
      EffectId::sidewall_softening,
      "sidewall_softening",
      "the inflated sidewalls' radial stiffness softens as the belt is pressed in "
      "(meridian arc of fixed length L, chord c0): the loss e(u) the linear modes do not "
      "carry acts on the belt as a load",
      {"sinking_mm", "length_mm", "width_mm"},
      ConditionId::load_N,
      // Searched from 0.3 (the loss 4 % of 0.8's): towards 0 the meridian is metres long
      // and its pull the difference of two large numbers.
      {{"chord_over_length",
        "-",
        kSidewallRatio,
        0.3,
        0.88,
        true,
        "c0 / L; 0.80-0.85 assumed for a passenger tyre, 0.9 exceeds the modes",
        {},
        {kRatioKey,
         [](const TyreConfig& c) {
           const SidewallMembrane& w = option_patch(c, kRatioKey).sidewall;
           return w.chord_m / w.length_m;
         },
         [](TyreConfig& c, double v) {
           SidewallMembrane& w = option_patch(c, kRatioKey).sidewall;
           w.length_m = w.chord_m / v;
         }}},
       {"meridian_chord_mm",
        "mm",
        kSidewallChord_mm,
        1,
        1e4,
        false,
        "c0, rim to belt edge radially: the section height",
        {},
        {kChordKey,
         [](const TyreConfig& c) { return option_patch(c, kChordKey).sidewall.chord_m * 1e3; },
         [](TyreConfig& c, double v) { option_patch(c, kChordKey).sidewall.chord_m = v * 1e-3; }}}},
      "carcass (a lost sidewall load on every section)"};
  e.option = o;  // strength from c0 / L = 0: an infinitely slack meridian loses nothing
  return e;
}

}  // namespace

std::vector<EffectInfo> option_effect_catalogue() {
  return {lateral_belt(), pneumatic_share(), crown_shape(), sidewall_softening()};
}

}  // namespace modaltyre::contact
