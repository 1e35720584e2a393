#pragma once
// From fitted shapes to physical modes: harmonic order, kind and spatial aliasing.
//
// Each mode's radial and tangential shapes are fitted with the trigonometric series of seed 001
// eq. (20)-(21). The dominant radial harmonic gives the apparent order; its share of the shape's
// energy is the fit quality R^2.
//   kind = rotation    radial motion small against tangential, tangential shape constant
//                      (rigid rotation of the belt about the axle)
//   kind = radial      a clean radial harmonic
//   kind = unresolved  no harmonic dominates
// Spatial aliasing: with N points orders k >= N/2 cannot be told apart from lower ones. A mode is
// flagged `aliased` when (a) it fits at the Nyquist order N/2, or (b) it lies above (in frequency)
// a radial mode whose order is higher than its own apparent order — along a tyre's radial mode
// family (orders >= 2) frequency rises with order, so such a mode must be a higher order folded
// down. Apparent orders 0 and 1 (breathing, rigid translation) are not part of that family and
// may lie above its low orders: they count as folded only above a family mode of order N - k - 1
// or higher. Aliased modes keep their apparent order, list the candidate true orders
// (j N +- k_apparent), and name the likely one from the dispersion fit of the resolved orders.
#include <complex>
#include <string>
#include <vector>

#include "modaltyre/modal/dispersion.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/harmonic_fit.h"

namespace modaltyre::modal {

enum class ModeKind { radial, rotation, unresolved };
const char* to_string(ModeKind kind);

struct IdentificationOptions {
  /// Below this share of energy in one harmonic, a radial shape is `unresolved`.
  double min_harmonic_r2 = 0.75;
  /// Rotation: radial RMS below this fraction of tangential RMS ...
  double rotation_radial_ratio = 0.3;
  /// ... and the tangential shape at least this constant (order-0 share).
  double rotation_min_r2 = 0.8;
};

struct IdentifiedMode {
  int id = 0;
  double freq_hz = 0;
  double damping_ratio = 0;
  ModeKind kind = ModeKind::unresolved;
  int apparent_order = 0;             ///< dominant harmonic at the sample points
  bool aliased = false;               ///< order cannot be resolved from N points
  std::vector<int> alias_candidates;  ///< possible true orders when aliased
  int likely_order = -1;              ///< most likely true order (dispersion), -1 if unknown
  double r2 = 0;  ///< share of radial (rotation: tangential) energy in that harmonic
  HarmonicSeries radial;
  HarmonicSeries tangential;
  std::complex<double> c_radial;      ///< radial shape = Re(c e^{ik theta}) [kg^-1/2]
  std::complex<double> c_tangential;  ///< tangential shape at the same order [kg^-1/2]
  /// Measurement noise of the shape values from the residual of the one-harmonic model (a ring
  /// mode is one harmonic; everything else at the points is noise): sigma^2 = residual energy /
  /// (N - p), p = 2 parameters (A_k, B_k), 1 at order 0 and N/2 [kg^-1/2]. 0 for N <= p.
  double radial_noise = 0, tangential_noise = 0;
  /// Standard deviation of each of Re c and Im c: sigma / sqrt(N/2) (sigma / sqrt(N) at order 0
  /// and N/2), the covariance of the orthogonal least-squares fit [kg^-1/2].
  double c_radial_std = 0, c_tangential_std = 0;
  /// Relative standard deviation of the modal amplitude |c_r|^2 (the mode's compliance scale),
  /// linearised: std(|c|^2) = 2 |c| std(c), relative 2 std(c) / |c| (docs/uncertainty.md).
  double amplitude2_rel_std = 0;
  /// The hammer file's standard deviations (`ema`, docs/uncertainty.md section 5), 0 without.
  double freq_std_hz = 0, damping_std = 0;
  /// The noise the shape values' stated standard deviations imply (their RMS over the points),
  /// 0 without; radial_noise / tangential_noise above take the larger of it and the residual's.
  double radial_noise_stated = 0, tangential_noise_stated = 0;
  std::string note;

  /// Order to use physically: apparent order when resolved, else likely_order.
  int order() const { return aliased ? likely_order : apparent_order; }
};

struct ModeIdentification {
  int points = 0;
  std::vector<IdentifiedMode> modes;  ///< same order as in the hammer file
  DispersionFit dispersion;           ///< fitted on resolved radial orders >= 2
};

ModeIdentification identify_modes(const HammerData& data, const IdentificationOptions& opts = {});

}  // namespace modaltyre::modal
