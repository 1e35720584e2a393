#include "modaltyre/studies/validation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/solvers/levenberg_marquardt.h"

namespace modaltyre::studies {
namespace {

using namespace contact;

// The parameter a `validation.calibrate` key names (parameter_spec.h: those with a calibration
// range); InputError listing the calibratable keys otherwise.
const ParameterSpec& calibratable(const std::string& key, const std::string& config_path) {
  const ParameterSpec* p = find_parameter(key);
  if (p && p->calibration) return *p;
  std::vector<std::string> keys;
  for (const auto& q : parameter_catalogue()) {
    if (q.calibration) keys.push_back(q.key);
  }
  std::sort(keys.begin(), keys.end());
  std::string list;
  for (const auto& k : keys) list += (list.empty() ? "" : ", ") + k;
  throw InputError({config_path, 0, "validation.calibrate"},
                   "'" + key + "' cannot be calibrated; choose from: " + list);
}

// Predicted footprints of the rows at their conditions, in file order (on the effect-free path
// each warm-started from the previous, as validate always did).
std::vector<Prediction> predict_rows(const TyreModel& model, const std::vector<MeasuredRow>& rows) {
  std::vector<OperatingConditions> conditions;
  for (const auto& r : rows) conditions.push_back(r.conditions);
  return predict_all(model, conditions);
}

void require_converged(const std::vector<Prediction>& res, const std::string& stage) {
  for (const auto& p : res) {
    if (!p.ok()) {
      std::ostringstream m;
      m << stage << ": load case " << p.footprint.load.load_N
        << " N did not converge: " << p.message;
      throw ComputationError(m.str());
    }
  }
}

// The calibrated scalars' covariance from the Jacobian at the fit (central differences in
// ln x) and the residual variance (Calibration's comment).
// With the rows' stated noise as weights (`cal.noise_weighted`) the residuals are in units of
// their standard deviations and the covariance is (J^T J)^-1 itself (known noise: no residual
// variance to estimate, so m = n residuals suffice).
template <class Residual>
void set_covariance(Calibration& cal, const Residual& residual, const Eigen::VectorXd& x,
                    const Eigen::VectorXd& r) {
  const Eigen::Index n = x.size(), m = r.size();
  if (cal.noise_weighted ? m < n : m <= n) {
    cal.covariance_note = "no standard errors: " + std::to_string(m) +
                          " calibration residuals for " + std::to_string(n) +
                          " scalars leave no degree of freedom to estimate the noise";
    return;
  }
  constexpr double kStep = 1e-4;  // in ln x: 0.01 % of each value, far above rounding
  Eigen::MatrixXd J(m, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    Eigen::VectorXd up = x, down = x;
    up(k) += kStep;
    down(k) -= kStep;
    J.col(k) = (residual(up) - residual(down)) / (2 * kStep);
  }
  const double s2 = cal.noise_weighted ? 1.0 : r.squaredNorm() / static_cast<double>(m - n);
  const Eigen::MatrixXd JtJ = J.transpose() * J;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(JtJ);
  if (!lu.isInvertible()) {
    cal.covariance_note =
        "no standard errors: the calibration rows do not determine every "
        "scalar (J^T J singular)";
    return;
  }
  const Eigen::MatrixXd cov = s2 * lu.inverse();
  for (Eigen::Index k = 0; k < n; ++k) {
    cal.std_errors.push_back(cal.values[static_cast<std::size_t>(k)] * std::sqrt(cov(k, k)));
  }
  cal.correlation.assign(static_cast<std::size_t>(n),
                         std::vector<double>(static_cast<std::size_t>(n)));
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      cal.correlation[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          cov(i, j) / std::sqrt(cov(i, i) * cov(j, j));
  cal.covariance_note =
      cal.noise_weighted
          ? "from the Jacobian at the fit and the calibration rows' stated noise (the *_std "
            "columns; chi-square " +
                std::to_string(r.squaredNorm()) + " on " + std::to_string(m - n) +
                " degrees of freedom)"
          : "from the Jacobian at the fit and the residual variance (" + std::to_string(m - n) +
                " degrees of freedom)";
}

// What a user with their own file can do when the config's calibration block does not fit it
// (issue 38): rows at the ends of the file's load range, the observables the file has, or no
// calibration at all - each as the --set that does it.
std::string calibration_fixes(const MeasurementSet& set, const std::vector<std::string>& keys) {
  const auto& rows = set.rows;
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].conditions.load_N < rows[lo].conditions.load_N) lo = i;
    if (rows[i].conditions.load_N > rows[hi].conditions.load_N) hi = i;
  }
  std::ostringstream s;
  s << "; the config calibrates";
  for (const auto& k : keys) s << " " << k;
  s << ": choose rows of " << set.path << " (e.g. its lightest and heaviest loads: --set "
    << "validation.calibration_rows=[" << rows[lo].row;
  if (hi != lo) s << "," << rows[hi].row;
  s << "])";
  if (!set.observables.empty()) {
    s << " and observables it has (--set validation.calibration_observables=[";
    for (std::size_t i = 0; i < set.observables.size(); ++i) {
      s << (i ? "," : "") << set.observables[i];
    }
    s << "])";
  }
  s << ", or predict every row without calibration: --set validation.calibrate=[]";
  return s.str();
}

}  // namespace

const std::vector<std::string>& validation_observables() {
  static const std::vector<std::string> names = {"sinking_mm", "length_mm", "width_mm"};
  return names;
}

bool rows_at_own_conditions(const MeasurementSet& set, const TyreConfig& config) {
  return !set.loads_only || conditions_act(config);
}

MeasurementSet read_validation_measurements(const std::string& path, const TyreConfig& config) {
  MeasurementSet set = read_measurements(path, config);
  for (const auto& r : set.rows)
    if (r.traction)
      throw InputError({path, r.line, "slip"},
                       "a traction row: validate compares footprints; traction tests go to "
                       "`discover` (docs/discover.md, \"Traction rows\")");
  bool compared = false;
  for (const auto& o : set.observables) {
    for (const auto& v : validation_observables()) compared = compared || o == v;
  }
  if (!compared) {
    throw InputError(
        {path, 1, "sinking_mm"},
        "no observable validate compares: give any of sinking_mm, length_mm, width_mm");
  }
  if (rows_at_own_conditions(set, config)) return set;
  // Rows at the config's conditions differ by their load only: one row per load.
  for (std::size_t i = 0; i < set.rows.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (set.rows[j].conditions.load_N == set.rows[i].conditions.load_N) {
        throw InputError({path, set.rows[i].line, "load_N"},
                         "duplicate load (same as line " + std::to_string(set.rows[j].line) + ")");
      }
    }
  }
  return set;
}

std::string range_bound_side(double value, double min, double max, bool log_scale) {
  const double span = log_scale ? std::log(max / min) : max - min;
  const double lo = log_scale ? std::log(value / min) : value - min;
  const double hi = log_scale ? std::log(max / value) : max - value;
  if (lo < 1e-3 * span) return "lower";
  if (hi < 1e-3 * span) return "upper";
  return "";
}

ValidationReport validate_footprints(const TyreConfig& base, const MeasurementSet& set) {
  const std::vector<MeasuredRow>& measured = set.rows;
  const std::string& config_path = base.source;
  const auto ident = config_modes(base);
  const auto& vs = base.validation;
  ValidationReport rep;
  Calibration& cal = rep.calibration;
  cal.keys = vs.calibrate;
  // Rows are calibration rows only when something is calibrated on them: with
  // `--set validation.calibrate=[]` every row is a prediction and counts.
  if (!cal.keys.empty()) cal.rows = vs.calibration_rows;
  cal.observables = vs.observables;
  std::vector<MeasuredRow> cal_rows;
  for (int r : cal.rows) {
    if (r < 1 || r > static_cast<int>(measured.size())) {
      throw InputError({config_path, 0, "validation.calibration_rows"},
                       "row " + std::to_string(r) + " does not exist in the measured file (" +
                           std::to_string(measured.size()) + " rows)" +
                           calibration_fixes(set, cal.keys));
    }
    cal_rows.push_back(measured[r - 1]);
  }
  std::vector<const ParameterSpec*> specs;
  for (const auto& key : cal.keys) {
    specs.push_back(&calibratable(key, config_path));
    cal.initial_values.push_back(specs.back()->get(base));
  }
  const auto& known = validation_observables();
  for (const auto& obs : cal.keys.empty() ? std::vector<std::string>{} : cal.observables) {
    if (std::find(known.begin(), known.end(), obs) == known.end()) {
      throw InputError(
          {config_path, 0, "validation.calibration_observables"},
          "'" + obs + "' cannot be fitted; choose from: sinking_mm, length_mm, width_mm");
    }
  }
  for (const auto& row : cal_rows) {
    for (const auto& obs : cal.observables) {
      if (!row.value(obs)) {
        const bool column =
            std::find(set.observables.begin(), set.observables.end(), obs) != set.observables.end();
        throw InputError({config_path, 0, "validation.calibration_observables"},
                         "calibration row " + std::to_string(row.row) + " has no " + obs +
                             (column ? " (the cell is empty or NA)"
                                     : " (" + set.path + " has no " + obs + " column)") +
                             calibration_fixes(set, cal.keys));
      }
    }
  }

  // The model at calibrated values: the config with the keys set as its reader sets them (no
  // YAML is read again), on the modes identified once.
  auto model_for = [&](const Eigen::VectorXd& log_values) {
    TyreConfig c = base;
    for (std::size_t k = 0; k < cal.keys.size(); ++k) {
      specs[k]->set(c, std::exp(log_values(static_cast<Eigen::Index>(k))));
    }
    return build_tyre_model(c, ident);
  };

  Eigen::VectorXd x(static_cast<Eigen::Index>(cal.keys.size()));
  for (std::size_t k = 0; k < cal.keys.size(); ++k) {
    x(static_cast<Eigen::Index>(k)) = std::log(cal.initial_values[k]);
  }
  if (!cal.keys.empty()) {
    // Parameters are positive: fit their logarithms (relative steps, no sign flips).
    const std::size_t n_res = cal_rows.size() * cal.observables.size();
    // The rows' stated noise (docs/uncertainty.md section 4): when every calibration residual
    // has a standard deviation > 0, each relative residual is divided by its relative std (a
    // chi-square fit); otherwise all weigh alike, as without the columns.
    std::vector<double> rel_sigma;
    cal.noise_weighted = true;
    for (const auto& row : cal_rows) {
      for (const auto& obs : cal.observables) {
        const auto it = row.observed_std.find(obs);
        if (it == row.observed_std.end() || !(it->second > 0)) {
          cal.noise_weighted = false;
        } else {
          rel_sigma.push_back(it->second / std::abs(*row.value(obs)));
        }
      }
    }
    if (!cal.noise_weighted) rel_sigma.assign(n_res, 1.0);
    auto residual = [&](const Eigen::VectorXd& lx) {
      // Outside the plausible range: a large residual makes the step fail instead of the model.
      for (std::size_t k = 0; k < cal.keys.size(); ++k) {
        const SearchRange& c = *specs[k]->calibration;
        const double v = std::exp(lx(static_cast<Eigen::Index>(k)));
        if (!(v >= c.min && v <= c.max)) {
          return Eigen::VectorXd::Constant(static_cast<Eigen::Index>(n_res), 1e6).eval();
        }
      }
      const auto res = predict_rows(model_for(lx), cal_rows);
      require_converged(res, "calibration");
      std::vector<double> r;
      for (std::size_t i = 0; i < cal_rows.size(); ++i) {
        for (const auto& obs : cal.observables) {
          r.push_back((res[i].observable(obs) / *cal_rows[i].value(obs) - 1.0) /
                      rel_sigma[r.size()]);
        }
      }
      return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())).eval();
    };
    solvers::LeastSquaresOptions lso;
    lso.relative_step = 1e-5;
    lso.step_tolerance = 1e-6;  // 1e-6 relative in each parameter is far below its meaning
    lso.cost_tolerance = 1e-8;
    const auto fit = solvers::levenberg_marquardt(residual, x, lso);
    x = fit.x;
    cal.status = fit.status;
    cal.evaluations = fit.evaluations;
    const Eigen::VectorXd rel_residual =
        fit.residual.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(
            rel_sigma.data(), static_cast<Eigen::Index>(rel_sigma.size())));
    cal.rms_rel_residual =
        rel_residual.size() ? std::sqrt(rel_residual.squaredNorm() / rel_residual.size()) : 0.0;
    for (std::size_t k = 0; k < cal.keys.size(); ++k) {
      const double v = std::exp(x(static_cast<Eigen::Index>(k)));
      const SearchRange& range = *specs[k]->calibration;
      cal.values.push_back(v);
      cal.at_bound.push_back(range_bound_side(v, range.min, range.max, true));  // log-fitted
    }
    if (cal.rms_rel_residual > 1e3) {
      throw ComputationError("calibration found no parameters within their plausible ranges");
    }
    set_covariance(cal, residual, x, fit.residual);
  }
  rep.model = model_for(x);
  const auto predicted = predict_rows(rep.model, measured);
  require_converged(predicted, "validation");
  for (const auto& p : predicted) rep.footprints.push_back(p.footprint);
  rep.with_conditions = rows_at_own_conditions(set, base);

  const std::set<int> cal_set(cal.rows.begin(), cal.rows.end());
  std::map<std::string, double> sq;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    ValidationRow row;
    row.measured = measured[i];
    row.calibration = cal_set.count(measured[i].row) > 0;
    row.sinking_mm = predicted[i].sinking_mm;
    row.length_mm = predicted[i].length_mm;
    row.width_mm = predicted[i].width_mm;
    auto rel_error = [&](const std::string& obs) -> std::optional<double> {
      const auto m = row.measured.value(obs);
      if (!m) return std::nullopt;
      const double e = predicted[i].observable(obs) / *m - 1;
      if (!row.calibration) {
        sq[obs] += e * e;
        ++rep.predicted_rows[obs];
      }
      return e;
    };
    row.sinking_rel_error = rel_error("sinking_mm");
    row.length_rel_error = rel_error("length_mm");
    row.width_rel_error = rel_error("width_mm");
    rep.rows.push_back(row);
  }
  for (const auto& [obs, s] : sq) rep.rms_rel_error[obs] = std::sqrt(s / rep.predicted_rows[obs]);
  return rep;
}

}  // namespace modaltyre::studies
