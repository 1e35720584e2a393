#pragma once
// The Kelvin-Voigt soil's rate term eta2 under the rolling flexible tyre (seed 000 eq. 23;
// docs/soil.md section 9.1). In steady rolling a ground point travels backward under the axle
// at the travel speed V: from the patch point ahead of it (depth z_a) to point i in the time
// h_i = (x_{i+1} - x_i) / V. Both branches of the law are eta2 dz/dt + E2 z = E2 Z_el(p; z_max)
// (Z_el the elastic law, k_E cancels from the loading branch's time constant), so under the
// pressure p held over h_i the point's depth is exactly (docs/soil.md (V1))
//   Z_i(p) = w_i z_a + (1 - w_i) Z_el(p; z_max),   w_i = exp(-h_i / tau),  tau = eta2 / E2:
// continuous and non-decreasing in p (the contact problems stay convex), Z_i(0) the surface
// recovering freely behind the tyre (where sigma would fall below 0 the tyre leaves it). The
// rolling fixed points take z_a from the last rolling step's surface (one-sided toward the
// front, where the ground point comes from; a plain step beside their Anderson-mixed state:
// mixed, an extrapolated surface could put the load on one point, docs/soil.md section 9.1).
// The surface's level returns through z_a with the factor w: a level error decays as w^n over
// the rolling steps (w = 1 - 1/35 at 1 mm units, 5 km/h, tau 25 ms), so the steps' budget and
// the depth test scale with 1 / (1 - w) (soil_rate_budget). Taking the level implicitly (z_a
// moved with the axle's approach) was tried: the entry point, whose z_a is the fixed ground
// ahead, then lags the approach and the steps oscillated apart.
// Off (eta2 = 0 or V = 0) the map is the identity and no arithmetic is added.
#include <cstddef>
#include <span>
#include <vector>

#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/ground/pressure_sinkage.h"

namespace modaltyre::contact {

struct SoilRate {
  std::vector<double> weight;   ///< w_i per patch point; empty: no rate term
  std::vector<double> start_m;  ///< z_a,i: the depth the ground point arrives with [m]

  bool on() const { return !weight.empty(); }
  /// Z_i from the elastic law's sinkage z_el at the same pressure.
  double sinkage_m(std::size_t i, double z_el_m) const {
    return on() ? weight[i] * start_m[i] + (1 - weight[i]) * z_el_m : z_el_m;
  }
  /// dZ_i/dZ_el = 1 - w_i.
  double scale(std::size_t i) const { return on() ? 1 - weight[i] : 1.0; }
  /// int_0^p Z_i dp from the elastic law's work w_el at p.
  double work_J_m2(std::size_t i, double p_Pa, double w_el_J_m2) const {
    return on() ? weight[i] * start_m[i] * p_Pa + (1 - weight[i]) * w_el_J_m2 : w_el_J_m2;
  }
};

/// The rolling fixed point's budget with the rate term at unit length ds: the steps
/// max_iterations + 20 tau V / ds (at most 20000) and the depth test depth_tolerance (1 - w) at
/// w = exp(-ds / (tau V)), so that the level's remaining error (change / (1 - w)) stays within
/// depth_tolerance of the sinkage.
struct SoilRateBudget {
  int max_iterations = 0;
  double depth_tolerance = 0;
};
SoilRateBudget soil_rate_budget(int max_iterations, double depth_tolerance, double tau_s,
                                double speed_m_per_s, double ds_m);

/// tau = eta2 / E2 [s] where the rate term acts (a Kelvin-Voigt soil with eta2 > 0 rolled at
/// V > 0), else 0.
double soil_rate_time_s(const ground::GroundSettings& ground, double speed_m_per_s);

/// One column of patch points, section i at point first + i * stride (front = the highest i,
/// road position x_i = R0 sin theta_i): writes w_i and z_a,i (the surface under the point ahead
/// in surface_m; the front point's: incoming_m, the surface ahead of the patch) into rate, sized
/// to every point.
void soil_rate_column(SoilRate& rate, std::span<const double> theta, double R0_m, double tau_s,
                      double speed_m_per_s, double incoming_m, std::size_t first,
                      std::size_t stride, std::span<const double> surface_m);

/// The surface the rate term rolls on after a solve, one column (as soil_rate_column): the depth
/// where a point is in contact (depth_m > 0), else the surface recovering freely from the one
/// ahead (this one's, front to back), w z_a + (1 - w) Z_el(0; z_max). Continuous across the
/// contact's edges, unlike the contact's depth, so that the fixed point may mix it.
void soil_rate_surface(std::span<double> surface_m, const SoilRate& rate,
                       const ground::PressureSinkage& law, double incoming_m, std::size_t first,
                       std::size_t stride, int sections, std::span<const double> depth_m,
                       std::span<const double> z_max_m);

}  // namespace modaltyre::contact
