#include "modaltyre/ground/kelvin_voigt_soil.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace modaltyre::ground {

void KelvinVoigtParams::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(E2_MPa > 0 && E2_MPa <= 1e6)) bad("kelvin_voigt.E2_MPa must be in (0, 1e6] MPa");
  if (!(eta2_kPa_s >= 0 && eta2_kPa_s <= 1e9)) bad("kelvin_voigt.eta2_kPa_s must be in [0, 1e9]");
  if (!(layer_mm > 0 && layer_mm <= 1e5)) bad("kelvin_voigt.layer_mm must be in (0, 1e5] mm");
  if (!(elastic_share > 0 && elastic_share <= 1))
    bad("kelvin_voigt.elastic_share must be in (0, 1] (k_E = h_E / h_G, seed 000 eq. 24)");
}

KelvinVoigtSoil::KelvinVoigtSoil(const KelvinVoigtParams& params)
    : params_(params), k_(params.stiffness_Pa_m()) {
  params_.validate();
}

double KelvinVoigtSoil::loading_Pa(double z_m) const {
  return z_m > 0 ? params_.elastic_share * k_ * z_m : 0.0;
}

double KelvinVoigtSoil::loading_sinkage_m(double p_Pa) const {
  return p_Pa > 0 ? p_Pa / (params_.elastic_share * k_) : 0.0;
}

double KelvinVoigtSoil::rebound_depth_m(double z_max_m) const {
  return (1 - params_.elastic_share) * std::max(z_max_m, 0.0);
}

double KelvinVoigtSoil::unloading_Pa(double z_m, double z_max_m) const {
  if (z_m >= z_max_m) return loading_Pa(z_m);
  return std::max(0.0, k_ * (z_m - rebound_depth_m(z_max_m)));
}

double KelvinVoigtSoil::work_J_m2(double p_Pa, double z_max_m) const {
  if (!(p_Pa > 0)) return 0.0;
  const double kl = params_.elastic_share * k_;  // the loading stiffness
  const double p_max = z_max_m > 0 ? loading_Pa(z_max_m) : 0.0;
  const double q = std::min(p_Pa, p_max);
  // Branch z = z_p + q / k up to p_max, then the virgin line z = q / k_l.
  double work = q > 0 ? rebound_depth_m(z_max_m) * q + q * q / (2 * k_) : 0.0;
  if (p_Pa > p_max) work += (p_Pa * p_Pa - p_max * p_max) / (2 * kl);
  return work;
}

// Seed 000 eq. (23) with the reduced parameters k_E eta2 on loading (docs/soil.md section 1.2).
double KelvinVoigtSoil::viscous_Pa(double dz_dt_m_s, bool virgin) const {
  const double eta2_Pa_s = params_.eta2_kPa_s * 1e3;
  return (virgin ? params_.elastic_share : 1.0) * eta2_Pa_s * dz_dt_m_s / (params_.layer_mm * 1e-3);
}

double KelvinVoigtSoil::unloading_sinkage_m(double p_Pa, double z_max_m) const {
  return std::min(z_max_m, rebound_depth_m(z_max_m) + std::max(p_Pa, 0.0) / k_);
}

}  // namespace modaltyre::ground
