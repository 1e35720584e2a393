#pragma once
// Poles by the least-squares complex-frequency-domain method (LSCF, common denominator; for
// one reference it is poly-reference LSCF with scalar coefficients), over every model order up
// to a maximum: the stabilisation diagram, and its automatic reading (docs/ema.md).
//
// Model of FRF o at line f: H_o(w_f) = N_o(Omega_f) / d(Omega_f), Omega_f = exp(-j w_f Ts),
// Ts = 1 / (2 f_hi), polynomials of degree n with real coefficients. The linearised error
// N_o - H_o d is minimised in least squares over all lines and FRFs; the numerators are
// eliminated (reduced normal equations), the denominator coefficient alpha_n = 1 fixes the
// scale. A root z of d gives the pole lambda = -ln(z) / Ts; with this sign of the exponent the
// physical poles come out stable and the mathematical ones mostly unstable (the property that
// makes LSCF diagrams clear).
#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace modaltyre::ema {

struct StabilityCriteria {
  double freq_tol = 0.01;     ///< |df| / f to the nearest pole one order lower
  double damping_tol = 0.05;  ///< |dzeta| / zeta
  double mac_min = 0.98;      ///< MAC of the numerator-based shapes
  void validate() const;
};

/// One pole of the diagram; `status`: 'o' new, 'f' frequency stable, 'd' frequency and
/// damping stable, 's' also shape stable (each against the nearest pole one order lower).
struct DiagramPole {
  double freq_hz = 0, damping_ratio = 0;
  char status = 'o';
};

struct DiagramOrder {
  int order = 0;
  std::vector<DiagramPole> poles;  ///< physical-looking poles in the band (0 < zeta < 1)
};

struct StabilisationDiagram {
  double band_lo_hz = 0, band_hi_hz = 0;
  std::vector<DiagramOrder> orders;  ///< orders 2 ... max, ascending
};

/// LSCF over `freq_hz` (the band's lines, > 0 Hz) and `frf` (lines x channels, each column
/// scaled as the caller wants it weighted), every order from 2 to max_order.
StabilisationDiagram lscf_diagram(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                                  int max_order, const StabilityCriteria& criteria = {});

struct PoleSelection {
  /// A pole of the top order is kept when the orders from max/2 to max-1 have a pole within
  /// `match_tol` of its frequency in at least this fraction of them.
  double min_recurrence = 0.05;
  double match_tol = 0.01;
  double max_damping = 0.2;  ///< poles more damped than this are not modes of a tyre test
  void validate() const;
};

struct SelectedPole {
  double freq_hz = 0, damping_ratio = 0;
  double recurrence = 0;                ///< fraction of the upper half of orders where it recurs
  std::complex<double> lambda() const;  ///< -zeta w + j w sqrt(1 - zeta^2) [rad/s]
};

std::vector<SelectedPole> select_poles(const StabilisationDiagram& diagram,
                                       const PoleSelection& selection = {});

}  // namespace modaltyre::ema
