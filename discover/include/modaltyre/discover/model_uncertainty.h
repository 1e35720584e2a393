#pragma once
// The model's own uncertainty in discover's decision (issue 35, docs/uncertainty.md section 9,
// docs/discover.md): a gap between model and data is an effect only where the model's uncertain
// inputs (the hammer shapes' noise, ema's standard deviations, stated std; uncertainty/inputs.h)
// could not have produced it.
//
// Linearised: each input u moves the relative residuals of the fitted entries by j_u (its
// central difference at +-1 sigma divided as the residual is, residual_scale): on footprint rows
// uncertainty::propagate's, on traction rows (issue 45) uncertainty::propagate_outputs' with the
// rows' traction run as the Evaluator runs it (TractionRows: groups, windows, mesh, flexing
// loss). The inputs are the config's (collect_inputs), a Bekker soil's stated scatter among them
// (ground.bekker.uncertainty). The part the
// variant's re-fitted parameters absorb is projected out (j_u - J (J^T W J)^-1 J^T W j_u, J the
// fit's Jacobian, W = 1 / sigma_o^2 its noise weights), and C = sum_u j_u j_u^T is the residuals'
// covariance the inputs add to the measurement noise D = diag(sigma_o^2). A candidate that
// changes the residuals by g carries evidence g^T D^-1 g against noise alone and
// g^T (D + C)^-1 g against noise and model uncertainty; the share the inputs could produce,
//   f = 1 - g^T (D + C)^-1 g / g^T D^-1 g   (0 <= f <= 1),
// is taken off the likelihood-ratio part of its Delta BIC (Delta BIC + Delta k ln N, whose
// small-signal limit is g^T D^-1 g; the share keeps the profiled likelihood's saturation for
// large changes) before the naming rule.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "modaltyre/discover/model_fit.h"

namespace modaltyre::discover {

struct ModelUncertainty {
  Eigen::MatrixXd cov;             ///< C over the fit's entries (relative residual units)
  Eigen::VectorXd noise_var;       ///< D's diagonal, sigma_o^2 per entry
  std::vector<std::string> names;  ///< the inputs used
  int evaluations = 0;             ///< model predictions spent
};

/// C and D at `fit` of variant `v` on `base` (Jacobian by central differences: 2 k evaluations
/// of every row; the propagation: 1 + 2 n_inputs model builds for the footprint rows and as many
/// traction runs of the traction rows). Empty cov (and nothing evaluated) when the config has no
/// uncertain input.
ModelUncertainty model_uncertainty(const Evaluator& ev, const contact::TyreConfig& base,
                                   const Variant& v, const FitResult& fit);

/// f for a change g of the residuals (0 without uncertain inputs or change).
double uncertain_share(const ModelUncertainty& mu, const Eigen::VectorXd& g);

}  // namespace modaltyre::discover
