#include "modaltyre/ground/bekker_wong.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace modaltyre::ground {

void BekkerParams::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(n > 0 && n <= 3)) bad("bekker.n must be in (0, 3]");
  if (!(k_c >= 0 && k_c <= 1e9)) bad("bekker.k_c must be in [0, 1e9] kN/m^(n+1)");
  if (!(k_phi >= 0 && k_phi <= 1e12)) bad("bekker.k_phi must be in [0, 1e12] kN/m^(n+2)");
  if (!(k_c + k_phi > 0)) bad("bekker.k_c and bekker.k_phi cannot both be 0");
  if (unloading) {
    if (!(unloading->k0_kN_m3 >= 0 && unloading->k0_kN_m3 <= 1e12))
      bad("bekker.unloading.k0 must be in [0, 1e12] kN/m^3");
    if (!(unloading->Au_kN_m4 >= 0 && unloading->Au_kN_m4 <= 1e15))
      bad("bekker.unloading.Au must be in [0, 1e15] kN/m^4");
    if (!(unloading->k0_kN_m3 + unloading->Au_kN_m4 > 0))
      bad("bekker.unloading: k0 and Au cannot both be 0 (the soil would not carry unloading)");
  }
}

BekkerWong::BekkerWong(const BekkerParams& params, double b_m) : params_(params), b_m_(b_m) {
  params_.validate();
  if (!(b_m > 0 && std::isfinite(b_m))) throw std::invalid_argument("Bekker width b must be > 0");
  k_ = params_.modulus_Pa(b_m);
}

double BekkerWong::loading_Pa(double z_m) const {
  return z_m > 0 ? k_ * std::pow(z_m, params_.n) : 0.0;
}

double BekkerWong::loading_sinkage_m(double p_Pa) const {
  return p_Pa > 0 ? std::pow(p_Pa / k_, 1.0 / params_.n) : 0.0;
}

double BekkerWong::unloading_stiffness_Pa_m(double z_max_m) const {
  if (!params_.unloading) return 0;
  const double ku = (params_.unloading->k0_kN_m3 + params_.unloading->Au_kN_m4 * z_max_m) * 1e3;
  // Not below the secant p_max / z_max: the unloading line then reaches p = 0 at or below the
  // undisturbed surface (rut >= 0) instead of pushing the surface above it.
  return z_max_m > 0 ? std::max(ku, loading_Pa(z_max_m) / z_max_m) : ku;
}

double BekkerWong::unloading_Pa(double z_m, double z_max_m) const {
  if (z_m >= z_max_m) return loading_Pa(z_m);
  if (!params_.unloading) return 0.0;  // rigid-plastic: no contact pressure above z_max
  const double p = loading_Pa(z_max_m) - unloading_stiffness_Pa_m(z_max_m) * (z_max_m - z_m);
  return std::max(p, 0.0);
}

double BekkerWong::unloading_sinkage_m(double p_Pa, double z_max_m) const {
  if (!params_.unloading) return z_max_m;
  const double ku = unloading_stiffness_Pa_m(z_max_m);
  const double z = z_max_m - (loading_Pa(z_max_m) - std::max(p_Pa, 0.0)) / ku;
  return std::clamp(z, 0.0, z_max_m);
}

double BekkerWong::compliance_m_per_Pa(double p_Pa, double z_max_m) const {
  const double p_max = z_max_m > 0 ? loading_Pa(z_max_m) : 0.0;
  if (p_Pa < p_max) {  // the branch: vertical (rigid-plastic), or Wong's line above the surface
    if (!params_.unloading) return 0.0;
    return unloading_sinkage_m(p_Pa, z_max_m) > 0 || p_Pa >= unloading_Pa(0.0, z_max_m)
               ? 1.0 / unloading_stiffness_Pa_m(z_max_m)
               : 0.0;
  }
  // Virgin curve z = (p / k)^(1/n): dz/dp = z / (n p); at p = 0 the limit (0 for n < 1).
  if (p_Pa > 0) return loading_sinkage_m(p_Pa) / (params_.n * p_Pa);
  return params_.n < 1 ? 0.0 : (params_.n == 1 ? 1.0 / k_ : 1e300);
}

double BekkerWong::virgin_sinkage_m(double p_Pa, double& dz_dp_m_per_Pa) const {
  if (!(p_Pa > 0)) {
    dz_dp_m_per_Pa = compliance_m_per_Pa(0.0, 0.0);
    return 0.0;
  }
  const double z = loading_sinkage_m(p_Pa);  // z = (p / k)^(1/n), dz/dp = z / (n p)
  dz_dp_m_per_Pa = z / (params_.n * p_Pa);
  return z;
}

double BekkerWong::work_J_m2(double p_Pa, double z_max_m) const {
  if (!(p_Pa > 0)) return 0.0;
  // Virgin curve: int_0^q (q'/k)^(1/n) dq' = n / (n + 1) q z(q).
  auto virgin = [&](double q) { return params_.n / (params_.n + 1) * q * loading_sinkage_m(q); };
  const double p_max = z_max_m > 0 ? loading_Pa(z_max_m) : 0.0;
  double work = 0;
  const double q = std::min(p_Pa, p_max);
  if (q > 0) {
    if (!params_.unloading) {
      work = z_max_m * q;  // the vertical branch at z_max
    } else {
      // z = z_max - (p_max - q') / k_u, clamped at 0 below q0 = p_max - k_u z_max.
      const double ku = unloading_stiffness_Pa_m(z_max_m);
      const double a = std::clamp(p_max - ku * z_max_m, 0.0, q);
      work = (q - a) * (z_max_m - p_max / ku) + (q * q - a * a) / (2 * ku);
    }
  }
  if (p_Pa > p_max) work += virgin(p_Pa) - virgin(p_max);
  return work;
}

double BekkerWong::rebound_depth_m(double z_max_m) const {
  return z_max_m > 0 ? unloading_sinkage_m(0.0, z_max_m) : 0.0;
}

}  // namespace modaltyre::ground
