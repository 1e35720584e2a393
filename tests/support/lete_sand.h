#pragma once
// The LETE sand of configs/soils/lete_sand.yaml as configuration overrides (Wong, Theory of Ground
// Vehicles, Table 2.3), and override lists put together: shared by the contact and transient
// tests.
#include <string>
#include <vector>

namespace modaltyre_test {

/// `a` followed by `b`.
inline std::vector<std::string> plus(std::vector<std::string> a,
                                     const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// Its pressure-sinkage law: Bekker's n, k_c, k_phi.
inline const std::vector<std::string> kLeteBekker = {"ground.model=bekker", "ground.bekker.n=0.79",
                                                     "ground.bekker.k_c=102",
                                                     "ground.bekker.k_phi=5301"};
/// The law and the soil's shear strength: cohesion, friction angle, shear modulus K.
inline const std::vector<std::string> kLeteBekkerShear =
    plus(kLeteBekker, {"ground.bekker.cohesion_kPa=1.3", "ground.bekker.friction_angle_deg=31.1",
                       "ground.bekker.shear_modulus_K_mm=12"});

}  // namespace modaltyre_test
