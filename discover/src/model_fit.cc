#include "modaltyre/discover/model_fit.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "modaltyre/contact/parameter_spec.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/levenberg_marquardt.h"
#include "modaltyre/studies/traction_rows.h"
#include "modaltyre/studies/validation.h"

namespace modaltyre::discover {
namespace {

using contact::EffectId;
using contact::TyreConfig;

constexpr double kNoiseFloor = 1e-4;
constexpr double kFailureResidual = 1.0;

// A fitted parameter from its specification (parameter_spec.h): discover's search range and
// transform, the config accessors.
FreeParameter make_parameter(const std::string& key) {
  const contact::ParameterSpec* spec = contact::find_parameter(key);
  MODALTYRE_CHECK(spec && spec->fit, "discover: " + key + " has no fit range");
  FreeParameter p;
  p.key = key;
  p.min = spec->fit->min;
  p.max = spec->fit->max;
  p.log_scale = spec->fit->transform == contact::SearchTransform::log_logistic;
  p.get = spec->get;
  p.set = spec->set;
  return p;
}

std::vector<double> values_of(const std::vector<FreeParameter>& ps, const Eigen::VectorXd& u) {
  std::vector<double> v(ps.size());
  for (std::size_t i = 0; i < ps.size(); ++i) v[i] = from_search(ps[i], u(static_cast<int>(i)));
  return v;
}

}  // namespace

// Bounded transform: value = lo + (hi - lo) sigma(u) (in ln value when log_scale).
double from_search(const FreeParameter& p, double u) {
  const double s = 1.0 / (1.0 + std::exp(-u));
  if (p.log_scale) return std::exp(std::log(p.min) + (std::log(p.max) - std::log(p.min)) * s);
  return p.min + (p.max - p.min) * s;
}

double to_search(const FreeParameter& p, double value) {
  double s = p.log_scale ? (std::log(value) - std::log(p.min)) / (std::log(p.max) - std::log(p.min))
                         : (value - p.min) / (p.max - p.min);
  s = std::clamp(s, 1e-6, 1 - 1e-6);
  return std::log(s / (1 - s));
}

double search_derivative(const FreeParameter& p, double u) {
  const double s = 1.0 / (1.0 + std::exp(-u));
  const double ds = s * (1 - s);
  if (p.log_scale) return from_search(p, u) * (std::log(p.max) - std::log(p.min)) * ds;
  return (p.max - p.min) * ds;
}

std::vector<FreeParameter> baseline_parameters(const TyreConfig& config) {
  std::vector<FreeParameter> out = {make_parameter("modal.compliance_scale")};
  if (config.footprint_3d && (config.footprint_3d->crown.shape == contact::CrownShape::circular ||
                              config.footprint_3d->crown.shape == contact::CrownShape::power)) {
    // The 3D patch's second scalar: its crown radius, circular or power crown (the tread modulus
    // is a sourced compound value there, not an effective layer).
    out.push_back(make_parameter("footprint_3d.crown.radius_mm"));
  } else {
    out.push_back(make_parameter("tread.modulus_MPa"));
  }
  return out;
}

std::vector<FreeParameter> effect_parameters(EffectId id) {
  const contact::EffectInfo& info = contact::effect_info(id);
  std::vector<FreeParameter> out;
  for (const auto& p : info.parameters) {
    if (!p.fitted) continue;
    FreeParameter fp = make_parameter(info.key(p));
    fp.of_effect = true;
    fp.effect = id;
    fp.catalogue_default = p.default_value;
    out.push_back(std::move(fp));
  }
  return out;
}

std::string Variant::name() const {
  if (effects.empty()) return "baseline";
  std::string n;
  for (auto id : effects) n += (n.empty() ? "" : "+") + contact::effect_info(id).name;
  return n;
}

Variant make_variant(const TyreConfig& config, const std::vector<EffectId>& effects) {
  Variant v;
  v.effects = effects;
  v.parameters = baseline_parameters(config);
  for (auto id : effects) {
    for (auto& p : effect_parameters(id)) v.parameters.push_back(std::move(p));
  }
  return v;
}

TyreConfig apply(const TyreConfig& base, const Variant& v, const std::vector<double>& values) {
  TyreConfig c = base;
  for (auto id : v.effects) contact::enable_effect(c, id);
  for (std::size_t i = 0; i < v.parameters.size(); ++i) v.parameters[i].set(c, values[i]);
  return c;
}

Evaluator::Evaluator(const contact::TyreModel& model, const studies::MeasurementSet& data,
                     const FlexingLoss& flexing)
    : model_(model), data_(data) {
  if (data.traction_rows() > 0)
    traction_ = std::make_shared<const TractionRows>(model.config, data, flexing);
}

std::map<int, contact::TractionResult> Evaluator::traction(
    const TyreConfig& config, const std::vector<int>& rows,
    const modal::ModeIdentification* modes) const {
  if (!traction_) return {};
  return traction_->predict(config, rows, threads_ > 0 ? threads_ : omp_get_max_threads(), modes);
}

std::vector<Evaluator::Entry> Evaluator::entries(const std::vector<int>& rows) const {
  std::vector<Entry> out;
  for (int r : rows) {
    for (std::size_t o = 0; o < data_.observables.size(); ++o) {
      const auto it = data_.rows[r].observed.find(data_.observables[o]);
      // A zero carries no relative information; a traction row's pull and torque are taken
      // against a floor (traction_evidence.h) and keep it.
      if (it != data_.rows[r].observed.end() &&
          (it->second != 0 || studies::is_traction_observable(it->first))) {
        out.push_back({r, static_cast<int>(o)});
      }
    }
  }
  return out;
}

std::vector<double> Evaluator::residuals(const TyreConfig& config, const std::vector<Entry>& e,
                                         int& failures) const {
  std::vector<std::size_t> starts;  // first entry of each row's group
  for (std::size_t i = 0; i < e.size(); ++i) {
    if (i == 0 || e[i].row != e[i - 1].row) starts.push_back(i);
  }
  starts.push_back(e.size());
  const int groups = static_cast<int>(starts.size()) - 1;
  const contact::TyreParameters parameters = contact::parameters_of(config);
  std::vector<int> rows;
  for (int g = 0; g < groups; ++g) rows.push_back(e[starts[g]].row);
  const std::map<int, contact::TractionResult> tr = traction(config, rows);
  const double R0 = config.outer_radius_m;
  std::vector<double> out(e.size());
  int failed = 0, footprints = 0;
  const int threads = threads_ > 0 ? threads_ : omp_get_max_threads();
  // Rows in parallel only at the top level (a candidate's fit inside discover's parallel loop
  // runs its rows in order) and when there are enough of them to pay for the threads.
#pragma omp parallel for num_threads(threads) schedule(dynamic, 4) \
    reduction(+ : failed, footprints) if (groups >= 16 && !omp_in_parallel())
  for (int g = 0; g < groups; ++g) {
    const int row = e[starts[g]].row;
    const auto& mr = data_.rows[row];
    contact::Prediction p;
    const contact::TractionResult* t = mr.traction ? &tr.at(row) : nullptr;
    if (!t) p = contact::predict(model_, parameters, mr.conditions), ++footprints;
    const bool ok = t ? t->ok() : p.ok();
    if (!ok) ++failed;
    for (std::size_t i = starts[g]; i < starts[g + 1]; ++i) {
      const std::string& obs = data_.observables[e[i].observable];
      const double meas = mr.observed.at(obs);
      const double model = !ok ? 0 : t ? traction_observable(*t, obs) : p.observable(obs);
      out[i] = ok ? (model - meas) / residual_scale(mr, obs, meas, R0) : kFailureResidual;
    }
  }
  predictions_.fetch_add(footprints, std::memory_order_relaxed);
  failures = failed;
  return out;
}

double bic(const std::vector<Evaluator::Entry>& entries, const std::vector<double>& residuals,
           int observables, int k) {
  std::vector<double> rss(observables, 0.0);
  std::vector<int> n(observables, 0);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    rss[entries[i].observable] += residuals[i] * residuals[i];
    ++n[entries[i].observable];
  }
  double b = 0;
  int total = 0;
  for (int o = 0; o < observables; ++o) {
    if (n[o] == 0) continue;
    b += n[o] * std::log(std::max(rss[o] / n[o], kNoiseFloor * kNoiseFloor));
    total += n[o];
  }
  return b + k * std::log(static_cast<double>(std::max(total, 1)));
}

std::map<std::string, double> rms_by_observable(const studies::MeasurementSet& data,
                                                const std::vector<Evaluator::Entry>& entries,
                                                const std::vector<double>& residuals) {
  std::map<std::string, double> sum;
  std::map<std::string, int> n;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const auto& o = data.observables[entries[i].observable];
    sum[o] += residuals[i] * residuals[i];
    ++n[o];
  }
  for (auto& kv : sum) kv.second = std::sqrt(kv.second / n[kv.first]);
  return sum;
}

namespace {

double rms_of(const std::vector<double>& r) {
  if (r.empty()) return 0;
  double s = 0;
  for (double x : r) s += x * x;
  return std::sqrt(s / static_cast<double>(r.size()));
}

}  // namespace

Eigen::MatrixXd jacobian(const Evaluator& ev, const TyreConfig& base, const Variant& v,
                         const std::vector<double>& values,
                         const std::vector<Evaluator::Entry>& entries) {
  const int k = static_cast<int>(v.parameters.size());
  const int m = static_cast<int>(entries.size());
  Eigen::MatrixXd J(m, k);
  for (int j = 0; j < k; ++j) {
    const auto& p = v.parameters[j];
    const double h = 1e-4 * std::max(std::abs(values[j]), 1e-3 * (p.max - p.min));
    std::vector<double> up = values, down = values;
    up[j] = std::min(up[j] + h, p.max);
    down[j] = std::max(down[j] - h, p.min);
    const auto ru = ev.residuals(apply(base, v, up), entries);
    const auto rd = ev.residuals(apply(base, v, down), entries);
    for (int i = 0; i < m; ++i) J(i, j) = (ru[i] - rd[i]) / (up[j] - down[j]);
  }
  return J;
}

Eigen::MatrixXd weighted_read_columns(const studies::MeasurementSet& data, const FitResult& fr,
                                      const Eigen::MatrixXd& jacobian, std::vector<int>& read,
                                      Eigen::VectorXd* row_weights) {
  const int k = static_cast<int>(jacobian.cols());
  std::vector<double> sigma(data.observables.size(), 1.0);
  for (std::size_t o = 0; o < sigma.size(); ++o) {
    const auto it = fr.rms.find(data.observables[o]);
    if (it != fr.rms.end()) sigma[o] = std::max(it->second, 1e-4);
  }
  // A parameter no row reads (its column exactly zero: e.g. the baseline's tyre scalars under
  // traction rows of the rigid wheel, tyre.rigid=true) is not identified; it must not make the
  // others unidentified too, so the information matrix is formed over the columns the rows read.
  read.clear();
  for (int j = 0; j < k; ++j)
    if (jacobian.rows() > 0 && jacobian.col(j).cwiseAbs().maxCoeff() > 0) read.push_back(j);
  Eigen::MatrixXd J(jacobian.rows(), static_cast<Eigen::Index>(read.size()));
  for (std::size_t j = 0; j < read.size(); ++j)
    J.col(static_cast<Eigen::Index>(j)) = jacobian.col(read[j]);
  if (row_weights) row_weights->resize(J.rows());
  for (Eigen::Index i = 0; i < J.rows(); ++i) {
    J.row(i) /= sigma[fr.entries[i].observable];
    if (row_weights) (*row_weights)(i) = 1 / sigma[fr.entries[i].observable];
  }
  return J;
}

std::vector<double> standard_errors(const studies::MeasurementSet& data, const FitResult& fr,
                                    const Eigen::MatrixXd& jacobian) {
  const int k = static_cast<int>(jacobian.cols());
  std::vector<int> read;  // an unread parameter keeps an infinite error
  const Eigen::MatrixXd J = weighted_read_columns(data, fr, jacobian, read);
  const int kr = static_cast<int>(read.size());
  std::vector<double> se(k, std::numeric_limits<double>::infinity());
  if (kr == 0) return se;
  const Eigen::MatrixXd info = J.transpose() * J;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(info);
  if (cod.rank() < kr) return se;  // not identifiable: infinite uncertainty
  const Eigen::MatrixXd cov = cod.pseudoInverse();
  for (int j = 0; j < kr; ++j) se[read[j]] = std::sqrt(std::max(cov(j, j), 0.0));
  return se;
}

FitResult evaluate_fit(const Evaluator& ev, const TyreConfig& base, const Variant& v,
                       const std::vector<double>& values,
                       const std::vector<Evaluator::Entry>& entries) {
  FitResult fr;
  fr.values = values;
  fr.config = apply(base, v, fr.values);
  fr.entries = entries;
  fr.residuals = ev.residuals(fr.config, entries, fr.failures);
  fr.rms = rms_by_observable(ev.data(), entries, fr.residuals);
  fr.rms_all = rms_of(fr.residuals);
  fr.bic = bic(entries, fr.residuals, static_cast<int>(ev.data().observables.size()),
               static_cast<int>(v.parameters.size()));
  fr.evaluations = 1;
  return fr;
}

namespace {
// Whether a re-fitted baseline scalar (not an effect's parameter) lies at a bound of its range.
bool scalar_at_bound(const std::vector<FreeParameter>& ps, const Eigen::VectorXd& u) {
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps[i].of_effect) continue;
    const double x = from_search(ps[i], u(Eigen::Index(i)));
    if (!studies::range_bound_side(x, ps[i].min, ps[i].max, ps[i].log_scale).empty()) return true;
  }
  return false;
}
}  // namespace

FitResult fit_variant(const Evaluator& ev, const TyreConfig& base, const Variant& v,
                      const std::vector<int>& rows, std::optional<std::span<const double>> start,
                      bool with_errors) {
  const auto entries = ev.entries(rows);
  const auto& ps = v.parameters;
  const int k = static_cast<int>(ps.size());
  int evaluations = 0;
  auto residual = [&](const Eigen::VectorXd& u) {
    ++evaluations;
    const auto r = ev.residuals(apply(base, v, values_of(ps, u)), entries);
    return Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<int>(r.size())).eval();
  };

  solvers::LeastSquaresOptions opt;
  opt.max_iterations = 60;
  opt.relative_step = 1e-5;
  opt.step_tolerance = 1e-7;
  Eigen::VectorXd u0(k);
  std::vector<int> fresh;      // parameters of effects base does not have on
  Eigen::VectorXd configured;  // the tyre's scalars as configured, the new effect at default
  if (start) {
    for (int i = 0; i < k; ++i) u0(i) = to_search(ps[i], (*start)[i]);
  } else {
    // Baseline scalars from the config; effect parameters from the default.
    for (int i = 0; i < k; ++i) {
      const bool is_new = ps[i].of_effect && !contact::effect_enabled(base, ps[i].effect);
      u0(i) = to_search(ps[i], is_new ? ps[i].catalogue_default : ps[i].get(base));
      if (is_new) fresh.push_back(i);
    }
    // The tyre as the user's config calibrates it (base is the current model's fit), the new
    // effect at its default.
    configured = u0;
    for (int i = 0; i < k; ++i)
      if (!ps[i].of_effect) configured(i) = to_search(ps[i], ps[i].get(ev.model().config));
  }
  // Short searches from each start; the best one is refined.
  auto scout_from = [&](const std::vector<Eigen::VectorXd>& starts) {
    solvers::LeastSquaresOptions scout;
    scout.max_iterations = 8;
    scout.relative_step = 1e-5;
    double best = -1;
    Eigen::VectorXd best_u = starts.front();
    for (const auto& u : starts) {
      const auto trial = solvers::levenberg_marquardt(residual, u, scout);
      if (best < 0 || trial.cost < best) best = trial.cost, best_u = trial.x;
    }
    return best_u;
  };
  if (!fresh.empty()) {
    // A new effect's parameters may start where the effect is negligible (a flat direction a
    // local search cannot leave) or far from the basin the re-fitted baseline scalars need:
    // short searches from the default and from every corner 2.5 units away in the transformed
    // variables (1 + 2^n starts).
    std::vector<Eigen::VectorXd> starts = {u0};
    for (int c = 0; c < 1 << fresh.size(); ++c) {
      starts.push_back(u0);
      for (std::size_t j = 0; j < fresh.size(); ++j)
        starts.back()(fresh[j]) += (c >> j & 1) ? 2.5 : -2.5;
    }
    u0 = scout_from(starts);
  }
  auto lm = solvers::levenberg_marquardt(residual, u0, opt);
  // Whether the new effect's strength (its first fitted parameter, as detection_limit.h's) ended
  // at the bound of its range where the effect is strongest: at the bound where it vanishes the
  // data ask for none of it (every candidate of a noise-only set), at the other the effect may
  // saturate an observable over much of the range.
  const auto at_strong_bound = [&](const Eigen::VectorXd& u) {
    if (fresh.empty()) return false;
    const FreeParameter& p = ps[fresh.front()];
    const std::string side =
        studies::range_bound_side(from_search(p, u(fresh.front())), p.min, p.max, p.log_scale);
    if (side.empty()) return false;
    const contact::EffectInfo& info = contact::effect_info(p.effect);
    if (info.strength == contact::EffectStrength::inverse) return side == "lower";
    if (info.strength == contact::EffectStrength::from_neutral && info.neutral <= p.min)
      return side == "upper";
    if (info.strength == contact::EffectStrength::from_neutral && info.neutral >= p.max)
      return side == "lower";
    return true;  // a neutral value inside the range, or no strength: both bounds
  };
  if (at_strong_bound(lm.x)) {
    // Ended at a bound of the new effect's range where it is strongest: no value located. The
    // cost can be flat over much of the range with a narrow basin elsewhere (the lateral belt's
    // foundation on twelve SF-350 footprints: profile RMS 2.7 % from 10 to 250 MPa/m, 1.2 % at
    // 300-500), and the default and its corners can all lie on the plateau: scout the strength
    // parameter's whole transformed range too (u = -4 ... 4, the range's 2 % to 98 % points)
    // and keep the better refined fit.
    std::vector<Eigen::VectorXd> starts;
    for (double u : {-4.0, -2.0, 0.0, 2.0, 4.0}) {
      starts.push_back(lm.x);
      for (int i : fresh) starts.back()(i) = to_search(ps[i], ps[i].catalogue_default);
      starts.back()(fresh.front()) = u;
    }
    const auto other = solvers::levenberg_marquardt(residual, scout_from(starts), opt);
    if (other.cost < lm.cost) lm = other;
  }

  if (!fresh.empty() && scalar_at_bound(ps, lm.x)) {
    // A re-fitted tyre scalar ended at a bound of its range (the soil's Wong-Reece set on the
    // default: the carcass 20x stiffer at compliance_scale 0.05, c1 at its own bound): the search
    // may have bent the tyre to the new effect's start rather than found the effect. Fit the
    // effect alone on the tyre as the user's config has it first, then release the scalars from
    // there; the better of the two fits is kept.
    auto alone = [&](const Eigen::VectorXd& uf) {
      Eigen::VectorXd u = configured;
      for (std::size_t j = 0; j < fresh.size(); ++j) u(fresh[j]) = uf(Eigen::Index(j));
      return residual(u);
    };
    Eigen::VectorXd uf(static_cast<Eigen::Index>(fresh.size()));
    for (std::size_t j = 0; j < fresh.size(); ++j) uf(Eigen::Index(j)) = configured(fresh[j]);
    const auto first = solvers::levenberg_marquardt(alone, uf, opt);
    Eigen::VectorXd from = configured;
    for (std::size_t j = 0; j < fresh.size(); ++j) from(fresh[j]) = first.x(Eigen::Index(j));
    const auto other = solvers::levenberg_marquardt(residual, from, opt);
    if (other.cost < lm.cost) lm = other;
  }

  FitResult fr = evaluate_fit(ev, base, v, values_of(ps, lm.x), entries);
  fr.evaluations += evaluations;
  if (with_errors) {
    fr.jacobian = jacobian(ev, base, v, fr.values, entries);
    fr.standard_errors = standard_errors(ev.data(), fr, fr.jacobian);
  }
  fr.status = lm.status;
  return fr;
}

CrossValidation cross_validate(const Evaluator& ev, const TyreConfig& base, const Variant& v,
                               const FitResult& full) {
  const int n = static_cast<int>(ev.data().rows.size());
  CrossValidation cv;
  cv.folds = n <= 8 ? n : 6;
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  cv.entries = ev.entries(all);
  cv.residuals.assign(cv.entries.size(), 0.0);
  std::map<std::pair<int, int>, std::size_t> slot;  // (row, observable) -> index in cv.entries
  for (std::size_t j = 0; j < cv.entries.size(); ++j) {
    slot[{cv.entries[j].row, cv.entries[j].observable}] = j;
  }
  for (int f = 0; f < cv.folds; ++f) {
    std::vector<int> train, test;
    for (int r = 0; r < n; ++r) (r % cv.folds == f ? test : train).push_back(r);
    const FitResult fit = fit_variant(ev, base, v, train, full.values);
    cv.evaluations += fit.evaluations;
    cv.fold_values.push_back(fit.values);
    const auto test_entries = ev.entries(test);
    const auto r = ev.residuals(fit.config, test_entries);
    for (std::size_t i = 0; i < test_entries.size(); ++i) {
      cv.residuals[slot.at({test_entries[i].row, test_entries[i].observable})] = r[i];
    }
  }
  cv.rms = rms_by_observable(ev.data(), cv.entries, cv.residuals);
  cv.rms_all = rms_of(cv.residuals);
  return cv;
}

}  // namespace modaltyre::discover
