#include "modaltyre/contact/tyre_config.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/modal/hammer_data.h"

namespace modaltyre::contact {

namespace {

/// A fitted tyre scalar SECTION.KEY, checked against the range the parameter specification
/// (parameter_spec.h) declares for it.
double scalar(const ConfigSection& s, const std::string& section, const std::string& key,
              double fallback) {
  const ValueRange& r = accepted_range(section + "." + key);
  return s.number(key, fallback, r.min, r.max);
}

/// A value that is 0 (the feature off) or inside the physical range [min, max]; anything else
/// is an InputError naming the key and both choices (`what_zero_or` says what they mean).
double zero_or_number(const ConfigSection& s, const std::string& key, double fallback, double min,
                      double max, const std::string& what_zero_or) {
  const double v = s.number(key, fallback, 0, max);
  if (v != 0 && v < min) {
    std::ostringstream msg;
    msg << "value " << v << " is out of range: " << what_zero_or << " in [" << min << ", " << max
        << "]";
    s.fail(key, msg.str());
  }
  return v;
}

/// The section `transient:` (transient/transient.h). The lower bounds are physical: below them
/// a run failed (exit 1) or stepped without end instead of describing a tyre.
TransientSettings read_transient_settings(const ConfigSection& tr, double unit_length_m) {
  TransientSettings T;
  // Hub = wheel (rim + tyre) + fixture: no wheel with a pneumatic tyre weighs under 0.1 kg (a
  // 12-inch bicycle wheel ~0.5 kg); 1e-308 kg made the hub bounce sqrt(k / m) unbounded.
  T.hub_mass_kg = tr.number("hub_mass_kg", T.hub_mass_kg, 0.1, 1e5);
  T.dynamic_max_order =
      static_cast<int>(tr.integer("dynamic_max_order", T.dynamic_max_order, 0, 2000));
  T.relaxation = tr.boolean("relaxation", T.relaxation);
  // Loss factors are measured at 0.01-100 Hz and road excitation reaches kHz; above 1e4 Hz the
  // tread's time constant tan(delta) / (2 pi Omega) falls under 1e-7 s, stiffer than the
  // integrator resolves (1e6 Hz: exit 1).
  T.tread_reference_frequency_hz =
      tr.number("tread_reference_frequency_hz", T.tread_reference_frequency_hz, 1e-3, 1e4);
  T.instantaneous_stiffness_ratio =
      tr.number("instantaneous_stiffness_ratio", T.instantaneous_stiffness_ratio, 1.01, 1e6);
  T.modal_damping_scale = tr.number("modal_damping_scale", T.modal_damping_scale, 0, 100);
  // `auto` (or absent): the run chooses the grid (transient/output_grid.h).
  if (tr.has("output_step_ms") && tr.text("output_step_ms", "") == "auto") {
    T.output_step_s = 0;
  } else {
    T.output_step_s = tr.number("output_step_ms", T.output_step_s * 1e3, 1e-3, 1e6) * 1e-3;
  }
  T.relative_tolerance = tr.number("relative_tolerance", T.relative_tolerance, 1e-12, 1e-2);
  T.tread_tolerance_m =
      tr.number("tread_tolerance_um", T.tread_tolerance_m * 1e6, 1e-6, 100) * 1e-6;
  // 1e-308 N made the load-hold ramp end at a denormal time that CVODE refused (exit 1).
  const auto load = [](const ConfigSection& s, const char* key, double fallback) {
    return s.number(key, fallback, kMinTransientLoad_N, kMaxLoad_N);
  };
  // A speed ramp is 0 (a step from rest) or at least one output step: a shorter one is not
  // seen in the output and its acceleration 1.5 V / ramp_s is unbounded (1e-308 s: exit 1).
  const double ramp_min_s =
      T.output_step_s > 0 ? T.output_step_s : TransientSettings::kAutoOutputStepCap_s;
  const auto ramp = [ramp_min_s](const ConfigSection& s, double fallback) {
    return zero_or_number(
        s, "ramp_s", fallback, ramp_min_s, 1e6,
        "0 (a speed step) or at least one output step (transient.output_step_ms)");
  };
  const ConfigSection lh = tr.section("load_hold");
  T.load_hold.load_N = load(lh, "load_N", T.load_hold.load_N);
  T.load_hold.ramp_rate_N_s = lh.positive("ramp_rate_N_s", T.load_hold.ramp_rate_N_s, 1e12);
  T.load_hold.hold_s = lh.number("hold_s", T.load_hold.hold_s, 0, 1e6);
  const ConfigSection fv = tr.section("free_vibration");
  T.free_vibration.load_N = load(fv, "load_N", T.free_vibration.load_N);
  T.free_vibration.initial_load_N = load(fv, "initial_load_N", T.free_vibration.initial_load_N);
  T.free_vibration.duration_s = fv.positive("duration_s", T.free_vibration.duration_s, 1e6);
  const ConfigSection ro = tr.section("rolling");
  T.rolling.load_N = load(ro, "load_N", T.rolling.load_N);
  T.rolling.speed_m_s = ro.number("speed_km_h", T.rolling.speed_m_s * 3.6, 0, 1000) / 3.6;
  T.rolling.ramp_s = ramp(ro, T.rolling.ramp_s);
  T.rolling.duration_s = ro.positive("duration_s", T.rolling.duration_s, 1e6);
  if (T.rolling.duration_s < T.rolling.ramp_s) {
    ro.fail("duration_s", "must be at least ramp_s (the speed ramp is part of the run)");
  }
  const ConfigSection cl = tr.section("cleat");
  T.cleat.load_N = load(cl, "load_N", T.cleat.load_N);
  T.cleat.speed_m_s = cl.positive("speed_km_h", T.cleat.speed_m_s * 3.6, 1000) / 3.6;
  T.cleat.height_m = cl.positive("height_mm", T.cleat.height_m * 1e3, 200) * 1e-3;
  // Each cosine edge (a quarter of the length) spans at least one candidate unit, or the road
  // falls between the units and the integrator's step limit L / (8 V) shrinks without end
  // (1e-3 mm ran for minutes).
  T.cleat.length_m =
      cl.number("length_mm", T.cleat.length_m * 1e3, 4 * unit_length_m * 1e3, 2000) * 1e-3;
  T.cleat.ramp_s = ramp(cl, T.cleat.ramp_s);
  T.cleat.width_m = cl.number("width_mm", T.cleat.width_m * 1e3, 0, 2000) * 1e-3;
  return T;
}

}  // namespace

TyreConfig read_tyre_config(const ConfigTree& tree) {
  TyreConfig c;
  c.source = tree.file();
  const ConfigSection root = tree.root();

  const ConfigSection tyre = root.section("tyre");
  c.name = tyre.text("name", c.name);
  c.outer_radius_m = scalar(tyre, "tyre", "outer_radius_mm", 294.8) * 1e-3;
  c.inflation_pressure_Pa = tyre.number("inflation_pressure_kPa", 230, 10, 2000) * 1e3;
  c.section_width_m = tyre.number("section_width_mm", 0, 0, 2000) * 1e-3;
  c.aspect_ratio = tyre.number("aspect_ratio", 0, 0, 2);
  c.rim_radius_m = tyre.number("rim_radius_mm", 0, 0, 2000) * 1e-3;
  c.rigid = tyre.boolean("rigid", false);
  if (c.rim_radius_m >= c.outer_radius_m) {
    tyre.fail("rim_radius_mm", "the rim radius must be smaller than outer_radius_mm");
  }

  const ConfigSection modal = root.section("modal");
  c.carcass = read_carcass_settings(modal);
  c.uncertainty.frequency_rel_std = modal.number("frequency_std_percent", 0, 0, 50) / 100;
  c.uncertainty.belt_width_rel_std = modal.number("belt_width_std_percent", 0, 0, 50) / 100;
  if (!c.carcass.frequency_list()) {
    if (!modal.has("hammer_csv")) {
      modal.fail("hammer_csv",
                 "required: path of the hammer data CSV (or a frequency list: "
                 "modal.frequencies_hz with orders; `modaltyre init` writes one)");
    }
    c.hammer_csv = tree.resolve_path(modal.text("hammer_csv", "")).string();
  }
  c.extend_orders = modal.boolean("extend_orders", true);
  c.compliance_scale = scalar(modal, "modal", "compliance_scale", 1.0);
  c.mesh.max_order = static_cast<int>(modal.integer("max_order", 0, 0, 100000));
  if (modal.has("extension_bending_s2_rad2_s2")) {
    c.extension_s2 = scalar(modal, "modal", "extension_bending_s2_rad2_s2", 0);
  }
  c.pneumatic_share = scalar(modal, "modal", "pneumatic_share", 0);

  const ConfigSection tread = root.section("tread");
  c.tread.modulus_Pa = scalar(tread, "tread", "modulus_MPa", 6.0) * 1e6;
  // 0 = an elastic tread; a rubber compound's loss factor is 0.02-0.3 at 1-100 Hz, so 0.01 is
  // below any tread (1e-6 made the transient's Kelvin-Voigt time constant tan(delta) / Omega so
  // short that CVODE failed, exit 1).
  c.tread.tan_delta = zero_or_number(tread, "tan_delta", c.tread.tan_delta, 0.01, 5,
                                     "0 (an elastic tread) or a rubber's loss factor");
  c.tread.thickness_m = scalar(tread, "tread", "thickness_mm", 8) * 1e-3;
  c.tread.width_m = scalar(tread, "tread", "contact_width_mm", 140) * 1e-3;
  c.tread.poisson = tread.number("poisson_ratio", c.tread.poisson, 0.0, 0.5);
  c.uncertainty.tread_modulus_rel_std = tread.number("modulus_std_percent", 0, 0, 50) / 100;
  c.uncertainty.tread_width_rel_std = tread.number("contact_width_std_percent", 0, 0, 50) / 100;

  const ConfigSection mesh = root.section("contact");
  c.mesh.unit_length_m = mesh.number("unit_length_mm", 0.5, 0.01, 50) * 1e-3;
  c.mesh.window_m = mesh.number("window_mm", 360, 5, 3000) * 1e-3;
  if (c.mesh.window_m > M_PI * c.outer_radius_m) {
    mesh.fail("window_mm", "candidate window longer than half the circumference");
  }
  const double units = c.mesh.window_m / c.mesh.unit_length_m;
  if (units > 20000) {
    mesh.fail("unit_length_mm", "window / unit length = " + std::to_string(long(units)) +
                                    " candidate units; at most 20000 are supported");
  }

  const ConfigSection solver = root.section("solver");
  c.solver.max_iterations = static_cast<int>(solver.integer("max_iterations", 200, 1, 100000));
  c.solver.gap_tolerance = solver.number("gap_tolerance", 1e-10, 1e-15, 1e-2);

  c.loads_N = root.numbers("loads_N", {2131, 3261, 5478, 6502, 7322, 8321}, kMinLoad_N, kMaxLoad_N);
  for (double f : c.loads_N) {
    if (!(f > 0)) root.fail("loads_N", "every load must be greater than 0 N");
  }
  c.horizontal_force_N = root.number("horizontal_force_N", 0, -1e7, 1e7);

  const ConfigSection val = root.section("validation");
  c.validation.calibrate = val.texts("calibrate", {});
  c.validation.calibration_rows = [&] {
    std::vector<int> rows;
    for (long r : val.integers("calibration_rows", {}, 1, 100000)) rows.push_back(int(r));
    return rows;
  }();
  c.validation.observables = val.texts("calibration_observables", c.validation.observables);
  if (c.validation.calibrate.size() > 3) {
    val.fail("calibrate", "at most three parameters may be calibrated");
  }
  if (c.validation.calibration_rows.size() > 2) {
    val.fail("calibration_rows", "at most two rows may be used for calibration");
  }
  if (!c.validation.calibrate.empty() && c.validation.calibration_rows.empty()) {
    val.fail("calibration_rows", "calibrated parameters need calibration rows");
  }
  for (const auto& o : c.validation.observables) {
    if (o != "sinking_mm" && o != "length_mm" && o != "width_mm") {
      val.fail("calibration_observables",
               "'" + o + "' is not one of: sinking_mm, length_mm, width_mm");
    }
  }
  c.transient = read_transient_settings(root.section("transient"), c.mesh.unit_length_m);
  c.effects = read_effects(root.section("effects"));
  if (root.has("footprint_3d")) {
    c.footprint_3d = read_patch3d_settings(root.section("footprint_3d"));
    // What the 3D patch does not model is refused, not ignored.
    for (const auto& e : effect_catalogue()) {
      if (!e.is_option() && c.effects.enabled(e.id) && !e.refused_with_3d.empty()) {
        root.section("effects").section(e.name).fail(
            "enabled", "cannot be combined with footprint_3d: " + e.refused_with_3d);
      }
    }
    if (c.horizontal_force_N != 0) {
      root.fail("horizontal_force_N",
                "the 3D patch (footprint_3d) takes no horizontal force; use a 2D config");
    }
  }
  if (root.has("ground")) {
    const ConfigSection g = root.section("ground");
    c.ground = ground::read_ground_settings(g, tree);
    const std::string refusal = ground_refusal(c);
    if (!refusal.empty()) g.fail("model", refusal);
  }
  if (c.rigid && !c.ground.soil())
    tyre.fail("rigid",
              "a rigid tyre (the terramechanics reference wheel) needs a soil: "
              "ground.model bekker or kelvin_voigt (on a road it would not deflect)");
  tree.reject_unknown_keys();
  // Named at the config's line (the hammer reader alone could only name the path), after every
  // key is read so that a bad key is reported first.
  if (c.carcass.frequency_list()) return c;
  std::error_code ec;
  const auto hammer_type = std::filesystem::status(c.hammer_csv, ec).type();
  if (hammer_type == std::filesystem::file_type::not_found) {
    modal.fail("hammer_csv", "'" + c.hammer_csv +
                                 "' not found (a relative path is taken from the config's folder)");
  }
  if (hammer_type != std::filesystem::file_type::regular) {
    modal.fail("hammer_csv", "'" + c.hammer_csv + "' is not a regular file (a folder or device?)");
  }
  // Shapes without a mass normalisation (`ema --unscaled`, column scaling = unscaled) have an
  // arbitrary scale: only the ring's tension can give their modes a mass (docs/ring_model.md).
  if (modal::read_hammer_csv(c.hammer_csv).unscaled) {
    if (modal.has("normalisation") && c.carcass.normalisation == ModalNormalisation::shapes) {
      modal.fail("normalisation",
                 "'" + c.hammer_csv +
                     "' holds unscaled shapes (scaling = unscaled): their scale is arbitrary, "
                     "so 'shapes' cannot give the modal masses; use 'ring'");
    }
    c.carcass.normalisation = ModalNormalisation::ring;
    if (!(c.carcass.mass_per_length_kg_m > 0) && !(c.carcass.belt_width_m > 0)) {
      modal.fail("hammer_csv", "'" + c.hammer_csv +
                                   "' holds unscaled shapes (scaling = unscaled): the ring's "
                                   "normalisation gives them a mass; state modal.belt_width_mm "
                                   "(the hoop tension T = p b R fixes it) or "
                                   "modal.mass_per_length_kg_m");
    }
  }
  return c;
}

std::string ground_refusal(const TyreConfig& c) {
  if (c.ground.model == ground::GroundModel::rigid) return "";
  // What the ground path does not model is refused, not ignored (docs/soil.md section 4).
  if (c.footprint_3d && !c.ground.soil())
    return "the 3D patch (footprint_3d) on a road profile is not built yet: use a 2D config";
  if (c.footprint_3d && c.footprint_3d->lateral_belt.enabled)
    return "the 3D patch's lateral belt (footprint_3d.lateral_belt) is not combined with a soil "
           "yet";
  if (c.effects.soil_compliance.enabled)
    return "the soil_compliance effect is a soil of its own: use ground.model: kelvin_voigt "
           "instead of both";
  if (c.effects.rolling_speed.enabled)
    return "the rolling_speed effect is not combined with a ground other than the flat rigid "
           "road";
  if (c.horizontal_force_N != 0)
    return "a ground other than the flat rigid road takes no horizontal_force_N (`traction` "
           "computes the tangential forces)";
  return "";
}

OperatingConditions TyreConfig::default_conditions(double load_N) const {
  OperatingConditions oc;
  oc.load_N = load_N;
  oc.horizontal_force_N = horizontal_force_N;
  oc.pressure_kPa = inflation_pressure_Pa * 1e-3;
  return oc;
}

TyreConfig load_tyre_config(const std::string& path, const std::vector<std::string>& overrides) {
  return read_tyre_config(ConfigTree::load(path, overrides));
}

}  // namespace modaltyre::contact
