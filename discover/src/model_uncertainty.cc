#include "modaltyre/discover/model_uncertainty.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::discover {
namespace {

// The propagation's output index of a discover observable; -1: no band (rolling resistance).
int output_of(const std::string& observable) {
  if (observable == "sinking_mm") return 0;
  if (observable == "length_mm") return 1;
  if (observable == "width_mm") return 2;
  return -1;
}

// Relative noise floor of model_fit.h's BIC: keeps D invertible on noise-free data.
constexpr double kFitNoiseFloor = 1e-4;

}  // namespace

ModelUncertainty model_uncertainty(const Evaluator& ev, const contact::TyreConfig& base,
                                   const Variant& v, const FitResult& fit) {
  const auto& data = ev.data();
  const auto& e = fit.entries;
  const auto m = static_cast<Eigen::Index>(e.size());
  ModelUncertainty mu;
  mu.noise_var.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double s = fit.rms.at(data.observables[e[i].observable]);
    mu.noise_var(i) = std::max(s * s, kFitNoiseFloor * kFitNoiseFloor);
  }
  mu.cov = Eigen::MatrixXd::Zero(m, m);
  std::vector<contact::OperatingConditions> cases;
  for (const auto& r : data.rows) cases.push_back(r.conditions);
  uncertainty::PropagationOptions o;
  o.method = uncertainty::Method::linear;  // the sensitivities are what is used
  const auto p = uncertainty::propagate(fit.config, contact::config_modes(fit.config), cases, o);
  mu.evaluations = p.evaluations * static_cast<int>(cases.size());
  if (p.inputs.empty()) return mu;
  Eigen::MatrixXd j(m, static_cast<Eigen::Index>(p.inputs.size()));
  for (std::size_t u = 0; u < p.inputs.size(); ++u) {
    mu.names.push_back(p.inputs[u].input.name);
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto& row = data.rows[e[i].row];
      const int q = output_of(data.observables[e[i].observable]);
      const double measured = std::abs(row.value(data.observables[e[i].observable]).value_or(0));
      j(i, static_cast<Eigen::Index>(u)) =
          q >= 0 && measured > 0 ? p.inputs[u].sensitivity[e[i].row][q] / measured : 0.0;
    }
  }
  // What the variant's own parameters absorb is not uncertainty left in the residuals.
  const Eigen::MatrixXd jb = jacobian(ev, base, v, fit.values, e);
  mu.evaluations += 2 * static_cast<int>(v.parameters.size()) * static_cast<int>(data.rows.size());
  if (jb.cols() > 0) {
    const Eigen::VectorXd w = mu.noise_var.cwiseInverse();
    const Eigen::MatrixXd jtw = jb.transpose() * w.asDiagonal();
    const Eigen::MatrixXd normal = jtw * jb;
    j -= jb * normal.completeOrthogonalDecomposition().solve(jtw * j);
  }
  mu.cov = j * j.transpose();
  return mu;
}

double uncertain_share(const ModelUncertainty& mu, const Eigen::VectorXd& g) {
  if (mu.names.empty() || g.size() != mu.noise_var.size()) return 0;
  const double alone = g.dot(mu.noise_var.cwiseInverse().asDiagonal() * g);
  if (!(alone > 0)) return 0;
  Eigen::MatrixXd total = mu.cov;
  total.diagonal() += mu.noise_var;
  const double with = g.dot(total.ldlt().solve(g));
  return std::clamp(1.0 - with / alone, 0.0, 1.0);
}

}  // namespace modaltyre::discover
