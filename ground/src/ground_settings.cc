#include "modaltyre/ground/ground_settings.h"

#include <stdexcept>

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

}  // namespace

GroundSettings read_ground_settings(const ConfigSection& s, const ConfigTree& tree) {
  GroundSettings g;
  const std::string model =
      s.choice("model", "rigid", {"rigid", "profile", "kelvin_voigt", "bekker"});
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
    const ConfigSection u = b.section("unloading");
    WongUnloading w;
    w.k0_kN_m3 = u.number("k0", 0, 0, 1e12);
    w.Au_kN_m4 = u.number("Au", 0, 0, 1e15);
    if (!(w.k0_kN_m3 + w.Au_kN_m4 > 0))
      u.fail("Au", "k0 and Au cannot both be 0 (leave out unloading: for a rigid-plastic soil)");
    g.bekker.unloading = w;
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
