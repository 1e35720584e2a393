#include "modaltyre/ground/pressure_sinkage.h"

#include <algorithm>
#include <cmath>

namespace modaltyre::ground {

double PressureSinkage::pressure_Pa(double z_m, double z_max_m) const {
  return z_m >= z_max_m ? loading_Pa(z_m) : unloading_Pa(z_m, z_max_m);
}

double PressureSinkage::virgin_sinkage_m(double p_Pa, double& dz_dp_m_per_Pa) const {
  dz_dp_m_per_Pa = compliance_m_per_Pa(p_Pa, 0.0);
  return loading_sinkage_m(p_Pa);
}

double PressureSinkage::sinkage_m(double p_Pa, double z_max_m) const {
  if (z_max_m > 0 && p_Pa < loading_Pa(z_max_m)) return unloading_sinkage_m(p_Pa, z_max_m);
  return std::max(loading_sinkage_m(p_Pa), z_max_m);
}

double PressureSinkage::compliance_m_per_Pa(double p_Pa, double z_max_m) const {
  // A one-sided difference with a step relative to the pressure scale: the laws are smooth on
  // each branch, and the derivative only serves as a Newton model.
  const double scale = std::max({p_Pa, loading_Pa(std::max(z_max_m, 1e-4)), 1.0});
  const double h = 1e-6 * scale;
  return std::max(0.0, (sinkage_m(p_Pa + h, z_max_m) - sinkage_m(p_Pa, z_max_m)) / h);
}

namespace {

// int_a^b f by 8-point Gauss-Legendre on `panels` panels in u, x = a + (b - a) u^2 (clustered
// at a, where the virgin curve has its power-law end).
template <class F>
double clustered_integral(F f, double a, double b, int panels) {
  static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                              0.9602898564975363};
  static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                              0.1012285362903763};
  double sum = 0;
  for (int p = 0; p < panels; ++p) {
    for (int k = 0; k < 8; ++k) {
      const double xi = k < 4 ? -x[k] : x[k - 4], wi = k < 4 ? w[k] : w[k - 4];
      const double u = (p + 0.5 * (1 + xi)) / panels;
      sum += 0.5 * wi / panels * f(a + (b - a) * u * u) * 2 * (b - a) * u;
    }
  }
  return sum;
}

}  // namespace

double PressureSinkage::work_J_m2(double p_Pa, double z_max_m) const {
  if (!(p_Pa > 0)) return 0.0;
  const double p_max = z_max_m > 0 ? loading_Pa(z_max_m) : 0.0;
  auto z = [&](double q) { return sinkage_m(q, z_max_m); };
  double work = 0;
  // The branch: linear (elastic) or constant (rigid-plastic), possibly clamped at the surface.
  const double branch_end = std::min(p_Pa, p_max);
  if (branch_end > 0) {
    const double rebound_p = unloading_Pa(0.0, z_max_m);  // pressure at which z leaves 0
    if (rebound_p > 0 && rebound_p < branch_end) {
      work += clustered_integral(z, rebound_p, branch_end, 2);
    } else {
      work += clustered_integral(z, 0.0, branch_end, 2);
    }
  }
  if (p_Pa > p_max) work += clustered_integral(z, p_max, p_Pa, 4);
  return work;
}

}  // namespace modaltyre::ground
