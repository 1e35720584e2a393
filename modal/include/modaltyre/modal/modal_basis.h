#pragma once
// The axisymmetric modal basis of the carcass: one term per mode used in the compliance sums.
//
// A measured mode of order k >= 1 with shapes phi_r = Re(c_r e^{ik theta}),
// phi_t = Re(c_t e^{ik theta}) contributes, averaged over its angular position psi (the tyre is
// axisymmetric, so the compliance may depend only on theta_i - theta_j):
//   <phi_a(theta_i) phi_b(theta_j)>_psi = 1/2 Re(c_a conj(c_b) e^{ik(theta_i - theta_j)}).
// Modes of order k >= 1 come in degenerate pairs (cos and sin); each measured member carries
// weight 1/2 of the pair term, and a lone member stands for its unmeasured twin (weight 1).
// Order-0 modes (breathing, rotation) have no twin: weight 1.
//
// Mass normalisation: the shapes are in kg^-1/2 (unit modal mass), so
//   H_ab(Delta) = sum_terms w Re(P_ab e^{ik Delta}) / omega^2   [m/N]
// is the static compliance directly, with P_ab = c_a conj(c_b). The tyre is also mirror
// symmetric (theta -> -theta), so the radial-tangential coupling P_rt is kept purely imaginary
// (tangential shape in quadrature with the radial one) and is zero at order 0.
//
// Modal truncation: the hammer test resolves few orders. Without the extension the sums run over
// the resolved measured modes only (seed 001 eq. 1-4; docs/footprint.md section 2). With it,
// orders that no resolved measured mode covers (aliased orders and all orders above) are filled
// from the dispersion fit (dispersion.h) with the mean measured modal amplitude |c_r|^2 of the
// resolved orders >= 2 and the inextensional-ring tangential shape c_t = c_r * s / (i k), s being
// the measured sign of the radial-tangential coupling: the ring-on-elastic-foundation
// extension; `max_order` sets where the sum stops (the mesh's Nyquist order).
#include <complex>
#include <string>
#include <vector>

#include "modaltyre/modal/mode_identification.h"

namespace modaltyre::modal {

struct ModalTerm {
  int order = 0;
  double omega_rad_s = 0;  ///< undamped natural circular frequency
  double damping_ratio = 0;
  double weight = 1;                      ///< 1/2 for a member of a measured pair, 1 otherwise
  std::complex<double> P_rr, P_rt, P_tt;  ///< c_r conj(c_r), c_r conj(c_t), c_t conj(c_t) [1/kg]
  bool measured = true;                   ///< false: from the dispersion extension
  bool rotation = false;                  ///< the rigid rotation (order 0, tangential)
  int mode_id = 0;                        ///< hammer mode number, 0 for extension terms
};

struct ModalBasisOptions {
  int max_order = 0;   ///< highest harmonic order in the sums (>= highest measured order)
  bool extend = true;  ///< fill unmeasured orders from the dispersion fit
  /// Scales every modal compliance term (1 = as measured). A single scalar, not per order: it
  /// represents the uncertainty of the modal-mass normalisation of the hammer data.
  double compliance_scale = 1.0;
};

struct ModalBasis {
  std::vector<ModalTerm> terms;
  DispersionFit dispersion;
  int max_order = 0;  ///< highest order in the sums: the highest measured one without extension
  int measured_terms = 0;
  std::vector<std::string> warnings;  ///< e.g. an order 0 or 1 mode missing from the test

  /// Static compliance coefficient of order k, sum of w P_rr / omega^2 [m/N].
  double static_rr(int k) const;
};

/// Builds the basis; throws InputError if the data cannot support a kernel (no resolved modes,
/// or extension requested without a valid dispersion fit).
ModalBasis build_modal_basis(const ModeIdentification& modes, const ModalBasisOptions& opts);

}  // namespace modaltyre::modal
