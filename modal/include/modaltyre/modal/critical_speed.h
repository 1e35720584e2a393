#pragma once
// The rolling carcass's critical speed: the lowest phase velocity omega_k R / k of its travelling
// waves. In the ground frame an order-k mode of a tyre rolling at V = Omega R has the stiffness
// omega_k^2 - (k Omega)^2 (docs/transient.md section 1, seed 001 eq. 5's rolling receptance):
// at V = omega_k R / k its backward wave stands still on the road (the standing wave), and
// beyond it the contact, a spring moving faster than the wave, feeds energy into that wave
// (anomalous Doppler waves; Metrikine and Dieterman 1997 for a moving oscillator on a beam):
// the rolling tyre of the model has no steady state there. The measured modes are those of the
// tyre at rest, without the centrifugal stiffening of the belt, which raises a real tyre's
// critical speed; passenger tyres form standing waves at roughly 200-300 km/h (their speed
// ratings H-Y, 210-300 km/h, stay below).
#include "modaltyre/modal/modal_basis.h"

namespace modaltyre::modal {

struct CriticalSpeed {
  double speed_m_s = 0;  ///< min over k >= 1 of omega_k R / k (infinite without such a term)
  int order = 0;         ///< the order that sets it
  double speed_km_h() const { return speed_m_s * 3.6; }
};

/// The critical speed of the basis' terms of orders 1 .. max_order (every order when
/// max_order <= 0) on a tyre of outer radius `radius_m` (the rigid rotation left out).
CriticalSpeed critical_speed(const ModalBasis& basis, double radius_m, int max_order = 0);

}  // namespace modaltyre::modal
