#include "modaltyre/ema/lsfd.h"

#include <cmath>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <unsupported/Eigen/NumericalDiff>

#include "lsfd_basis.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::ema {
namespace {

using cd = std::complex<double>;
using detail::basis;
using detail::kResiduals;
using detail::kTwoPi;
using detail::stack;

// Least-squares coefficients of `y` (stacked) on `a`, columns scaled to unit norm first (the
// residual terms and the resonant terms differ by orders of magnitude).
Eigen::MatrixXd solve(const Eigen::MatrixXd& a, const Eigen::MatrixXd& y) {
  Eigen::VectorXd scale = a.colwise().norm().transpose();
  for (auto& s : scale) s = s > 0 ? 1.0 / s : 1.0;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(a * scale.asDiagonal());
  return scale.asDiagonal() * qr.solve(y);
}

std::vector<cd> poles_of(const Eigen::VectorXd& x) {  // x = (ln f_k, ln zeta_k)
  const int m = static_cast<int>(x.size() / 2);
  std::vector<cd> poles(m);
  for (int k = 0; k < m; ++k) {
    const double w = kTwoPi * std::exp(x(k)), z = std::min(std::exp(x(m + k)), 0.999);
    poles[k] = cd(-z * w, w * std::sqrt(1 - z * z));
  }
  return poles;
}

struct Misfit : Eigen::DenseFunctor<double> {
  Misfit(const std::vector<double>& f, const Eigen::MatrixXd& y, FrfType t, int params, int& n)
      : DenseFunctor<double>(params, static_cast<int>(y.size())),
        freq(f),
        data(y),
        type(t),
        evaluations(&n) {}
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& fvec) const {
    const Eigen::MatrixXd a = stack(basis(freq, type, poles_of(x)));
    const Eigen::MatrixXd r = data - a * solve(a, data);
    fvec = Eigen::Map<const Eigen::VectorXd>(r.data(), r.size());
    ++*evaluations;
    return 0;
  }
  const std::vector<double>& freq;
  const Eigen::MatrixXd& data;
  FrfType type;
  int* evaluations;  // shared with the copy NumericalDiff makes
};

}  // namespace

LsfdFit lsfd(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf, FrfType type,
             const std::vector<cd>& poles) {
  const int m = static_cast<int>(poles.size());
  MODALTYRE_CHECK(frf.rows() == static_cast<Eigen::Index>(freq_hz.size()) &&
                      2 * frf.rows() > 2 * m + kResiduals,
                  "lsfd: too few lines for the poles");
  const Eigen::MatrixXcd a = basis(freq_hz, type, poles);
  const Eigen::MatrixXd c = solve(stack(a), stack(frf));
  LsfdFit fit;
  fit.residues.resize(frf.cols(), m);
  for (int k = 0; k < m; ++k) {
    fit.residues.col(k) = (c.row(2 * k) + cd(0, 1) * c.row(2 * k + 1)).transpose();
  }
  fit.upper = c.row(2 * m).transpose();
  fit.lower = c.row(2 * m + 1).transpose();
  fit.synthesis = a * c.cast<cd>();
  const double norm = frf.norm();
  fit.relative_error = norm > 0 ? (frf - fit.synthesis).norm() / norm : 0.0;
  return fit;
}

void RefineOptions::validate() const {
  if (max_evaluations_per_parameter < 1 || max_evaluations_per_parameter > 1000) {
    throw InputError("refinement: max_evaluations_per_parameter must be 1 ... 1000");
  }
}

RefinedPoles refine_poles(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                          FrfType type, const std::vector<cd>& poles,
                          const RefineOptions& options) {
  options.validate();
  RefinedPoles out;
  out.poles = poles;
  const int m = static_cast<int>(poles.size());
  if (m == 0) return out;
  Eigen::VectorXd x(2 * m);
  for (int k = 0; k < m; ++k) {
    x(k) = std::log(std::abs(poles[k]) / kTwoPi);
    x(m + k) = std::log(-poles[k].real() / std::abs(poles[k]));
  }
  const Eigen::MatrixXd y = stack(frf);
  const double norm = y.norm();
  Misfit misfit(freq_hz, y, type, 2 * m, out.evaluations);
  Eigen::VectorXd r0;
  misfit(x, r0);
  out.initial_error = norm > 0 ? r0.norm() / norm : 0.0;
  out.final_error = out.initial_error;

  Eigen::NumericalDiff<Misfit> diff(misfit);
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Misfit>> lm(diff);
  // Counts LM steps only; every Jacobian costs 2m more evaluations.
  lm.setMaxfev(options.max_evaluations_per_parameter);
  Eigen::VectorXd xr = x;
  lm.minimize(xr);
  if (!xr.allFinite()) return out;
  Eigen::VectorXd r1;
  misfit(xr, r1);
  const double e1 = norm > 0 ? r1.norm() / norm : 0.0;
  if (std::isfinite(e1) && e1 < out.initial_error) {
    out.poles = poles_of(xr);
    out.final_error = e1;
    out.improved = true;
  }
  return out;
}

}  // namespace modaltyre::ema
