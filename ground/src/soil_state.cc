#include "modaltyre/ground/soil_state.h"

#include <algorithm>

namespace modaltyre::ground {

void SoilState::record(std::size_t i, double z_m) {
  double& z = z_max_m_.at(i);
  z = std::max(z, z_m);
}

double SoilState::rut_depth_m(const PressureSinkage& law, std::size_t i) const {
  return law.rebound_depth_m(z_max_m_.at(i));
}

double SoilState::deepest_m() const {
  return z_max_m_.empty() ? 0.0 : *std::max_element(z_max_m_.begin(), z_max_m_.end());
}

double SoilState::deepest_rut_m(const PressureSinkage& law) const {
  double d = 0;
  for (double z : z_max_m_) d = std::max(d, law.rebound_depth_m(z));
  return d;
}

}  // namespace modaltyre::ground
