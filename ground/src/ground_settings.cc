#include "modaltyre/ground/ground_settings.h"

#include <stdexcept>
#include <vector>

#include "modaltyre/core/errors.h"
#include "modaltyre/ground/slip_sinkage.h"

namespace modaltyre::ground {

const char* to_string(GroundModel model) {
  switch (model) {
    case GroundModel::rigid:
      return "rigid";
    case GroundModel::profile:
      return "profile";
    case GroundModel::kelvin_voigt:
      return "kelvin_voigt";
    case GroundModel::bekker:
      return "bekker";
  }
  return "?";
}

std::unique_ptr<PressureSinkage> GroundSettings::normal_law(double b_m, double slip) const {
  if (model == GroundModel::bekker) {
    auto law = std::make_unique<BekkerWong>(bekker, b_m);
    const double f = slip_sinkage.factor(slip);
    if (f == 1.0) return law;
    slip_sinkage.validate();
    return std::make_unique<SlipSinkageLaw>(std::move(law), f);
  }
  if (model == GroundModel::kelvin_voigt) return std::make_unique<KelvinVoigtSoil>(kelvin_voigt);
  throw std::invalid_argument(std::string("ground model '") + to_string(model) +
                              "' is a rigid road, not a soil");
}

const JanosiParams& GroundSettings::soil_shear() const {
  if (model == GroundModel::bekker) return bekker_shear;
  if (model == GroundModel::kelvin_voigt) return kelvin_voigt_shear;
  throw std::invalid_argument(std::string("ground model '") + to_string(model) +
                              "' is a rigid road, not a soil");
}

std::unique_ptr<ShearLaw> GroundSettings::shear_law(double stick_stiffness_Pa_m) const {
  if (soil()) return std::make_unique<JanosiHanamoto>(soil_shear());
  return std::make_unique<CoulombFriction>(friction_coefficient, stick_stiffness_Pa_m);
}

namespace {

JanosiParams read_shear(const ConfigSection& s, const JanosiParams& fallback) {
  JanosiParams p;
  p.cohesion_kPa = s.number("cohesion_kPa", fallback.cohesion_kPa, 0, 1e5);
  p.friction_angle_deg = s.number("friction_angle_deg", fallback.friction_angle_deg, 0, 89);
  p.shear_modulus_K_mm = s.positive("shear_modulus_K_mm", fallback.shear_modulus_K_mm, 1e4);
  return p;
}

// A soil's keys must not be dropped in silence (issue 44): a block of another model than the one
// stated, or soil keys without a model (which would leave the rigid road), are refused; a soil
// model needs its normal law's keys stated (no default stands in for a soil).
void check_blocks(const ConfigSection& s, const std::string& model) {
  const bool stated = s.has("model");
  for (const char* block : {"bekker", "kelvin_voigt"}) {
    if (!s.has(block)) continue;
    // Named at the block's first key present (its --set when it came from the command line).
    const ConfigSection keys = s.section(block);
    std::string at;
    for (const char* k : {"n", "k_c", "k_phi", "E2_MPa", "eta2_kPa_s", "layer_mm", "elastic_share",
                          "cohesion_kPa", "friction_angle_deg", "shear_modulus_K_mm", "unloading",
                          "wong_reece", "slip_sinkage", "bulldozing", "uncertainty"})
      if (at.empty() && keys.has(k)) at = k;
    auto fail = [&](const std::string& why) {
      if (at.empty()) s.fail(block, why);
      keys.fail(at, why);
    };
    if (!stated)
      fail(std::string("a soil's keys (ground.") + block +
           ") without ground.model: state `model: " + block +
           "` (without it the ground is the rigid road and these keys would be dropped)");
    if (model != block)
      fail(std::string("ground.") + block + " is given but ground.model is " + model +
           ": its keys would be dropped (remove the block, or set model: " + block + ")");
  }
}

void require(const ConfigSection& section, const std::vector<const char*>& keys,
             const std::string& model) {
  for (const char* k : keys)
    if (!section.has(k))
      section.fail(k, "required with model: " + model +
                          " (no default stands in for a soil's law; configs/soils/ gives "
                          "published values)");
}

// ground.bekker.uncertainty: each key a standard deviation, bounded so that a 1-sigma change
// keeps the parameter physical; a percentage of a zero parameter is refused (it would be no
// scatter at all, dropped in silence).
SoilScatter read_scatter(const ConfigSection& b, const BekkerParams& p, const JanosiParams& shear) {
  const ConfigSection u = b.section("uncertainty");
  SoilScatter sc;
  auto percent = [&](const char* key, double value, const char* of) {
    const double pct = u.number(key, 0, 0, 50);
    if (pct > 0 && !(value > 0))
      u.fail(key, std::string("a percentage of ") + of + " = 0 is no scatter: state " + of +
                      " or leave the key out");
    return pct / 100;
  };
  sc.k_c_rel_std = percent("k_c_std_percent", p.k_c, "k_c");
  sc.k_phi_rel_std = percent("k_phi_std_percent", p.k_phi, "k_phi");
  sc.cohesion_rel_std = percent("cohesion_std_percent", shear.cohesion_kPa, "cohesion_kPa");
  sc.shear_modulus_rel_std =
      percent("shear_modulus_K_std_percent", shear.shear_modulus_K_mm, "shear_modulus_K_mm");
  sc.n_std = u.number("n_std", 0, 0, 1);
  if (sc.n_std > 0 && !(sc.n_std < 0.5 * p.n))
    u.fail("n_std", "must be below half of n (" + std::to_string(p.n) +
                        "): a 1-sigma change would take the exponent near 0");
  sc.friction_angle_std_deg = u.number("friction_angle_std_deg", 0, 0, 15);
  if (sc.friction_angle_std_deg > 0 &&
      !(sc.friction_angle_std_deg < 0.5 * shear.friction_angle_deg))
    u.fail("friction_angle_std_deg", "must be below half of friction_angle_deg (" +
                                         std::to_string(shear.friction_angle_deg) + ")");
  if (!(shear.friction_angle_deg + sc.friction_angle_std_deg < 89))
    u.fail("friction_angle_std_deg", "friction_angle_deg + 1 sigma must stay below 89 degrees");
  return sc;
}

}  // namespace

GroundSettings read_ground_settings(const ConfigSection& s, const ConfigTree& tree) {
  GroundSettings g;
  const std::string model =
      s.choice("model", "rigid", {"rigid", "profile", "kelvin_voigt", "bekker"});
  check_blocks(s, model);
  if (model == "bekker") require(s.section("bekker"), {"n", "k_c", "k_phi"}, model);
  if (model == "kelvin_voigt") require(s.section("kelvin_voigt"), {"E2_MPa", "layer_mm"}, model);
  g.model = model == "profile"        ? GroundModel::profile
            : model == "kelvin_voigt" ? GroundModel::kelvin_voigt
            : model == "bekker"       ? GroundModel::bekker
                                      : GroundModel::rigid;
  g.name = s.text("name", "");
  g.source = s.text("source", "");
  g.friction_coefficient = s.number("friction_coefficient", 0.8, 0, 10);
  if (s.has("profile_csv")) g.profile_csv = tree.resolve_path(s.text("profile_csv", "")).string();
  if (g.model == GroundModel::profile) {
    if (g.profile_csv.empty())
      s.fail("profile_csv", "required with model: profile (a CSV x_m,height_m)");
    g.profile = std::make_shared<const RoadProfile>(read_road_profile_csv(g.profile_csv));
  }

  const ConfigSection b = s.section("bekker");
  g.bekker.n = b.positive("n", g.bekker.n, 3);
  g.bekker.k_c = b.number("k_c", g.bekker.k_c, 0, 1e9);
  g.bekker.k_phi = b.number("k_phi", g.bekker.k_phi, 0, 1e12);
  if (!(g.bekker.k_c + g.bekker.k_phi > 0)) b.fail("k_phi", "k_c and k_phi cannot both be 0");
  g.bekker_shear = read_shear(b, g.bekker_shear);
  if (b.has("unloading")) {
    // Wong's elastic unloading, on when its block is given (enabled: false keeps the block's
    // values and the rigid-plastic soil: the switch of the discovery's soil_unloading).
    const ConfigSection u = b.section("unloading");
    const bool on = u.boolean("enabled", true);
    if (on && !u.has("k0") && !u.has("Au"))
      u.fail("Au", "Wong's unloading needs k0 and Au stated (identify bevameter's cycles)");
    WongUnloading w;
    w.k0_kN_m3 = u.number("k0", 0, 0, 1e12);
    w.Au_kN_m4 = u.number("Au", 0, 0, 1e15);
    if (!(w.k0_kN_m3 + w.Au_kN_m4 > 0))
      u.fail("Au", "k0 and Au cannot both be 0 (leave out unloading: for a rigid-plastic soil)");
    g.stated_unloading = w;
    if (on) g.bekker.unloading = w;
  }
  if (b.has("slip_sinkage")) {
    const ConfigSection w = b.section("slip_sinkage");
    SlipSinkage& ss = g.slip_sinkage;
    ss.enabled = w.boolean("enabled", ss.enabled);
    ss.k1 = w.number("k1", ss.k1, 0, 10);
    ss.k2 = w.number("k2", ss.k2, 0, 0.99);
  }
  if (b.has("bulldozing")) {
    const ConfigSection w = b.section("bulldozing");
    g.bulldozing.enabled = w.boolean("enabled", g.bulldozing.enabled);
    g.bulldozing.unit_weight_kN_m3 =
        w.positive("unit_weight_kN_m3", g.bulldozing.unit_weight_kN_m3, 30);
  }
  if (b.has("uncertainty")) g.bekker_scatter = read_scatter(b, g.bekker, g.bekker_shear);
  if (b.has("wong_reece")) {
    const ConfigSection w = b.section("wong_reece");
    WongReeceStress& wr = g.wong_reece;
    wr.enabled = w.boolean("enabled", wr.enabled);
    wr.c1 = w.number("c1", wr.c1, 0, 1);
    wr.c2 = w.number("c2", wr.c2, 0, 1);
    wr.c3 = w.number("c3", wr.c3, 0, 0.99);
  }

  const ConfigSection kv = s.section("kelvin_voigt");
  g.kelvin_voigt.E2_MPa = kv.positive("E2_MPa", g.kelvin_voigt.E2_MPa, 1e6);
  g.kelvin_voigt.eta2_kPa_s = kv.number("eta2_kPa_s", g.kelvin_voigt.eta2_kPa_s, 0, 1e9);
  g.kelvin_voigt.layer_mm = kv.positive("layer_mm", g.kelvin_voigt.layer_mm, 1e5);
  g.kelvin_voigt.elastic_share = kv.positive("elastic_share", g.kelvin_voigt.elastic_share, 1);
  g.kelvin_voigt_shear = read_shear(kv, g.kelvin_voigt_shear);
  const ConfigSection& own = g.model == GroundModel::kelvin_voigt ? kv : b;
  g.shear_stated =
      own.has("cohesion_kPa") && own.has("friction_angle_deg") && own.has("shear_modulus_K_mm");
  return g;
}

GroundSettings load_ground_file(const std::string& path,
                                const std::vector<std::string>& overrides) {
  const ConfigTree tree = ConfigTree::load(path, overrides);
  const ConfigSection root = tree.root();
  if (!root.has("ground"))
    throw InputError({path, 0, "ground"},
                     "a soil file has a top-level 'ground:' section (configs/soils/)");
  GroundSettings g = read_ground_settings(root.section("ground"), tree);
  tree.reject_unknown_keys();
  return g;
}

}  // namespace modaltyre::ground
