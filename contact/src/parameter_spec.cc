#include "modaltyre/contact/parameter_spec.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "modaltyre/contact/effects.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::contact {
namespace {

// The 3D patch settings a footprint_3d.* key moves; InputError when the config has none.
template <class Config>
auto& patch3d_of(Config& c) {
  if (!c.footprint_3d) {
    throw InputError({c.source, 0, "validation.calibrate"},
                     "footprint_3d.* keys need a footprint_3d: section (the 3D patch)");
  }
  return *c.footprint_3d;
}

template <class Config>
auto& crown_of(Config& c) {
  auto& crown = patch3d_of(c).crown;
  if (crown.shape != CrownShape::circular && crown.shape != CrownShape::power) {
    throw InputError({c.source, 0, "validation.calibrate"},
                     "footprint_3d.crown.* is calibrated only on a circular or power crown");
  }
  return crown;
}

template <class Config>
auto& power_crown_of(Config& c) {
  auto& crown = patch3d_of(c).crown;
  if (crown.shape != CrownShape::power) {
    throw InputError({c.source, 0, "validation.calibrate"},
                     "footprint_3d.crown.exponent needs a power crown (shape: power)");
  }
  return crown;
}

SearchRange ln_search(double min, double max) { return {min, max, SearchTransform::log}; }

// Where validate and discover both search a key they search different ranges: validate
// calibrates one to three keys on one or two declared rows, starting from the config's value,
// and keeps to the plausible range of an SF-350-like tyre; discover re-fits the baseline under
// every candidate effect, which can move the carcass level and the tread far from the config's
// (an effect taking over part of the compliance), so its bounded search is wider. Both ranges
// are the ones the two commands have always used (their outputs depend on them).
std::vector<ParameterSpec> tyre_scalars() {
  return {
      {"modal.compliance_scale", "-", ValueRange{1e-3, 1e3}, ln_search(0.2, 5),
       logistic_search(0.05, 20), [](const TyreConfig& c) { return c.compliance_scale; },
       [](TyreConfig& c, double v) { c.compliance_scale = v; }},
      {"tread.modulus_MPa", "MPa", ValueRange{1e-3, 1e4}, ln_search(0.1, 100),
       logistic_search(0.05, 200), [](const TyreConfig& c) { return c.tread.modulus_Pa * 1e-6; },
       [](TyreConfig& c, double v) { c.tread.modulus_Pa = v * 1e6; }},
      {"tread.thickness_mm", "mm", ValueRange{0.1, 200}, ln_search(1, 50), std::nullopt,
       [](const TyreConfig& c) { return c.tread.thickness_m * 1e3; },
       [](TyreConfig& c, double v) { c.tread.thickness_m = v * 1e-3; }},
      {"tread.contact_width_mm", "mm", ValueRange{1, 2000}, ln_search(20, 500), std::nullopt,
       [](const TyreConfig& c) { return c.tread.width_m * 1e3; },
       [](TyreConfig& c, double v) { c.tread.width_m = v * 1e-3; }},
      {"tyre.outer_radius_mm", "mm", ValueRange{50, 2000}, ln_search(100, 1500), std::nullopt,
       [](const TyreConfig& c) { return c.outer_radius_m * 1e3; },
       [](TyreConfig& c, double v) {
         c.outer_radius_m = v * 1e-3;
         // The config reader's check of the key (read_tyre_config).
         if (c.mesh.window_m > M_PI * c.outer_radius_m) {
           throw InputError({c.source, 0, "contact.window_mm"},
                            "candidate window longer than half the circumference");
         }
       }},
      // The 3D patch's crown (footprint_3d.crown, circular or power): rounder crown, narrower
      // patch.
      // Above 100 mm the crown stays a graph over a tread.
      {"footprint_3d.crown.radius_mm", "mm", std::nullopt, ln_search(100, 1e5),
       logistic_search(100, 1e5), [](const TyreConfig& c) { return crown_of(c).radius_m * 1e3; },
       [](TyreConfig& c, double v) { crown_of(c).radius_m = v * 1e-3; }},
      // The power crown's exponent (crown_profile.h): 2 is the circular crown's parabola.
      {"footprint_3d.crown.exponent", "-", std::nullopt, ln_search(1.05, 8), std::nullopt,
       [](const TyreConfig& c) { return power_crown_of(c).exponent; },
       [](TyreConfig& c, double v) { power_crown_of(c).exponent = v; }},
      {"footprint_3d.tread_width_mm", "mm", ValueRange{20, 2000}, ln_search(20, 500), std::nullopt,
       [](const TyreConfig& c) { return patch3d_of(c).tread_width_m * 1e3; },
       [](TyreConfig& c, double v) { patch3d_of(c).tread_width_m = v * 1e-3; }},
      // The pneumatic share beta (pneumatic_share.h): validate may calibrate it (a diagnostic:
      // what share the data would ask for); it starts at 0.1 when the config has none.
      {"modal.pneumatic_share", "-", ValueRange{0, 1}, ln_search(1e-3, 1), std::nullopt,
       [](const TyreConfig& c) { return c.pneumatic_share > 0 ? c.pneumatic_share : 0.1; },
       [](TyreConfig& c, double v) { c.pneumatic_share = v; }},
      // The belt's net hoop tension as a share of p b R (ring normalisation; docs/ring_model.md
      // section 3a): validate may calibrate it on a measured load-deflection row, which settles
      // the section's unknown pull for one tyre.
      {"modal.net_tension_share", "-", ValueRange{0.2, 1}, ln_search(0.2, 1), std::nullopt,
       [](const TyreConfig& c) { return c.carcass.net_tension_share; },
       [](TyreConfig& c, double v) { c.carcass.net_tension_share = v; }},
      // Starts at 10 rad^2/s^2 when not stated (the fit to resolved orders may give 0).
      {"modal.extension_bending_s2_rad2_s2", "rad^2/s^2", ValueRange{0, 1e12}, ln_search(1e-3, 1e6),
       std::nullopt, [](const TyreConfig& c) { return c.extension_s2 > 0 ? c.extension_s2 : 10.0; },
       [](TyreConfig& c, double v) { c.extension_s2 = v; }},
  };
}

std::vector<ParameterSpec> make_parameter_catalogue() {
  std::vector<ParameterSpec> out = tyre_scalars();
  for (const auto& e : effect_catalogue()) {
    for (const auto& p : e.parameters) {
      if (e.is_option()) {
        // An option's key: its reader checks what a config states; discover searches the
        // effect's range. A tyre scalar validate calibrates (modal.pneumatic_share,
        // footprint_3d.crown.exponent) keeps its entry and gains the fit range.
        const std::optional<SearchRange> fit =
            p.fitted ? std::optional<SearchRange>(logistic_search(p.min, p.max)) : std::nullopt;
        auto it = std::find_if(out.begin(), out.end(),
                               [&](const ParameterSpec& q) { return q.key == p.option.key; });
        if (it != out.end()) {
          it->fit = fit;
        } else {
          out.push_back(
              {p.option.key, p.unit, std::nullopt, std::nullopt, fit, p.option.get, p.option.set});
        }
        continue;
      }
      const EffectParameterRef ref = p.ref;
      out.push_back(
          {e.key(p), p.unit, ValueRange{p.min, p.max}, std::nullopt,
           p.fitted ? std::optional<SearchRange>(logistic_search(p.min, p.max)) : std::nullopt,
           [ref](const TyreConfig& c) { return ref(c.effects); },
           [ref](TyreConfig& c, double v) { ref(c.effects) = v; }});
    }
  }
  return out;
}

}  // namespace

SearchRange logistic_search(double min, double max) {
  return {min, max,
          min > 0 && max / min >= 100 ? SearchTransform::log_logistic : SearchTransform::logistic};
}

const std::vector<ParameterSpec>& parameter_catalogue() {
  static const std::vector<ParameterSpec> c = make_parameter_catalogue();
  return c;
}

const ParameterSpec* find_parameter(std::string_view key) {
  for (const auto& p : parameter_catalogue()) {
    if (p.key == key) return &p;
  }
  return nullptr;
}

const ValueRange& accepted_range(std::string_view key) {
  const ParameterSpec* p = find_parameter(key);
  if (!p || !p->accepted) {
    throw std::logic_error("no accepted range for " + std::string(key));
  }
  return *p->accepted;
}

}  // namespace modaltyre::contact
