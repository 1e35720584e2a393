#pragma once
// Bekker's pressure-sinkage law with Wong's elastic unloading and reloading.
//
// Loading (Bekker 1956; Wong, Theory of Ground Vehicles, 4th ed., 2008, eq. 2.45):
//   p = (k_c / b + k_phi) z^n,
// b the smaller side of the loaded area (Bekker's convention), k_c in kN/m^(n+1), k_phi in
// kN/m^(n+2), z in m, p in kPa: the units of Wong's Table 2.3, kept in the parameters.
// Unloading and reloading (Wong, ibid., section 2.4.2, repetitive normal loading):
//   p = p_max - k_u (z_max - z),   k_u = k_0 + A_u z_max,
// k_0 in kN/m^3, A_u in kN/m^4; the rut after unloading is z_max - p_max / k_u. Where Wong's
// k_u falls below the secant p_max / z_max (small z_max with k_0 = 0) the secant is taken: the
// soil then rebounds to its undisturbed surface (rut 0) and never above it, where the line
// would otherwise lie above the virgin curve and return more work than loading took.
// Without the unloading block the soil is rigid-plastic: it does not rebound (the classic
// assumption of rolling-wheel analysis).
#include <optional>

#include "modaltyre/ground/pressure_sinkage.h"

namespace modaltyre::ground {

struct WongUnloading {
  double k0_kN_m3 = 0;  ///< k_0 >= 0 [kN/m^3]
  double Au_kN_m4 = 0;  ///< A_u >= 0 [kN/m^4]; k_0 + A_u > 0
};

struct BekkerParams {
  double n = 1;        ///< sinkage exponent, (0, 3]
  double k_c = 0;      ///< cohesive modulus [kN/m^(n+1)], >= 0
  double k_phi = 1e3;  ///< frictional modulus [kN/m^(n+2)], >= 0; k_c + k_phi > 0
  std::optional<WongUnloading> unloading;  ///< absent: rigid-plastic (no rebound)
  /// Throws std::invalid_argument naming the parameter.
  void validate() const;
  /// k_c / b + k_phi in SI: p[Pa] = modulus z[m]^n [Pa/m^n].
  double modulus_Pa(double b_m) const { return (k_c / b_m + k_phi) * 1e3; }
};

class BekkerWong final : public PressureSinkage {
 public:
  /// b_m: the smaller side of the contact (Bekker's b), > 0.
  BekkerWong(const BekkerParams& params, double b_m);
  double loading_Pa(double z_m) const override;
  double loading_sinkage_m(double p_Pa) const override;
  double unloading_Pa(double z_m, double z_max_m) const override;
  double unloading_sinkage_m(double p_Pa, double z_max_m) const override;
  double rebound_depth_m(double z_max_m) const override;
  bool rigid_plastic() const override { return !params_.unloading.has_value(); }
  double work_J_m2(double p_Pa, double z_max_m) const override;
  double compliance_m_per_Pa(double p_Pa, double z_max_m) const override;
  double virgin_sinkage_m(double p_Pa, double& dz_dp_m_per_Pa) const override;

  double b_m() const { return b_m_; }
  /// Wong's unloading stiffness k_u at z_max, at least the secant p_max / z_max [Pa/m] (0 when
  /// rigid-plastic).
  double unloading_stiffness_Pa_m(double z_max_m) const;

 private:
  BekkerParams params_;
  double b_m_;
  double k_;  ///< (k_c / b + k_phi) in Pa/m^n
};

}  // namespace modaltyre::ground
