#include "modaltyre/fmu/soil_parameters.h"

namespace modaltyre::fmu {
namespace {

using G = ground::GroundSettings;

// One accessor pair per key (captureless lambdas as function pointers).
#define MODALTYRE_SOIL_FIELD(expr) \
  [](const G& g) -> double { return g.expr; }, [](G& g, double v) { g.expr = v; }

/// The Janosi-Hanamoto keys of a soil model's section (ground/shear.h), held in member S.
template <ground::JanosiParams G::*S>
void shear_keys(std::vector<SoilParameter>& p, const std::string& section) {
  const std::string s = "ground." + section + ".";
  p.push_back({s + "cohesion_kPa", "kPa", 0, 1e5, false, "soil cohesion c (Janosi-Hanamoto)",
               [](const G& g) -> double { return (g.*S).cohesion_kPa; },
               [](G& g, double v) { (g.*S).cohesion_kPa = v; }});
  p.push_back({s + "friction_angle_deg", "deg", 0, 89, false,
               "soil internal friction angle phi (Janosi-Hanamoto)",
               [](const G& g) -> double { return (g.*S).friction_angle_deg; },
               [](G& g, double v) { (g.*S).friction_angle_deg = v; }});
  p.push_back({s + "shear_modulus_K_mm", "mm", 0, 1e4, true,
               "shear deformation modulus K (Janosi-Hanamoto), > 0",
               [](const G& g) -> double { return (g.*S).shear_modulus_K_mm; },
               [](G& g, double v) { (g.*S).shear_modulus_K_mm = v; }});
}

}  // namespace

std::vector<SoilParameter> soil_parameters(const ground::GroundSettings& g, bool patch_3d) {
  std::vector<SoilParameter> p;
  if (g.model == ground::GroundModel::bekker) {
    p.push_back({"ground.bekker.n", "1", 0, 3, true, "Bekker's sinkage exponent n, (0, 3]",
                 MODALTYRE_SOIL_FIELD(bekker.n)});
    p.push_back({"ground.bekker.k_c", "kN/m^(n+1)", 0, 1e9, false,
                 "Bekker's cohesive modulus k_c (Wong's units)", MODALTYRE_SOIL_FIELD(bekker.k_c)});
    p.push_back({"ground.bekker.k_phi", "kN/m^(n+2)", 0, 1e12, false,
                 "Bekker's frictional modulus k_phi (Wong's units)",
                 MODALTYRE_SOIL_FIELD(bekker.k_phi)});
    shear_keys<&G::bekker_shear>(p, "bekker");
    if (g.bekker.unloading) {
      p.push_back({"ground.bekker.unloading.k0", "kN/m3", 0, 1e12, false,
                   "Wong's unloading stiffness k_u = k0 + Au z_max: k0",
                   [](const G& s) -> double { return s.bekker.unloading->k0_kN_m3; },
                   [](G& s, double v) { s.bekker.unloading->k0_kN_m3 = v; }});
      p.push_back({"ground.bekker.unloading.Au", "kN/m4", 0, 1e15, false,
                   "Wong's unloading stiffness k_u = k0 + Au z_max: Au",
                   [](const G& s) -> double { return s.bekker.unloading->Au_kN_m4; },
                   [](G& s, double v) { s.bekker.unloading->Au_kN_m4 = v; }});
    }
  } else if (g.model == ground::GroundModel::kelvin_voigt) {
    p.push_back({"ground.kelvin_voigt.E2_MPa", "MPa", 0, 1e6, true,
                 "deformation modulus E2 (seed 000 eq. 23), > 0",
                 MODALTYRE_SOIL_FIELD(kelvin_voigt.E2_MPa)});
    if (!patch_3d)
      p.push_back({"ground.kelvin_voigt.eta2_kPa_s", "kPa.s", 0, 1e9, false,
                   "viscosity factor eta2 (seed 000 eq. 23)",
                   MODALTYRE_SOIL_FIELD(kelvin_voigt.eta2_kPa_s)});
    p.push_back({"ground.kelvin_voigt.layer_mm", "mm", 0, 1e5, true,
                 "depth H of the deforming layer, > 0",
                 MODALTYRE_SOIL_FIELD(kelvin_voigt.layer_mm)});
    p.push_back({"ground.kelvin_voigt.elastic_share", "1", 0, 1, true,
                 "elastic share k_E (seed 000 eq. 24), (0, 1]",
                 MODALTYRE_SOIL_FIELD(kelvin_voigt.elastic_share)});
    shear_keys<&G::kelvin_voigt_shear>(p, "kelvin_voigt");
  }
  return p;
}

std::string soil_combination_problem(const ground::GroundSettings& g) {
  if (g.model == ground::GroundModel::bekker) {
    if (!(g.bekker.k_c + g.bekker.k_phi > 0))
      return "ground.bekker.k_c and ground.bekker.k_phi cannot both be 0";
    if (g.bekker.unloading && !(g.bekker.unloading->k0_kN_m3 + g.bekker.unloading->Au_kN_m4 > 0))
      return "ground.bekker.unloading.k0 and ground.bekker.unloading.Au cannot both be 0";
  }
  return "";
}

}  // namespace modaltyre::fmu
