#include "modaltyre/contact/carcass_source.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/ring_basis.h"

namespace modaltyre::contact {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;
/// A belt mass whose mu differs from the tension's by more than this factor is reported: the
/// two facts disagree beyond the belt width's and the sidewall share's uncertainty.
constexpr double kMassDisagreementFactor = 1.5;
/// A wheel's polar inertia as a share of m r_rim^2 (mass mostly at the rim, some in the disc):
/// the free rotation mode's correction; stated in docs/ring_model.md section 5.
constexpr double kWheelInertiaShare = 0.6;

std::string fmt(double v, int prec = 3) {
  std::ostringstream s;
  s.precision(prec);
  s << v;
  return s.str();
}

// One mode of the data as the ring takes it: order, kind, test-pressure frequency.
struct DataMode {
  int order = 0;
  bool rotation = false;
  double freq_hz = 0, damping = 0;
  int id = 0;
  std::size_t ident_index = 0;
};

std::vector<DataMode> data_modes(const modal::ModeIdentification& ident) {
  std::vector<DataMode> out;
  for (std::size_t i = 0; i < ident.modes.size(); ++i) {
    const auto& m = ident.modes[i];
    if (m.kind == modal::ModeKind::rotation) {
      out.push_back({0, true, m.freq_hz, m.damping_ratio, m.id, i});
    } else if (m.kind == modal::ModeKind::radial && m.order() >= 0) {
      out.push_back({m.order(), false, m.freq_hz, m.damping_ratio, m.id, i});
    }
  }
  return out;
}

// The belt mass of the boundary correction: stated, else the ring's 2 pi R mu.
double belt_mass(const CarcassSettings& s, double mu, double R) {
  return s.belt_mass_kg > 0 ? s.belt_mass_kg : kTwoPi * R * mu;
}

// Free test -> rim held: order-1 translation and the rotation (docs/ring_model.md section 5).
double rim_held_hz(const DataMode& m, const CarcassSettings& s, const TyreConfig& c, double mu) {
  if (s.boundary != TestBoundary::free) return m.freq_hz;
  const double R = c.outer_radius_m;
  const double mb = belt_mass(s, mu, R);
  if (m.rotation) {
    const double r_rim = c.rim_radius_m > 0 ? c.rim_radius_m : 0.6 * R;
    return modal::rim_held_frequency_hz(m.freq_hz, mb * R * R,
                                        kWheelInertiaShare * s.wheel_mass_kg * r_rim * r_rim);
  }
  if (m.order == 1) return modal::rim_held_frequency_hz(m.freq_hz, mb, s.wheel_mass_kg);
  return m.freq_hz;
}

modal::RingFit ring_fit_of(const std::vector<DataMode>& modes, const std::vector<double>& hz) {
  std::vector<int> orders;
  std::vector<double> f;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    if (modes[i].rotation || modes[i].order < 1) continue;
    orders.push_back(modes[i].order);
    f.push_back(hz[i]);
  }
  return modal::fit_ring(orders, f);
}

// The stiffness ratio K(p) / K(p0) of a mode of the data (order >= 1 from the fit; breathing
// and rotation by their foundation's pneumatic share).
double stiffness_ratio(const DataMode& m, const modal::RingCoefficients& at_p0,
                       const modal::RingCoefficients& at_p) {
  if (m.rotation) {
    return at_p0.tangential_foundation > 0
               ? at_p.tangential_foundation / at_p0.tangential_foundation
               : 1.0;
  }
  if (m.order == 0) {
    return at_p0.radial_foundation > 0 ? at_p.radial_foundation / at_p0.radial_foundation : 1.0;
  }
  return at_p.stiffness_per_mass(m.order) / at_p0.stiffness_per_mass(m.order);
}

// Median of mu_n = 1 / (pi R (1 + 1/n^2) |c_r|^2) over the resolved radial modes of order >= 2
// (what mass-normalised shapes say of the belt), 0 when there is none.
double shapes_mass(const modal::ModeIdentification& ident, double R) {
  std::vector<double> mus;
  for (const auto& m : ident.modes) {
    if (m.kind != modal::ModeKind::radial || m.aliased || m.apparent_order < 2) continue;
    const double a2 = std::norm(m.c_radial);
    if (a2 > 0) mus.push_back(1.0 / (M_PI * R * modal::ring_mass_factor(m.apparent_order) * a2));
  }
  if (mus.empty()) return 0;
  std::nth_element(mus.begin(), mus.begin() + mus.size() / 2, mus.end());
  return mus[mus.size() / 2];
}

}  // namespace

CarcassSettings read_carcass_settings(const ConfigSection& modal) {
  CarcassSettings s;
  s.frequencies_hz = modal.numbers("frequencies_hz", {}, 1e-3, 1e5);
  for (double f : s.frequencies_hz) {
    if (!(f > 0)) modal.fail("frequencies_hz", "every frequency must be greater than 0 Hz");
  }
  for (long k : modal.integers("orders", {}, 0, 1000)) s.orders.push_back(int(k));
  s.damping_ratios = modal.numbers("damping_ratios", {}, 0, 0.999);
  if (s.frequency_list()) {
    if (modal.has("hammer_csv")) {
      modal.fail("frequencies_hz", "give either hammer_csv or a frequency list, not both");
    }
    if (s.orders.size() != s.frequencies_hz.size()) {
      modal.fail("orders", "one harmonic order per frequency is needed (" +
                               std::to_string(s.frequencies_hz.size()) + " frequencies, " +
                               std::to_string(s.orders.size()) +
                               " orders); `modaltyre init` proposes orders");
    }
    if (!s.damping_ratios.empty() && s.damping_ratios.size() != s.frequencies_hz.size()) {
      modal.fail("damping_ratios", "one damping ratio per frequency (or none)");
    }
    if (s.damping_ratios.empty()) s.damping_ratios.assign(s.frequencies_hz.size(), 0.03);
  } else if (!s.orders.empty() || !s.damping_ratios.empty()) {
    modal.fail(s.orders.empty() ? "damping_ratios" : "orders",
               "belongs to a frequency list (modal.frequencies_hz)");
  }
  // Alternative order assignments: at most init's max_alternatives (5) plus a few of the user's.
  constexpr std::size_t kMaxAlternatives = 10;
  for (const auto& alt : modal.integer_lists("order_alternatives", 0, 1000, kMaxAlternatives)) {
    s.order_alternatives.emplace_back(alt.begin(), alt.end());
    if (!s.frequency_list() || s.order_alternatives.back().size() != s.frequencies_hz.size()) {
      modal.fail("order_alternatives",
                 "each alternative gives one order per frequency of modal.frequencies_hz");
    }
  }
  s.order_alternative_probabilities = modal.numbers("order_alternative_probabilities", {}, 0, 1);
  if (s.order_alternative_probabilities.size() != s.order_alternatives.size()) {
    modal.fail(
        s.order_alternatives.empty() ? "order_alternative_probabilities" : "order_alternatives",
        "one probability per alternative (modal.order_alternative_probabilities)");
  }
  double sum = 0;
  for (double p : s.order_alternative_probabilities) {
    if (!(p > 0)) modal.fail("order_alternative_probabilities", "every probability must be > 0");
    sum += p;
  }
  if (!(sum < 1)) {
    modal.fail("order_alternative_probabilities",
               "the alternatives' probabilities must sum to less than 1 (modal.orders has the "
               "rest)");
  }
  s.rotation_frequency_hz = modal.number("rotation_frequency_hz", 0, 0, 1e5);
  s.rotation_damping_ratio = modal.number("rotation_damping_ratio", 0, 0, 0.999);
  const std::string norm =
      modal.choice("normalisation", s.frequency_list() ? "ring" : "shapes", {"shapes", "ring"});
  if (s.frequency_list() && norm == "shapes") {
    modal.fail("normalisation", "a frequency list has no shapes: only 'ring' applies");
  }
  s.normalisation = norm == "ring" ? ModalNormalisation::ring : ModalNormalisation::shapes;
  s.test_pressure_Pa = modal.number("test_pressure_kPa", 0, 0, 2000) * 1e3;
  if (modal.has("test_pressure_kPa") && s.test_pressure_Pa < 10e3) {
    modal.fail("test_pressure_kPa", "must be at least 10 kPa (an inflated tyre)");
  }
  const std::string b = modal.choice("boundary", "rim-fixed", {"rim-fixed", "free"});
  s.boundary = b == "free" ? TestBoundary::free : TestBoundary::rim_fixed;
  s.wheel_mass_kg = modal.number("wheel_mass_kg", 0, 0, 1e4);
  if (s.boundary == TestBoundary::free && !(s.wheel_mass_kg > 0)) {
    modal.fail("boundary",
               "a free modal test needs modal.wheel_mass_kg (the wheel's mass, which moves with "
               "the order-1 and rotation modes; a passenger-car wheel weighs 5-12 kg)");
  }
  s.belt_width_m = modal.number("belt_width_mm", 0, 0, 5000) * 1e-3;
  const ValueRange& share = accepted_range("modal.net_tension_share");
  s.net_tension_share = modal.number("net_tension_share", 1.0, share.min, share.max);
  s.net_tension_share_stated = modal.has("net_tension_share");
  s.mass_per_length_kg_m = modal.number("mass_per_length_kg_m", 0, 0, 1e4);
  s.belt_mass_kg = modal.number("belt_mass_kg", 0, 0, 1e5);
  s.foundation_pneumatic_fraction = modal.number("foundation_pneumatic_fraction", 1.0, 0, 1);
  if (s.normalisation == ModalNormalisation::ring && !(s.mass_per_length_kg_m > 0) &&
      !(s.belt_width_m > 0)) {
    modal.fail(modal.has("normalisation") ? "normalisation" : "frequencies_hz",
               "the ring normalisation needs the modal mass's scale: state modal.belt_width_mm "
               "(the hoop tension T = p b R fixes it) or modal.mass_per_length_kg_m");
  }
  return s;
}

modal::ModeIdentification config_modes(const TyreConfig& config) {
  const CarcassSettings& s = config.carcass;
  if (!s.frequency_list()) {
    return modal::identify_modes(modal::read_hammer_csv(config.hammer_csv));
  }
  modal::ModeIdentification ident;
  for (std::size_t i = 0; i < s.frequencies_hz.size(); ++i) {
    modal::IdentifiedMode m;
    m.id = static_cast<int>(i + 1);
    m.freq_hz = s.frequencies_hz[i];
    m.damping_ratio = s.damping_ratios[i];
    m.kind = modal::ModeKind::radial;
    m.apparent_order = s.orders[i];
    m.r2 = 1;
    m.note = "stated order (frequency list)";
    ident.modes.push_back(m);
  }
  if (s.rotation_frequency_hz > 0) {
    modal::IdentifiedMode m;
    m.id = static_cast<int>(ident.modes.size() + 1);
    m.freq_hz = s.rotation_frequency_hz;
    m.damping_ratio = s.rotation_damping_ratio;
    m.kind = modal::ModeKind::rotation;
    m.r2 = 1;
    m.note = "stated rotation mode (frequency list)";
    ident.modes.push_back(m);
  }
  return ident;
}

modal::ModalBasis carcass_basis(const TyreConfig& config, const modal::ModeIdentification& ident,
                                int max_order, CarcassDerivation& d) {
  const CarcassSettings& s = config.carcass;
  const double R = config.outer_radius_m;
  d = {};
  d.ring = s.normalisation == ModalNormalisation::ring;
  d.operating_pressure_Pa = config.inflation_pressure_Pa;
  d.test_pressure_Pa = s.test_pressure_Pa > 0 ? s.test_pressure_Pa : config.inflation_pressure_Pa;
  if (!(s.test_pressure_Pa > 0)) {
    d.warnings.push_back(
        "modal.test_pressure_kPa not stated: the modal data are taken at the operating "
        "pressure; state the modal test's pressure so that a change of pressure acts");
  }
  const std::vector<DataMode> modes = data_modes(ident);
  std::vector<double> hz;
  for (const auto& m : modes) hz.push_back(m.freq_hz);

  // The mass scale: stated, else the shapes' own (their median, for the boundary's belt mass),
  // else the tension of a first fit (the order-1 correction needs mu, and mu the fit: the fit
  // of orders >= 2 alone gives the tension term, the order-1 mode adds only a + d).
  const double mu_shapes = d.ring ? 0.0 : shapes_mass(ident, R);
  auto mu_for = [&](const modal::RingFit& fit, std::string& source) {
    if (s.mass_per_length_kg_m > 0) {
      source = "stated";
      return s.mass_per_length_kg_m;
    }
    if (!d.ring) {
      source = "shapes";
      return mu_shapes;
    }
    if (!fit.valid || !(fit.coefficients.tension > 0)) {
      throw InputError({config.source, 0, "modal.belt_width_mm"},
                       "the ring fit of the modes has no tension term (" +
                           (fit.valid ? std::string("it is zero") : fit.reason) +
                           "): the hoop tension cannot fix the modal mass; state "
                           "modal.mass_per_length_kg_m");
    }
    source = "tension";
    // The net tension H = share p b R (docs/ring_model.md section 3a) is the ring's tension term.
    return modal::mass_per_length_from_tension(fit.coefficients, d.test_pressure_Pa,
                                               s.net_tension_share * s.belt_width_m, R);
  };
  std::vector<DataMode> high;
  std::vector<double> high_hz;
  for (std::size_t i = 0; i < modes.size(); ++i) {
    if (!modes[i].rotation && modes[i].order >= 2)
      high.push_back(modes[i]), high_hz.push_back(hz[i]);
  }
  std::string source;
  double mu = mu_for(ring_fit_of(high, high_hz), source);
  std::vector<double> held(hz.size());
  // The order-1 correction needs mu and the tension's mu the fit: a fixed point, settled in a
  // few passes (the correction moves only a + d, mu rests on the tension term).
  for (int pass = 0; pass < 3; ++pass) {
    for (std::size_t i = 0; i < modes.size(); ++i)
      held[i] = rim_held_hz(modes[i], s, config, mu > 0 ? mu : 1.0);
    d.fit = ring_fit_of(modes, held);
    if (d.ring && !(s.mass_per_length_kg_m > 0)) mu = mu_for(d.fit, source);
  }
  d.mass_per_length_kg_m = mu;
  d.mass_source = source;
  if (source == "tension" && !s.net_tension_share_stated) {
    d.warnings.push_back(
        "modal.net_tension_share not stated: the modal mass takes the gross tension p b R; the "
        "sidewalls' pull lowers it to about 0.4-0.7 of that (docs/ring_model.md section 3a; "
        "init states it)");
  }
  if (s.belt_width_m > 0)
    d.membrane_tension_N = s.net_tension_share * d.test_pressure_Pa * s.belt_width_m * R;
  if (d.fit.valid && mu > 0) d.tension_N = modal::implied_tension_N(d.fit.coefficients, mu, R);
  if (s.belt_mass_kg > 0 && mu > 0) {
    const double mu_belt = s.belt_mass_kg / (kTwoPi * R);
    const double ratio = mu_belt / mu;
    if (ratio > kMassDisagreementFactor || ratio < 1 / kMassDisagreementFactor) {
      d.warnings.push_back("modal.belt_mass_kg " + fmt(s.belt_mass_kg) + " kg is " + fmt(mu_belt) +
                           " kg/m on the ring, " + fmt(ratio, 2) + " x the " + source + "'s " +
                           fmt(mu) + " kg/m (a maker's belt mass includes part of the sidewalls)");
    }
  }
  if (!d.ring && d.membrane_tension_N > 0 && d.tension_N > 0) {
    const double ratio = d.tension_N / d.membrane_tension_N;
    if (ratio > kMassDisagreementFactor || ratio < 1 / kMassDisagreementFactor) {
      d.warnings.push_back("the shapes' modal mass (" + fmt(mu) + " kg/m) implies a hoop tension " +
                           fmt(d.tension_N, 4) + " N, " + fmt(ratio, 2) +
                           " x p b R = " + fmt(d.membrane_tension_N, 4) + " N");
    }
  }

  // The operating pressure: every mode's stiffness by the ring's pressure terms.
  const bool pressure_moves = std::abs(d.operating_pressure_Pa - d.test_pressure_Pa) > 0;
  if (pressure_moves && !d.fit.valid) {
    throw InputError({config.source, 0, "modal.test_pressure_kPa"},
                     "the operating pressure differs from the modal test's, but the modes give no "
                     "ring fit to move them by (" +
                         d.fit.reason + ")");
  }
  const modal::RingCoefficients at_p =
      d.fit.valid ? modal::at_pressure(d.fit.coefficients, d.test_pressure_Pa,
                                       d.operating_pressure_Pa, s.foundation_pneumatic_fraction)
                  : modal::RingCoefficients{};
  std::vector<double> at_op(held.size());
  for (std::size_t i = 0; i < modes.size(); ++i) {
    at_op[i] = pressure_moves
                   ? held[i] * std::sqrt(stiffness_ratio(modes[i], d.fit.coefficients, at_p))
                   : held[i];
  }

  if (d.ring) {
    std::vector<modal::RingMode> ring_modes;
    for (std::size_t i = 0; i < modes.size(); ++i) {
      ring_modes.push_back(
          {modes[i].order, modes[i].rotation, at_op[i], modes[i].damping, modes[i].id});
    }
    modal::RingFit fit_p = d.fit;
    fit_p.coefficients = at_p;
    modal::RingBasisOptions o;
    o.mass_per_length_kg_m = mu;
    o.radius_m = R;
    o.max_order = max_order;
    o.extend = config.extend_orders;
    o.compliance_scale = config.compliance_scale;
    return modal::build_ring_basis(ring_modes, fit_p, o);
  }

  // The shapes' own scale: today's basis on the moved frequencies; a free test's order-1 and
  // rotation terms rescaled to the rim-held modal mass (docs/ring_model.md section 5).
  modal::ModeIdentification moved = ident;
  for (std::size_t i = 0; i < modes.size(); ++i)
    moved.modes[modes[i].ident_index].freq_hz = at_op[i];
  if (config.extension_s2 >= 0) moved.dispersion.s2 = config.extension_s2;
  if (pressure_moves && moved.dispersion.valid) {
    // The extension's dispersion is on omega^2: its terms move like the ring's at each order.
    d.warnings.push_back("unmeasured orders keep the modal test's pressure (shapes path)");
  }
  modal::ModalBasisOptions bo;
  bo.max_order = max_order;
  bo.extend = config.extend_orders;
  bo.compliance_scale = config.compliance_scale;
  modal::ModalBasis basis = modal::build_modal_basis(moved, bo);
  if (s.boundary == TestBoundary::free) {
    const double mb = belt_mass(s, mu > 0 ? mu : 1.0, R);
    const double r_rim = config.rim_radius_m > 0 ? config.rim_radius_m : 0.6 * R;
    for (auto& t : basis.terms) {
      if (!t.measured || !(t.order == 1 || t.rotation)) continue;
      const double ratio = t.rotation
                               ? mb * R * R / (kWheelInertiaShare * s.wheel_mass_kg * r_rim * r_rim)
                               : mb / s.wheel_mass_kg;
      t.P_rr *= 1 + ratio;
      t.P_rt *= 1 + ratio;
      t.P_tt *= 1 + ratio;
    }
  }
  return basis;
}

modal::ModalBasis basis_at_pressure(const modal::ModalBasis& basis, const CarcassDerivation& d,
                                    const CarcassSettings& s, double pressure_Pa) {
  if (!d.fit.valid || pressure_Pa == d.operating_pressure_Pa) return basis;
  const auto at_model =
      modal::at_pressure(d.fit.coefficients, d.test_pressure_Pa, d.operating_pressure_Pa,
                         s.foundation_pneumatic_fraction);
  const auto at_case = modal::at_pressure(d.fit.coefficients, d.test_pressure_Pa, pressure_Pa,
                                          s.foundation_pneumatic_fraction);
  modal::ModalBasis out = basis;
  for (auto& t : out.terms) {
    DataMode m;
    m.order = t.order;
    m.rotation = t.rotation;
    t.omega_rad_s *= std::sqrt(stiffness_ratio(m, at_model, at_case));
  }
  return out;
}

}  // namespace modaltyre::contact
