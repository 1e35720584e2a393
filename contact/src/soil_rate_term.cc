// The Kelvin-Voigt soil's rate term under the rolling flexible tyre: see soil_rate_term.h and
// docs/soil.md section 9.1.
#include "modaltyre/contact/soil_rate_term.h"

#include <algorithm>
#include <cmath>

namespace modaltyre::contact {
namespace {

// 1 - w is kept above this: at h / tau below it the soil is far stiffer than the tyre over a
// patch point's passage (the ground point barely moves), and the cell roots divide by 1 - w.
constexpr double kMinShare = 1e-9;

}  // namespace

double soil_rate_time_s(const ground::GroundSettings& g, double speed_m_per_s) {
  if (g.model != ground::GroundModel::kelvin_voigt || !(speed_m_per_s > 0)) return 0.0;
  const double eta2_Pa_s = g.kelvin_voigt.eta2_kPa_s * 1e3, E2_Pa = g.kelvin_voigt.E2_MPa * 1e6;
  return eta2_Pa_s > 0 ? eta2_Pa_s / E2_Pa : 0.0;
}

SoilRateBudget soil_rate_budget(int max_iterations, double depth_tolerance, double tau_s,
                                double speed_m_per_s, double ds_m) {
  const double passage = tau_s * speed_m_per_s / ds_m;  // relaxation length over unit length
  SoilRateBudget b;
  b.max_iterations = max_iterations + static_cast<int>(std::min(20 * passage, 20000.0));
  b.depth_tolerance = depth_tolerance * std::max(1 - std::exp(-1 / passage), kMinShare);
  return b;
}

void soil_rate_column(SoilRate& rate, std::span<const double> theta, double R0_m, double tau_s,
                      double speed_m_per_s, double incoming_m, std::size_t first,
                      std::size_t stride, std::span<const double> surface_m) {
  const int S = static_cast<int>(theta.size());
  auto x = [&](int i) { return R0_m * std::sin(theta[i]); };
  for (int i = S - 1; i >= 0; --i) {
    const std::size_t a = first + std::size_t(i) * stride;
    // The passage time from the point ahead (the front point: its own spacing to the next).
    const double dx = i + 1 < S ? x(i + 1) - x(i) : x(i) - x(i - 1);
    rate.weight[a] = std::min(std::exp(-dx / (speed_m_per_s * tau_s)), 1 - kMinShare);
    rate.start_m[a] = i + 1 < S ? surface_m[a + stride] : incoming_m;
  }
}

void soil_rate_surface(std::span<double> surface_m, const SoilRate& rate,
                       const ground::PressureSinkage& law, double incoming_m, std::size_t first,
                       std::size_t stride, int sections, std::span<const double> depth_m,
                       std::span<const double> z_max_m) {
  double ahead = incoming_m;
  for (int i = sections - 1; i >= 0; --i) {
    const std::size_t a = first + std::size_t(i) * stride;
    const double w = rate.weight[a];
    ahead = depth_m[a] > 0 ? depth_m[a] : w * ahead + (1 - w) * law.sinkage_m(0.0, z_max_m[a]);
    surface_m[a] = ahead;
  }
}

}  // namespace modaltyre::contact
