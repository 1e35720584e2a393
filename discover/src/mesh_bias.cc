// The evaluation mesh's share of a fitted estimate (mesh_bias.h).
#include "modaltyre/discover/mesh_bias.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace modaltyre::discover {

std::vector<double> gauss_newton_shift(const studies::MeasurementSet& data, const FitResult& fit,
                                       const Eigen::MatrixXd& jacobian,
                                       const std::vector<double>& residual_change) {
  const Eigen::Index m = jacobian.rows(), k = jacobian.cols();
  if (m != static_cast<Eigen::Index>(residual_change.size()) ||
      m != static_cast<Eigen::Index>(fit.entries.size()))
    return {};
  std::vector<int> read;  // a parameter no row reads moves by 0
  Eigen::VectorXd w;      // 1 / each entry's noise level
  const Eigen::MatrixXd J = weighted_read_columns(data, fit, jacobian, read, &w);
  const auto kr = static_cast<Eigen::Index>(read.size());
  const Eigen::VectorXd dr =
      Eigen::Map<const Eigen::VectorXd>(residual_change.data(), m).cwiseProduct(w);
  std::vector<double> d(k, 0.0);
  if (kr == 0) return d;
  const Eigen::MatrixXd info = J.transpose() * J;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(info);
  if (cod.rank() < kr) return {};
  const Eigen::VectorXd step = -cod.solve(J.transpose() * dr);
  for (Eigen::Index j = 0; j < kr; ++j) d[read[j]] = step(j);
  return d;
}

MeshBias mesh_bias(const Evaluator& coarse, const Evaluator& fine, double fine_unit_length_m,
                   const contact::TyreConfig& base, const Variant& v, const FitResult& fit) {
  MeshBias b;
  b.unit_length_mm = coarse.model().unit_length_m * 1e3;
  b.fine_unit_length_mm = fine_unit_length_m * 1e3;
  contact::TyreConfig at_fine = fit.config;
  at_fine.mesh.unit_length_m = fine_unit_length_m;  // the traction rows roll on the config's
  int failures = 0;
  const std::vector<double> r_fine = fine.residuals(at_fine, fit.entries, failures);
  if (failures > 0) {
    std::ostringstream s;
    s << failures << " row(s) fail on the " << b.fine_unit_length_mm
      << " mm mesh at the fitted values: no mesh shift";
    b.note = s.str();
    return b;
  }
  std::vector<double> change(r_fine.size());
  double sum = 0;
  for (std::size_t i = 0; i < change.size(); ++i) {
    change[i] = r_fine[i] - fit.residuals[i];
    sum += change[i] * change[i];
  }
  b.change_rms = change.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(change.size()));
  b.residual_rms = fit.rms_all;
  // The fit's own Jacobian where it kept one (its standard errors came from it), else 2k
  // evaluations.
  const bool kept = fit.jacobian.rows() == static_cast<Eigen::Index>(fit.entries.size()) &&
                    fit.jacobian.cols() == static_cast<Eigen::Index>(v.parameters.size());
  const Eigen::MatrixXd J =
      kept ? fit.jacobian : jacobian(coarse, base, v, fit.values, fit.entries);
  const std::vector<double> d = gauss_newton_shift(coarse.data(), fit, J, change);
  if (d.empty()) {
    b.note = "the fitted parameters are not identifiable from these rows: no mesh shift";
    return b;
  }
  for (std::size_t j = 0; j < v.parameters.size() && j < d.size(); ++j)
    if (std::isfinite(d[j])) b.shift[v.parameters[j].key] = d[j];
  return b;
}

bool mesh_is_coarse(const MeshBias& b) {
  return b.change_rms >= 0 && 2 * b.change_rms >= 0.5 * b.residual_rms;
}

ParameterBand band_with_mesh(const ParameterBand& band, double shift, const FreeParameter& p) {
  ParameterBand w = band;
  const double continuum = 2 * shift;  // Richardson at first order (mesh_bias.h)
  w.lower = std::max(std::min(band.lower, band.lower + continuum), p.min);
  w.upper = std::min(std::max(band.upper, band.upper + continuum), p.max);
  w.lower_at_bound = band.lower_at_bound || !(w.lower > p.min);
  w.upper_at_bound = band.upper_at_bound || !(w.upper < p.max);
  w.fits = 0;
  return w;
}

}  // namespace modaltyre::discover
