#include "modaltyre/init/init_tyre.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "init_checks.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/ring_model.h"
#include "order_alternatives.h"

namespace modaltyre::init {
namespace {

// ---- stated defaults (each with its range and source; docs/ring_model.md section 6) ---------

/// Tread (arc) width as a share of the section width: the usual passenger proportion
/// (assumed, as the SF-350 default's 150 mm of 195 mm; 0.70-0.85 across passenger sizes).
constexpr double kTreadWidthShare = 0.77;
/// New passenger tread depth [mm]: 9/32-13/32 in = 7.1-10.3 mm (National Research Council,
/// "Tires and Passenger Vehicle Fuel Economy", 2006, p. 18).
constexpr double kTreadDepth_mm = 8.0;
/// Tread compound static modulus [MPa]: the low end of 3-8 MPa (Shore A 60-70 by Gent's
/// relation: 3.7-5.6 MPa), as the SF-350 default.
constexpr double kTreadModulus_MPa = 3.0;
/// The assumptions' spreads, carried into --uncertainty's bands (issue 44 item 2), each a
/// uniform range written as (b - a) / sqrt(12) of the nominal: the tread-width share's
/// 0.70-0.85 (above, when the width is not given); the compound's Shore A 60-70 by Gent's
/// relation, 3.7-5.6 MPa.
constexpr double kTreadWidthShareLo = 0.70, kTreadWidthShareHi = 0.85;
constexpr double kModulusLo_MPa = 3.7, kModulusHi_MPa = 5.6;
/// The roundest crown the flat assumption's band spans (footprint_3d.crown.round_limit_radius_mm):
/// the SF-350's crown radius calibrated on Table 3's measured widths on this structure (laterally
/// rigid belt), 1058 mm on its 150 mm tread (docs/validation.md), scaled with the tread width.
constexpr double kRoundCrown_mm = 1058, kRoundCrownTread_mm = 150;
/// Tread loss factor: a passenger compound's 0.1-0.2 at 10-100 Hz.
constexpr double kTreadTanDelta = 0.15;
/// Modal damping ratio when none is given: the median of seed 001 Table 2's radial modes
/// (2.8-5.2 %); a static footprint does not depend on it.
constexpr double kDampingRatio = 0.035;
/// A passenger wheel's mass [kg] at 14 in and per inch of rim (steel and alloy wheels of
/// 13-17 in weigh about 6-10 kg; assumed).
constexpr double kWheelMass14_kg = 7.0, kWheelMassPerInch_kg = 0.7;
/// FNOMIN of a passenger tyre [N] (MF-Tool's passenger default, e.g. the TNO 205/60R15).
constexpr double kFnomin_N = 4000;
/// The patch's candidate window as a multiple of the outer radius (the SF-350's 360 mm on
/// 294.8 mm; the window must hold the longest footprint, 2a < 0.6 R0 up to 2 x FNOMIN).
constexpr double kWindowPerRadius = 1.22;
/// The belt's net hoop tension (docs/ring_model.md section 3a) needs the section's shape, which a
/// designation does not give; stated: the widest point at mid-height of the section (radial
/// passenger sidewalls: 0.45-0.55 of the height), the sidewall leaving the belt edge at 37.5 deg
/// to the axis (30-45 deg), the carcass line 4 mm under the tread (belt plies and under-tread).
constexpr double kWidestPointShare = 0.5, kEdgeAngle_deg = 37.5, kUnderTread_mm = 4;
/// The TNO 205/60R15 sample file's BELT_MASS [kg] (docs/validation.md), the passenger belt the
/// warning on a free test without --belt-mass-kg compares the ring's mass with.
constexpr double kTnoBeltMass_kg = 7.698;
/// Order proposals whose scores differ by less than this are near-ties (Akaike's margin).
constexpr double kNearTie = 2.0;

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

template <class T>
std::string list(const std::vector<T>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(double(v[i]));
  return s + "]";
}

std::string yaml_quoted(const std::string& text) {
  YAML::Emitter e;
  e << YAML::DoubleQuoted << text;
  return e.c_str();
}

void require_positive(double v, const std::string& option, const std::string& what) {
  if (!(v > 0) || !std::isfinite(v)) throw InputError({option, 0, ""}, what + " must be > 0");
}

}  // namespace

InitResult init_tyre(const InitInputs& in) {
  InitResult r;
  const TyreSize size = parse_tyre_size(in.size);
  check_init_inputs(in, size);
  const double p_kPa = in.pressure_kPa.value_or(in.test_pressure_kPa);
  const bool list_given = !in.frequencies_hz.empty();

  const double R0_mm = size.outer_radius_mm();
  const double tread_w =
      in.tread_width_mm.value_or(std::round(kTreadWidthShare * size.section_width_mm));
  const double belt_w = in.belt_width_mm.value_or(tread_w);
  const double depth = in.tread_depth_mm.value_or(kTreadDepth_mm);
  const double wheel = in.wheel_mass_kg.value_or(kWheelMass14_kg + kWheelMassPerInch_kg *
                                                                       (size.rim_diameter_in - 14));
  const double fnomin = in.fnomin_N.value_or(kFnomin_N);
  auto decide = [&](const std::string& key, const std::string& value, const std::string& source) {
    r.decisions.push_back({key, value, source});
  };

  // ---- the modal data: orders stated, or proposed from the list ----------------------------
  std::vector<double> freqs;
  std::vector<double> damping = in.damping_ratios;
  if (list_given) {
    freqs = in.frequencies_hz;
    for (double f : freqs) require_positive(f, "--frequencies", "every frequency");
    if (!damping.empty() && damping.size() != freqs.size())
      throw InputError({"--damping", 0, ""}, "one damping ratio per frequency (or none)");
    for (double z : damping)
      if (!(z >= 0 && z < 1))
        throw InputError({"--damping", 0, ""}, "damping ratios must be in [0, 1)");
    if (!in.orders.empty() && in.orders.size() != freqs.size())
      throw InputError({"--orders", 0, ""}, "one order per frequency (" +
                                                std::to_string(freqs.size()) + " frequencies, " +
                                                std::to_string(in.orders.size()) + " orders)");
    if (in.orders.empty()) {
      modal::OrderProposalOptions o;
      o.pressure_Pa = in.test_pressure_kPa * 1e3;
      // The proposal's mass plausibility (1-8 kg/m) is on the gross tension p b R.
      o.belt_width_m = belt_w * 1e-3;
      o.radius_m = R0_mm * 1e-3;
      // A free test's order 1 is scored at the held wheel; a rim-fixed one as it is.
      o.order1_in_fit = in.boundary == "rim-fixed";
      if (in.boundary == "free") o.wheel_mass_kg = wheel;
      o.max_alternatives = kProposalsAsked;
      r.alternatives = modal::propose_orders(freqs, o);
      if (r.alternatives.empty())
        throw InputError({"--frequencies", 0, ""},
                         "at least three frequencies are needed to propose orders; state --orders");
      r.orders = r.alternatives.front().orders;
      r.orders_proposed = true;
      int ties = 0;
      for (std::size_t k = 1; k < r.alternatives.size(); ++k)
        ties += r.alternatives[k].score < r.alternatives.front().score + kNearTie;
      if (ties > 0) {
        r.warnings.push_back("the orders were proposed, and " + std::to_string(ties) +
                             " other assignment(s) fit within " + num(kNearTie) +
                             " of the best score (init --json lists them): the frequencies "
                             "alone cannot decide; state --orders if the test's shapes say");
      }
    } else {
      r.orders = in.orders;
    }
  }

  // ---- the config text -------------------------------------------------------------------
  std::ostringstream y;
  const std::string name = in.name.empty() ? size.text + " at " + num(p_kPa) + " kPa" : in.name;
  y << "# " << name
    << ": written by `modaltyre init` (docs/ring_model.md). No value is calibrated;\n"
    << "# each says where it comes from. A declared calibration on measured rows can be added in "
       "a\n"
    << "# validation: section (README, step 4).\n";
  y << "tyre:\n  name: " << yaml_quoted(name) << "\n";
  y << "  # " << size.text << ": rim " << num(size.rim_diameter_in)
    << " in = " << num(2 * size.rim_radius_mm()) << " mm, section height " << num(size.aspect_ratio)
    << " x " << num(size.section_width_mm) << " mm\n";
  y << "  outer_radius_mm: " << num(R0_mm) << "\n";
  y << "  inflation_pressure_kPa: " << num(p_kPa) << "   # operating pressure (input)\n";
  y << "  section_width_mm: " << num(size.section_width_mm)
    << "\n  aspect_ratio: " << num(size.aspect_ratio)
    << "\n  rim_radius_mm: " << num(size.rim_radius_mm()) << "\n";
  decide("tyre.outer_radius_mm", num(R0_mm), "size designation");
  decide("tyre.inflation_pressure_kPa", num(p_kPa),
         in.pressure_kPa > 0 ? "input" : "the test pressure (input)");

  y << "modal:\n";
  if (list_given) {
    if (damping.empty()) damping.assign(freqs.size(), kDampingRatio);
    std::vector<double> f_list, z_list;
    std::vector<int> o_list;
    double rot_f = 0, rot_z = 0;
    for (std::size_t i = 0; i < freqs.size(); ++i) {
      if (r.orders[i] < 0) {
        if (rot_f > 0) throw InputError({"--orders", 0, ""}, "at most one rotation mode (r)");
        rot_f = freqs[i], rot_z = damping[i];
        continue;
      }
      f_list.push_back(freqs[i]), z_list.push_back(damping[i]), o_list.push_back(r.orders[i]);
    }
    y << "  # Frequencies: input. Orders: "
      << (r.orders_proposed
              ? "proposed from the ring dispersion (init --json lists the alternatives)"
              : "input")
      << ".\n";
    y << "  frequencies_hz: " << list(f_list) << "\n  orders: " << list(o_list) << "\n";
    y << "  # Damping: "
      << (in.damping_ratios.empty() ? "not given; 0.035, the median of seed 001 Table 2 (2.8-5.2 "
                                      "%), acts only in the transient"
                                    : "input")
      << ".\n";
    y << "  damping_ratios: " << list(z_list) << "\n";
    if (rot_f > 0)
      y << "  rotation_frequency_hz: " << num(rot_f) << "\n  rotation_damping_ratio: " << num(rot_z)
        << "\n";
    decide("modal.orders", list(o_list),
           r.orders_proposed ? "proposed (ring dispersion)" : "input");
    // The readings the frequencies leave plausible (order_alternatives.h): written with their
    // Akaike weights exp(-(score - best) / 2) over the set, so that --uncertainty mixes them
    // into its bands (issues 35, 44; docs/uncertainty.md section 2).
    if (r.orders_proposed) {
      const CarriedOrders carried = carried_orders(r.alternatives, freqs);
      if (carried.index.size() > 1) {
        std::string lists = "[", probs = "[";
        for (std::size_t k = 1; k < carried.index.size(); ++k) {
          lists += (k > 1 ? ", " : "") + list(r.alternatives[carried.index[k]].orders);
          // 4 decimals, never 0 (the reader wants every probability > 0).
          const double p = std::max(std::round(carried.probability[k] * 1e4) / 1e4, 1e-4);
          probs += (k > 1 ? ", " : "") + num(p);
        }
        y << "  # Other readings of the list, weighed by the evidence: their Akaike weights\n"
          << "  # exp(-(score - best)/2) over every reading within 6 of the best score and the\n"
          << "  # consecutive readings (orders 1.. and 2..) within 13.8; the prediction uses\n"
          << "  # `orders` (probability " << num(std::round(carried.probability[0] * 1e4) / 1e4)
          << "), --uncertainty mixes these into its bands.\n"
          << "  # State --orders if the test's shapes decide.\n";
        y << "  order_alternatives: " << lists << "]\n";
        y << "  order_alternative_probabilities: " << probs << "]\n";
        decide("modal.order_alternatives", lists + "]",
               "readings within 6 of the best score, consecutive ones within 13.8 (Akaike "
               "weights)");
      }
      // The JSON lists the carried readings, then the next best up to five.
      std::vector<modal::OrderProposal> shown;
      for (std::size_t k : carried.index) shown.push_back(r.alternatives[k]);
      for (std::size_t k = 0; k < r.alternatives.size() && shown.size() < 5; ++k) {
        if (std::find(carried.index.begin(), carried.index.end(), k) == carried.index.end())
          shown.push_back(r.alternatives[k]);
      }
      std::stable_sort(shown.begin(), shown.end(),
                       [](const auto& a, const auto& b) { return a.score < b.score; });
      r.alternatives = std::move(shown);
    }
  } else {
    std::string path = in.hammer_csv;
    if (!in.output_path.empty()) {
      std::error_code ec;
      const auto folder = std::filesystem::absolute(in.output_path, ec).parent_path();
      const auto rel =
          std::filesystem::relative(std::filesystem::absolute(in.hammer_csv, ec), folder, ec);
      if (!ec && !rel.empty()) path = rel.generic_string();
    }
    y << "  # Hammer data (input); their orders from the shapes (fit-modes), their scale from the "
         "ring:\n"
      << "  hammer_csv: " << yaml_quoted(path) << "\n  normalisation: ring\n";
  }
  y << "  # The modal test's pressure and boundary: properties of the data (input).\n";
  y << "  test_pressure_kPa: " << num(in.test_pressure_kPa) << "\n  boundary: " << in.boundary
    << "\n";
  if (in.boundary == "free") {
    y << "  # The wheel moves with the free test's order-1 mode (docs/ring_model.md section 5): "
      << (in.wheel_mass_kg > 0 ? "input" : "assumed, 6-10 kg for 13-17 in passenger wheels")
      << ".\n";
    y << "  wheel_mass_kg: " << num(wheel) << "\n";
    decide("modal.wheel_mass_kg", num(wheel),
           in.wheel_mass_kg > 0 ? "input" : "assumed (13-17 in wheels: 6-10 kg)");
  }
  y << "  # The hoop tension T = p b R over the belt width fixes the modal mass: "
    << (in.belt_width_mm > 0 ? "input" : "the tread width (the belt spans the tread; assumed)")
    << ".\n";
  y << "  belt_width_mm: " << num(belt_w) << "\n";
  decide("modal.belt_width_mm", num(belt_w),
         in.belt_width_mm > 0 ? "input" : "= tread width (assumed)");
  {
    // The ring's tension term is the belt's net hoop tension (docs/ring_model.md section 3a):
    // p b R less the sidewalls' pull, for the stated section; the section's ranges (widest point
    // 0.45-0.55 of the height, edge angle 30-45 deg) are its uncertainty, as a uniform range
    // (b - a) / sqrt(12) of the nominal, carried as the tension's width.
    auto share_at = [&](double widest_share, double angle_deg) {
      modal::BeltSection sec;
      sec.belt_width_m = belt_w * 1e-3;
      sec.edge_radius_m = (R0_mm - depth - kUnderTread_mm) * 1e-3;
      sec.max_width_radius_m =
          (size.rim_radius_mm() + widest_share * size.aspect_ratio * size.section_width_mm) * 1e-3;
      sec.edge_angle_rad = angle_deg * M_PI / 180;
      if (!(sec.max_width_radius_m < sec.edge_radius_m)) return 1.0;
      return modal::net_hoop_tension_N(1.0, sec) / (sec.belt_width_m * sec.edge_radius_m);
    };
    const double share = std::clamp(share_at(kWidestPointShare, kEdgeAngle_deg), 0.2, 1.0);
    const double hi =
        std::clamp(share_at(kWidestPointShare + 0.05, kEdgeAngle_deg - 7.5), 0.2, 1.0);
    const double lo =
        std::clamp(share_at(kWidestPointShare - 0.05, kEdgeAngle_deg + 7.5), 0.2, 1.0);
    const double share_r = std::round(share * 1000) / 1000;
    const double std_percent = std::round(1000 * (hi - lo) / std::sqrt(12.0) / share) / 10;
    y << "  # The ring's tension is the belt's net hoop tension: p b R less the sidewalls' pull at "
         "the\n"
      << "  # belt edges, H = p [b r_e - (r_e^2 - r_m^2) tan psi_e] (docs/ring_model.md 3a), for "
         "the\n"
      << "  # stated section: widest point at mid-height (0.45-0.55), psi_e 37.5 deg (30-45).\n";
    y << "  net_tension_share: " << num(share_r) << "\n";
    y << "  # The section's ranges as the tension's uncertainty (uniform, (b - a)/sqrt(12)): "
      << num(std::round(lo * 100) / 100) << "-" << num(std::round(hi * 100) / 100) << ".\n";
    y << "  belt_width_std_percent: " << num(std_percent) << "\n";
    decide("modal.net_tension_share", num(share_r),
           "sidewall pull on the stated section (docs/ring_model.md 3a)");
    decide("modal.belt_width_std_percent", num(std_percent),
           "the section's ranges " + num(std::round(lo * 100) / 100) + "-" +
               num(std::round(hi * 100) / 100) + " as a uniform range");
  }
  if (in.belt_mass_kg > 0) {
    y << "  # The maker's belt mass (input): checks the tension's mass, and is the order-1 mass.\n";
    y << "  belt_mass_kg: " << num(*in.belt_mass_kg) << "\n";
  }
  y << "  # Unmeasured orders up to the mesh's Nyquist order from the ring fit.\n  extend_orders: "
       "true\n";

  y << "tread:\n";
  y << "  # Compound static modulus: the low end of a passenger tread compound's 3-8 MPa "
       "(stated).\n";
  y << "  modulus_MPa: " << num(kTreadModulus_MPa) << "\n  tan_delta: " << num(kTreadTanDelta)
    << "\n";
  {
    const double pct =
        std::round(1000 * (kModulusHi_MPa - kModulusLo_MPa) / std::sqrt(12.0) / kTreadModulus_MPa) /
        10;
    y << "  # Its spread: Shore A 60-70 by Gent's relation, 3.7-5.6 MPa, as a uniform range.\n"
      << "  modulus_std_percent: " << num(pct) << "\n";
    decide("tread.modulus_std_percent", num(pct), "Shore A 60-70 (Gent) as a uniform range");
  }
  y << "  # "
    << (in.tread_depth_mm > 0 ? "Input" : "A new passenger tread's depth, 7.1-10.3 mm (NRC 2006)")
    << ".\n";
  y << "  thickness_mm: " << num(depth) << "\n";
  y << "  # "
    << (in.tread_width_mm > 0 ? "Input"
                              : "77 % of the section width (usual passenger proportion, assumed)")
    << ".\n";
  y << "  contact_width_mm: " << num(tread_w) << "\n";
  if (!in.tread_width_mm) {
    const double pct = std::round(1000 * (kTreadWidthShareHi - kTreadWidthShareLo) *
                                  size.section_width_mm / std::sqrt(12.0) / tread_w) /
                       10;
    y << "  # Its spread: the share's 0.70-0.85 across passenger sizes, as a uniform range.\n"
      << "  contact_width_std_percent: " << num(pct) << "\n";
    decide("tread.contact_width_std_percent", num(pct),
           "tread-width share 0.70-0.85 as a uniform range");
  }
  decide("tread.thickness_mm", num(depth),
         in.tread_depth_mm > 0 ? "input" : "new passenger tread (NRC 2006)");
  decide("tread.contact_width_mm", num(tread_w),
         in.tread_width_mm > 0 ? "input" : "0.77 x section width (assumed)");

  const double window =
      std::min(std::round(kWindowPerRadius * R0_mm), std::floor(0.95 * M_PI * R0_mm));
  // The mesh (numerical): the 3D default's 1 mm sections and 5 mm columns (converged: halving
  // moves the static footprint of this tyre by < 0.01 %, its free vibration and rolling by
  // < 0.8 %; docs/footprint.md section 10); the 2D patch keeps 0.5 mm (its rolling resistance
  // moves by 1 % from 1 to 0.5 mm, docs/transient.md section 1).
  y << "contact:\n  unit_length_mm: " << (in.two_d ? "0.5" : "1")
    << "\n  window_mm: " << num(window) << "\n";
  std::vector<double> loads;
  for (double s : {0.5, 0.75, 1.0, 1.25, 1.5}) loads.push_back(std::round(s * fnomin));
  y << "# 0.5-1.5 x FNOMIN " << num(fnomin) << " N ("
    << (in.fnomin_N > 0 ? "input" : "MF-Tool's passenger default") << ").\n";
  y << "loads_N: " << list(loads) << "\n";
  if (!in.two_d) {
    y << "footprint_3d:\n  tread_width_mm: " << num(tread_w) << "\n  lateral_cell_mm: 5\n";
    y << "  # No section drawing: the tread face is taken flat across the tread width (multi-arc\n"
      << "  # passenger profiles are 'very flat' near the centre); state the measured contour\n"
      << "  # (crown: shape: contour) or radius when you have it.\n";
    const double round_mm = std::round(kRoundCrown_mm * tread_w / kRoundCrownTread_mm);
    y << "  # The flat face is an assumption: the bands span crowns from flat to a circle of\n"
      << "  # this radius (the SF-350's, calibrated on its measured widths: 1058 mm on a 150 mm\n"
      << "  # tread, scaled with the tread width; docs/uncertainty.md section 2).\n";
    y << "  crown:\n    shape: flat\n    round_limit_radius_mm: " << num(round_mm) << "\n";
    decide("footprint_3d.crown.shape", "flat", "no section drawing (stated)");
    decide("footprint_3d.crown.round_limit_radius_mm", num(round_mm),
           "the SF-350's calibrated crown (1058 mm on 150 mm) scaled with the tread width");
  }
  // The time-domain scenarios at FNOMIN (modaltyre transient, docs/transient.md), with the
  // bundled configs' conditions; the output grid chosen per scenario (transient/output_grid.h).
  const std::string F = num(fnomin), F125 = num(std::round(1.25 * fnomin));
  y << "transient:\n"
    << "  # Stated: the hub carries tyre + rim + fixture, 20 kg (the bundled configs' value); the\n"
    << "  # scenarios at FNOMIN; the output grid resolves the hub bounce and a cleat (auto).\n"
    << "  hub_mass_kg: 20\n  output_step_ms: auto\n"
    << "  load_hold: {load_N: " << F << ", ramp_rate_N_s: " << F << ", hold_s: 120}\n"
    << "  free_vibration: {load_N: " << F << ", initial_load_N: " << F125 << ", duration_s: 1.0}\n"
    << "  rolling: {load_N: " << F << ", speed_km_h: 60, ramp_s: 1.0, duration_s: 3.0}\n"
    << "  cleat: {load_N: " << F
    << ", speed_km_h: 30, height_mm: 10, length_mm: 20, ramp_s: 0.5}\n";
  decide("transient.hub_mass_kg", "20", "tyre + rim + fixture (stated, the bundled configs')");
  r.yaml = y.str();

  // ---- build once: what is written runs ----------------------------------------------------
  // Read as if at the output (a hammer path is relative to it); a key the reader refuses there
  // is named by the option that set it, not by a file not yet written.
  const std::string origin = in.output_path.empty() ? std::string("init") : in.output_path;
  contact::TyreConfig config;
  try {
    config = contact::read_tyre_config(ConfigTree::from_string(r.yaml, origin));
  } catch (const InputError& e) {
    if (e.where().file == origin) rethrow_at_option(e);
    throw;
  }
  if (!list_given) config.hammer_csv = std::filesystem::absolute(in.hammer_csv).string();
  const contact::TyreModel model = contact::build_tyre_model(config);
  check_ring_mass(model.carcass.mass_per_length_kg_m, config.outer_radius_m, list_given);
  r.carcass = model.carcass;
  r.warnings.insert(r.warnings.end(), model.basis.warnings.begin(), model.basis.warnings.end());
  if (in.boundary == "free" && !(in.belt_mass_kg > 0)) {
    // The ring's mu is the mass that makes its frequencies and statics agree, not the belt's
    // weighed mass; the two-mass correction of a free test's order 1 wants the latter.
    const double ring_kg = 2 * M_PI * R0_mm * 1e-3 * model.carcass.mass_per_length_kg_m;
    r.warnings.push_back(
        "a free test without --belt-mass-kg: the order-1 correction takes the ring's mass 2 pi R "
        "mu = " +
        num(std::round(ring_kg * 10) / 10) + " kg as the belt's, " +
        (ring_kg < kTnoBeltMass_kg ? "lighter" : "heavier") +
        " than a passenger belt with its tread (the TNO 205/60R15 file's "
        "BELT_MASS: 7.7 kg); state the "
        "maker's BELT_MASS (docs/validation.md: +21 % stiffness on the held-out 205/60R15 without "
        "it)");
  }
  if (!list_given) {
    for (const auto& m : contact::config_modes(config).modes) {
      if (m.kind == modal::ModeKind::rotation)
        r.orders.push_back(-1);
      else
        r.orders.push_back(m.order());
    }
  }
  return r;
}

}  // namespace modaltyre::init
