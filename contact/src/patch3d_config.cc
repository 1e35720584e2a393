#include <cmath>
#include <stdexcept>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/contact/patch3d.h"

namespace modaltyre::contact {

namespace {

/// The `lateral_belt:` section (its presence enables the lateral belt unless enabled: false,
/// which states its values for the lateral_belt effect, effects.h).
LateralBelt read_lateral_belt(const ConfigSection& s, const Patch3dSettings& p) {
  LateralBelt b;
  b.enabled = s.boolean("enabled", true);
  b.given = true;
  // The cord laminate's lateral D_y = D_x tan^4(theta) >= 10 N m x 0.018 for belt angles >= 20
  // degrees (docs/validation.md, "Lateral belt bending"); softer, the belt is a membrane that
  // lets the patch run out of the candidate window (0.1 N m: exit 1).
  b.bending_stiffness_Nm = s.number("bending_stiffness_Nm", b.bending_stiffness_Nm, 0.18, 1e12);
  b.tension_N_m = s.number("tension_N_per_m", 0, 0, 1e9);
  b.foundation_Pa_m = s.number("foundation_MPa_per_m", 0, 0, 1e9) * 1e6;
  const std::string sup = s.choice("supports", "shoulders", {"shoulders", "free"});
  b.supports = sup == "free" ? BeltSupports::free : BeltSupports::shoulders;
  b.support_span_m = s.number("support_span_mm", 0, 0, 1e4) * 1e-3;
  const double columns = std::round(p.tread_width_m / p.lateral_cell_m);
  if (columns > Patch3d::kMaxLateralBeltColumns) {
    s.fail("bending_stiffness_Nm", "a lateral belt supports at most " +
                                       std::to_string(Patch3d::kMaxLateralBeltColumns) +
                                       " columns (footprint_3d.lateral_cell_mm)");
  }
  try {
    b.validate(p.tread_width_m);
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    const char* key = msg.find("span") != std::string::npos         ? "support_span_mm"
                      : msg.find("foundation") != std::string::npos ? "foundation_MPa_per_m"
                                                                    : "tension_N_per_m";
    s.fail(key, msg);
  }
  return b;
}

/// The `sidewall:` section (its presence enables the sidewalls' pneumatic softening,
/// sidewall_membrane.h, unless enabled: false, which states the chord for the
/// sidewall_softening effect, effects.h). The meridian's length is given as
/// meridian_length_mm or as chord_over_length (c0 / L, what the effect fits).
SidewallMembrane read_sidewall(const ConfigSection& s) {
  SidewallMembrane m;
  m.enabled = s.boolean("enabled", true);
  m.given = true;
  if (!s.has("meridian_chord_mm")) s.fail("meridian_chord_mm", "required in footprint_3d.sidewall");
  const bool length = s.has("meridian_length_mm"), ratio = s.has("chord_over_length");
  if (length && ratio) {
    s.fail("chord_over_length",
           "give the meridian's length once: meridian_length_mm or "
           "chord_over_length");
  }
  if (m.enabled && !length && !ratio) {
    s.fail("meridian_length_mm", "required in footprint_3d.sidewall (or chord_over_length)");
  }
  m.chord_m = s.positive("meridian_chord_mm", 0, 1e4) * 1e-3;
  if (ratio) m.length_m = m.chord_m / s.positive("chord_over_length", 0.8, 0.999);
  if (length) m.length_m = s.positive("meridian_length_mm", 0, 1e4) * 1e-3;
  if ((length || ratio) && !(m.length_m > m.chord_m)) {
    s.fail("meridian_length_mm", "the meridian must be longer than its chord (meridian_chord_mm)");
  }
  return m;
}

}  // namespace

Patch3dSettings read_patch3d_settings(const ConfigSection& s) {
  Patch3dSettings p;
  // A tread narrower than 20 mm (a racing bicycle's) is no tyre; 1 mm ran the patch out of its
  // candidate window (exit 1).
  const ValueRange& width = accepted_range("footprint_3d.tread_width_mm");
  p.tread_width_m = s.number("tread_width_mm", p.tread_width_m * 1e3, width.min, width.max) * 1e-3;
  p.lateral_cell_m = s.positive("lateral_cell_mm", p.lateral_cell_m * 1e3, 200) * 1e-3;
  const double columns = p.tread_width_m / p.lateral_cell_m;
  if (columns > 2000) {
    s.fail("lateral_cell_mm", "tread width / lateral cell = " + std::to_string(long(columns)) +
                                  " columns; at most 2000 are supported");
  }
  p.max_pattern_iterations =
      static_cast<int>(s.integer("max_pattern_iterations", p.max_pattern_iterations, 1, 100000));
  p.crown = read_crown_profile(s.section("crown"));
  if (s.has("lateral_belt")) p.lateral_belt = read_lateral_belt(s.section("lateral_belt"), p);
  if (s.has("sidewall")) p.sidewall = read_sidewall(s.section("sidewall"));
  // The profile must stay a graph over the tread: no vertical tangent inside the shoulders.
  if (0.5 * p.tread_width_m >= p.crown.reach_m()) {
    s.fail("tread_width_mm", "the crown profile turns vertical inside the tread width");
  }
  return p;
}

}  // namespace modaltyre::contact
