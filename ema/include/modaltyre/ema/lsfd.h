#pragma once
// Residues by least-squares frequency-domain fitting (LSFD) over given poles, and the
// refinement of those poles by output-error least squares (variable projection).
//
// Model of FRF o (receptance; the FRF type multiplies every term by (j w)^p, p = 0, 1, 2):
//   H_o(w) = sum_k [ R_ok / (j w - lambda_k) + conj(R_ok) / (j w - conj(lambda_k)) ]
//            + UR_o + LR_o / (j w)^2
// with real upper and lower residuals: UR_o stands for the modes above the band (their
// stiffness line), LR_o for rigid-body and support modes below it (their mass line). For
// mass-normalised real shapes phi, R_ok = phi_ok phi_refk / (2 j w_dk), w_dk = Im(lambda_k).
#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "modaltyre/ema/frf_set.h"

namespace modaltyre::ema {

struct LsfdFit {
  Eigen::MatrixXcd residues;     ///< channels x modes, R_ok
  Eigen::VectorXd upper, lower;  ///< per channel, UR_o and LR_o
  Eigen::MatrixXcd synthesis;    ///< lines x channels, the model at the fitted lines
  double relative_error = 0;     ///< ||H - model||_F / ||H||_F
};

/// LSFD on lines `freq_hz` (> 0 Hz) of `frf` (lines x channels) of the given type.
LsfdFit lsfd(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf, FrfType type,
             const std::vector<std::complex<double>>& poles);

struct RefineOptions {
  int max_evaluations_per_parameter = 40;  ///< bounds the Levenberg-Marquardt iterations
  void validate() const;
};

struct RefinedPoles {
  std::vector<std::complex<double>> poles;
  double initial_error = 0, final_error = 0;  ///< relative LSFD error before and after
  int evaluations = 0;
  bool improved = false;  ///< false: the initial poles are returned unchanged
};

/// Minimises the LSFD misfit ||H - model(poles)|| over the poles' natural frequencies and
/// damping ratios (the residues eliminated by least squares, Levenberg-Marquardt on
/// ln f and ln zeta): the linearised LSCF estimate is biased by noise, the output error is not.
RefinedPoles refine_poles(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                          FrfType type, const std::vector<std::complex<double>>& poles,
                          const RefineOptions& options = {});

}  // namespace modaltyre::ema
