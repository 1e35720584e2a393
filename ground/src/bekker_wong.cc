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

double BekkerWong::rebound_depth_m(double z_max_m) const {
  return z_max_m > 0 ? unloading_sinkage_m(0.0, z_max_m) : 0.0;
}

}  // namespace modaltyre::ground
