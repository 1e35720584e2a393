#pragma once
// The modal basis of a tyre known by its frequencies (and orders) alone, mass-normalised by the
// ring relations of ring_model.h: a frequency list from a paper, `ema --unscaled` shapes, or a
// hammer CSV whose shape scale is not trusted. Each mode of order n >= 1 stands for its pair
// (cos and sin members; two entries of one order share the pair term) with the inextensible
// ring's shapes, inward radial amplitude a and tangential (a/n) sin (data/README's convention):
//   P_rr = a^2 = 1 / (pi R mu (1 + 1/n^2)),  P_tt = P_rr / n^2,  P_rt = i P_rr / n;
// order 0 (breathing, radial only): P_rr = 1 / (2 pi R mu); the rigid rotation (tangential
// only): P_tt = 1 / (2 pi R mu). Orders no mode covers, up to max_order, come from the ring fit
// with the mean damping of the measured orders >= 2. docs/ring_model.md.
#include <string>
#include <vector>

#include "modaltyre/modal/modal_basis.h"
#include "modaltyre/modal/ring_model.h"

namespace modaltyre::modal {

/// One mode as the ring basis takes it: rim-held, at the operating pressure.
struct RingMode {
  int order = 0;          ///< harmonic order n >= 0
  bool rotation = false;  ///< the rigid rotation (order 0, tangential) instead of breathing
  double freq_hz = 0;     ///< undamped natural frequency [Hz]
  double damping_ratio = 0;
  int id = 0;  ///< the mode's number in its source (a list position or a hammer mode)
};

struct RingBasisOptions {
  double mass_per_length_kg_m = 0;  ///< mu, > 0
  double radius_m = 0;              ///< R, > 0 (the kernel's radius)
  int max_order = 0;                ///< highest order in the sums
  bool extend = true;               ///< fill orders without a mode from `fit`
  double compliance_scale = 1.0;    ///< a declared calibration's scalar, 1 = none
};

/// Builds the basis; `fit` must be valid when `extend` is set. InputError (naming the order)
/// for a mode without a positive frequency or a negative order.
ModalBasis build_ring_basis(const std::vector<RingMode>& modes, const RingFit& fit,
                            const RingBasisOptions& opts);

}  // namespace modaltyre::modal
