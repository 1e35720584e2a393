#pragma once
// Carcass transfer functions between two points of the circumference (seed 001 eq. 1-5).
//
// Seed eq. (1): b_r = H_rr f_r + H_tr f_t,  b_t = H_rt f_r + H_tt f_t, where the seed's H_rt is
// the tangential response to a radial force and H_tr the radial response to a tangential force.
// Here the four functions are named by response and excitation: r_from_r (H_rr), r_from_t (H_tr),
// t_from_r (H_rt), t_from_t (H_tt). Radial is positive inwards (towards the axle), tangential
// positive in the direction of increasing theta. Units m/N.
//
// Static (t -> infinity in eq. 2): the impulse response integrated over time gives
//   H_ab(Delta) = sum w Re(P_ab e^{ik Delta}) / omega_k^2,  Delta = theta_i - theta_j.
// Steady rolling at speed V (eq. 5, the cos(k V (t - tau)/R) factor): material points pass a load
// fixed in the ground frame at angular speed Omega = V/R, so mode k sees it at frequency k Omega
// and responds with the complex receptance
//   D_k = 1 / (omega_k^2 - (k Omega)^2 - 2 i zeta_k omega_k k Omega),
//   H_ab(Delta) = sum w Re(P_ab D_k e^{ik Delta}),
// which reduces to the static form as V -> 0 and becomes asymmetric in Delta when rolling
// (the deformation trails the load: damping makes rolling resistance). Gyroscopic coupling of the
// rotating ring is neglected.
//
// Axisymmetry makes every function depend on Delta only; kernels on a uniform grid are built in
// O(terms * lags) with a complex rotation recurrence, never as an O(n^2 K) double loop.
#include <vector>

#include "modaltyre/modal/modal_basis.h"

namespace modaltyre::modal {

struct Transfer2x2 {
  double r_from_r = 0, r_from_t = 0, t_from_r = 0, t_from_t = 0;  ///< [m/N]
};

struct RollingState {
  double speed_m_s = 0;   ///< rolling speed V, >= 0 (0 = static)
  double radius_m = 0.3;  ///< rolling radius R used for Omega = V / R
};

/// Transfer functions between two points an angle Delta = theta_i - theta_j apart.
Transfer2x2 transfer(const ModalBasis& basis, double delta_rad, const RollingState& rolling = {});

/// Kernels sampled on a uniform angular grid, lags -(lags-1) .. +(lags-1).
struct LagKernels {
  double dtheta_rad = 0;
  int lags = 0;
  std::vector<double> r_from_r, r_from_t, t_from_r, t_from_t;  ///< index j + lags - 1

  Transfer2x2 at(int j) const {
    const auto i = static_cast<std::size_t>(j + lags - 1);
    return {r_from_r[i], r_from_t[i], t_from_r[i], t_from_t[i]};
  }
};

LagKernels build_lag_kernels(const ModalBasis& basis, double dtheta_rad, int lags,
                             const RollingState& rolling = {});

/// The same kernels on the grid of n units around the circumference (dtheta = 2 pi / n), built
/// with one inverse FFT of length n per function from the per-order coefficients: O(n log n)
/// instead of O(terms * lags). Requires every term's order <= n / 2 (no aliasing on the grid).
LagKernels build_periodic_kernels(const ModalBasis& basis, int n, int lags,
                                  const RollingState& rolling = {});

/// Nearest n' >= 8 of the form 2^a 3^b 5^c (fast FFT lengths) to n.
int fft_friendly_size(int n);

}  // namespace modaltyre::modal
