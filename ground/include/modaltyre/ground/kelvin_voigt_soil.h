#pragma once
// Seed 000's Kelvin-Voigt soil (eq. 23-28) as a ground model: a layer of depth H whose
// elementary volumes obey sigma2 = E2 eps2 + eta2 deps2/dt (eq. 23), eps2 = z / H.
//
// Of the total (plastic) sinkage h_G only the share k_E = h_E / h_G (eq. 24) is elastic: on
// loading the Kelvin-Voigt element carries the elastic share (seed 000's reduced parameters
// k_E E2, k_E eta2, docs/rheology.md section 5):
//   loading    p = k_E (E2 z + eta2 dz/dt) / H,
//   unloading  p = E2 (z - z_p) / H,   z_p = (1 - k_E) z_max  (the permanent sinkage, the rut).
// Both branches meet at z_max (p = k_E E2 z_max / H), so the law is continuous; the seed's
// unloading strain refers to the compacted layer A_c = H - z_p, which differs from H by the
// rut depth over the layer depth (< 1 % for sinkages below H/100) and would make the reloading
// branch overshoot the virgin one; H is used on both branches here (docs/soil.md section 1.3).
// k_E = 1 is the elastic Winkler soil of the soil_compliance effect: z = p H / E2.
// The static laws below leave out the rate term (dz/dt = 0); viscous_Pa gives it at a rate,
//   loading  k_E eta2 dz/dt / H,   below z_max  eta2 dz/dt / H,
// which the rigid wheel's steady rolling adds at dz/dt = V tan(theta) (rigid_wheel.h, docs/soil.md
// section 3.2); the 2D transient integrates it in time (transient/soil_contact.h, section 8.4).
#include "modaltyre/ground/pressure_sinkage.h"

namespace modaltyre::ground {

struct KelvinVoigtParams {
  double E2_MPa = 2;         ///< deformation modulus E2 [MPa], > 0
  double eta2_kPa_s = 0;     ///< viscosity factor eta2 [kPa s], >= 0
  double layer_mm = 200;     ///< depth H of the deforming layer [mm], > 0
  double elastic_share = 1;  ///< k_E = h_E / h_G (seed 000 eq. 24), (0, 1]
  void validate() const;     ///< std::invalid_argument naming the parameter
  double stiffness_Pa_m() const { return E2_MPa * 1e6 / (layer_mm * 1e-3); }  ///< E2 / H
};

class KelvinVoigtSoil final : public PressureSinkage {
 public:
  explicit KelvinVoigtSoil(const KelvinVoigtParams& params);
  double loading_Pa(double z_m) const override;
  double loading_sinkage_m(double p_Pa) const override;
  double unloading_Pa(double z_m, double z_max_m) const override;
  double unloading_sinkage_m(double p_Pa, double z_max_m) const override;
  double rebound_depth_m(double z_max_m) const override;
  bool rigid_plastic() const override { return false; }
  double work_J_m2(double p_Pa, double z_max_m) const override;
  double viscous_Pa(double dz_dt_m_s, bool virgin) const override;

 private:
  KelvinVoigtParams params_;
  double k_;  ///< E2 / H [Pa/m]
};

}  // namespace modaltyre::ground
