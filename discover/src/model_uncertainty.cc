#include "modaltyre/discover/model_uncertainty.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/core/errors.h"
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

// The traction rows' outputs, in the order traction_output_of() indexes them.
const std::vector<std::string> kTractionOutputs = {"drawbar_pull_N", "soil_sinkage_mm",
                                                   "torque_Nm"};

int traction_output_of(const std::string& observable) {
  const auto it = std::find(kTractionOutputs.begin(), kTractionOutputs.end(), observable);
  return it == kTractionOutputs.end() ? -1 : static_cast<int>(it - kTractionOutputs.begin());
}

// The inputs' central differences on the traction rows `rows`, run as discover's Evaluator runs
// them (TractionRows: the same groups, windows, mesh and flexing loss) on each perturbed config
// and modal basis; a row failing at +-1 sigma is a ComputationError naming it and the input.
uncertainty::PropagationResult traction_propagation(const Evaluator& ev,
                                                    const contact::TyreConfig& config,
                                                    const modal::ModeIdentification& modes,
                                                    const std::vector<int>& rows,
                                                    const uncertainty::PropagationOptions& o) {
  const auto& data = ev.data();
  const uncertainty::Evaluator rolled = [&](const contact::TyreConfig& c,
                                            const modal::ModeIdentification& m,
                                            const std::string& what) {
    const auto t = ev.traction(c, rows, &m);
    std::vector<std::vector<double>> out;
    for (int r : rows) {
      const contact::TractionResult& res = t.at(r);
      if (!res.ok())
        throw ComputationError("discover --uncertainty: traction row " +
                               std::to_string(data.rows[r].row) + " with " + what +
                               " failed: " + res.message);
      out.emplace_back();
      for (const auto& name : kTractionOutputs)
        out.back().push_back(traction_observable(res, name));
    }
    return out;
  };
  uncertainty::OutputSet outputs;
  outputs.names = kTractionOutputs;
  for (int r : rows) outputs.row_labels.push_back("row " + std::to_string(data.rows[r].row));
  return uncertainty::propagate_outputs(config, modes, rolled, outputs, o);
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
  const modal::ModeIdentification modes = contact::config_modes(fit.config);
  if (uncertainty::collect_inputs(fit.config, modes).empty()) return mu;
  // Footprint rows by the footprint's propagation, traction rows by their own (both perturb
  // the same inputs, collect_inputs, in the same order).
  std::vector<int> footprint_rows, traction_rows;
  std::vector<int> case_of(data.rows.size(), -1);
  std::vector<contact::OperatingConditions> cases;
  for (std::size_t r = 0; r < data.rows.size(); ++r) {
    auto& list = data.rows[r].traction ? traction_rows : footprint_rows;
    case_of[r] = static_cast<int>(list.size());
    list.push_back(static_cast<int>(r));
    if (!data.rows[r].traction) cases.push_back(data.rows[r].conditions);
  }
  uncertainty::PropagationOptions o;
  o.method = uncertainty::Method::linear;  // the sensitivities are what is used
  std::optional<uncertainty::PropagationResult> pf, pt;
  if (!cases.empty()) {
    pf = uncertainty::propagate(fit.config, modes, cases, o);
    mu.evaluations += pf->evaluations * static_cast<int>(cases.size());
  }
  if (!traction_rows.empty()) {
    pt = traction_propagation(ev, fit.config, modes, traction_rows, o);
    mu.evaluations += pt->evaluations * static_cast<int>(traction_rows.size());
  }
  const auto& inputs = (pf ? pf : pt)->inputs;
  MODALTYRE_CHECK(!pf || !pt || pf->inputs.size() == pt->inputs.size(),
                  "the footprint and traction propagations perturbed different inputs");
  const double R0 = fit.config.outer_radius_m;
  Eigen::MatrixXd j(m, static_cast<Eigen::Index>(inputs.size()));
  for (std::size_t u = 0; u < inputs.size(); ++u) {
    mu.names.push_back(inputs[u].input.name);
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto& row = data.rows[e[i].row];
      const std::string& obs = data.observables[e[i].observable];
      const int q = row.traction ? traction_output_of(obs) : output_of(obs);
      const auto& p = row.traction ? pt : pf;
      // Divided as the residuals are (residual_scale: |measured| on a footprint, the traction
      // rows' load floors on pull and torque).
      const double scale = residual_scale(row, obs, std::abs(row.value(obs).value_or(0)), R0);
      j(i, static_cast<Eigen::Index>(u)) =
          q >= 0 && scale > 0 ? p->inputs[u].sensitivity[case_of[e[i].row]][q] / scale : 0.0;
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
