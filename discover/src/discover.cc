#include "modaltyre/discover/discover.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <set>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/core/thread_env.h"
#include "modaltyre/solvers/correlation.h"
#include "modaltyre/studies/traction_rows.h"
#include "modaltyre/studies/validation.h"

namespace modaltyre::discover {
namespace {

using contact::EffectId;
using contact::TyreConfig;
using studies::MeasurementSet;

std::string percent(double rel) {
  std::ostringstream s;
  s.precision(3);
  s << 100 * rel << " %";
  return s.str();
}

std::size_t distinct(const MeasurementSet& d, const std::string& condition) {
  std::set<double> v;
  for (const auto& r : d.rows) v.insert(studies::condition_value(r.conditions, condition));
  return v.size();
}

// Whether the data can reveal an effect: its regime variable must vary (an effect acting as a
// constant factor is confounded with the re-fitted baseline scalars).
// Traction rows are evidence for the effects that act on soil runs (traction_evidence.h), each
// through the slip: testable when the slip varies among them. Footprint rows are evidence for
// the others (and for a soil effect through its regime variable, as before).
std::string untestable_reason(EffectId id, const MeasurementSet& d, const TyreConfig& config) {
  const auto& info = contact::effect_info(id);
  const std::string refusal = contact::effect_refusal(config, id);
  if (!refusal.empty()) return refusal;
  const bool soil = acts_on_soil_runs(info);
  std::string traction_reason;
  if (d.traction_rows() > 0) {
    std::set<double> slips;
    for (const auto& r : d.rows)
      if (r.traction) slips.insert(r.traction->slip);
    if (soil && slips.size() >= 2) return "";
    traction_reason = soil ? "the slip does not vary in the traction rows"
                           : "acts on footprints only, not on traction runs";
    if (d.footprint_rows() == 0) return traction_reason;
  }
  const std::string& regime = condition_info(info.regime).name;
  const std::size_t n = distinct(d, regime);
  std::string reason;
  if (info.regime == ConditionId::load_N) {
    // A load law needs a trend, not only a level the re-fitted scalars absorb.
    reason = n >= 3 ? "" : "needs at least 3 distinct loads";
  } else if (id == EffectId::rolling_speed) {
    bool rolling = false;
    for (const auto& r : d.rows) rolling = rolling || (!r.traction && r.conditions.speed_kmh > 0);
    reason = rolling ? "" : "no row is rolling (speed_kmh > 0)";
  } else {
    reason = n >= 2 ? "" : regime + " does not vary in the data";
  }
  return reason.empty() || traction_reason.empty() ? reason : reason + "; " + traction_reason;
}

struct Stage {
  Variant variant;
  FitResult fit;
  CrossValidation cv;
};

std::map<std::string, double> named_values(const Variant& v, const std::vector<double>& values,
                                           bool effects_only) {
  std::map<std::string, double> out;
  for (std::size_t i = 0; i < v.parameters.size(); ++i) {
    if (effects_only && !v.parameters[i].of_effect) continue;
    out[v.parameters[i].key] = values[i];
  }
  return out;
}

double row_variable(const studies::MeasuredRow& row, const std::string& var) {
  return var == "slip" && row.traction ? row.traction->slip
                                       : studies::condition_value(row.conditions, var);
}

std::vector<RegimeFinding> locate(const MeasurementSet& d, const FitResult& base) {
  std::vector<RegimeFinding> out;
  std::vector<std::string> vars;
  for (const auto& c : studies::condition_names()) {
    if (distinct(d, c) >= 2) vars.push_back(c);
  }
  for (std::size_t o = 0; o < d.observables.size(); ++o) {
    std::vector<double> res;
    std::vector<int> rows;
    for (std::size_t i = 0; i < base.entries.size(); ++i) {
      if (base.entries[i].observable == static_cast<int>(o)) {
        res.push_back(base.residuals[i]);
        rows.push_back(base.entries[i].row);
      }
    }
    if (res.size() < 3) continue;
    RegimeFinding f;
    f.observable = d.observables[o];
    f.mean_residual = std::accumulate(res.begin(), res.end(), 0.0) / res.size();
    // A traction observable's rows are traction rows: their slip is a variable too.
    std::vector<std::string> its_vars = vars;
    if (studies::is_traction_observable(f.observable) &&
        std::find(vars.begin(), vars.end(), "slip") == vars.end())
      its_vars.push_back("slip");
    for (const auto& var : its_vars) {
      std::vector<double> x;
      for (int r : rows) x.push_back(row_variable(d.rows[r], var));
      const double r = solvers::pearson_correlation(x, res);
      if (std::abs(r) > std::abs(f.correlation)) f.correlation = r, f.variable = var;
    }
    std::ostringstream s;
    s.precision(2);
    s << f.observable << ": ";
    if (f.variable.empty()) {
      s << "no condition varies; mean residual " << percent(f.mean_residual);
    } else {
      const bool categorical = f.variable == "branch" || f.variable == "surface";
      s << "predicted minus measured " << (f.correlation > 0 ? "rises" : "falls");
      if (categorical) {
        s << " from " << (f.variable == "branch" ? "load to unload" : "rigid to soil") << " rows";
      } else {
        s << " as " << f.variable << " grows";
      }
      s << " (r = " << std::fixed << f.correlation << ")";
    }
    f.summary = s.str();
    out.push_back(f);
  }
  std::sort(out.begin(), out.end(), [](const RegimeFinding& a, const RegimeFinding& b) {
    return std::abs(a.correlation) > std::abs(b.correlation);
  });
  return out;
}

std::vector<int> worst_rows(const MeasurementSet& d, const FitResult& fit) {
  std::vector<double> sum(d.rows.size(), 0.0);
  std::vector<int> n(d.rows.size(), 0);
  for (std::size_t i = 0; i < fit.entries.size(); ++i) {
    sum[fit.entries[i].row] += fit.residuals[i] * fit.residuals[i];
    ++n[fit.entries[i].row];
  }
  std::vector<int> idx(d.rows.size());
  std::iota(idx.begin(), idx.end(), 0);
  auto score = [&](int r) { return n[r] ? sum[r] / n[r] : 0.0; };
  std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) { return score(a) > score(b); });
  std::vector<int> out;
  for (std::size_t i = 0; i < idx.size() && i < 3; ++i) out.push_back(d.rows[idx[i]].row);
  return out;
}

void fill_rows(const MeasurementSet& d, const Stage& before, const Stage& after,
               std::vector<RowResidual>& rows) {
  rows.assign(d.rows.size(), {});
  for (std::size_t r = 0; r < d.rows.size(); ++r) rows[r].row = d.rows[r].row;
  auto put = [&](const std::vector<Evaluator::Entry>& e, const std::vector<double>& res,
                 std::map<std::string, double> RowResidual::*field) {
    for (std::size_t i = 0; i < e.size(); ++i) {
      (rows[e[i].row].*field)[d.observables[e[i].observable]] = res[i];
    }
  };
  put(before.fit.entries, before.fit.residuals, &RowResidual::before);
  put(after.fit.entries, after.fit.residuals, &RowResidual::after);
  put(before.cv.entries, before.cv.residuals, &RowResidual::cv_before);
  put(after.cv.entries, after.cv.residuals, &RowResidual::cv_after);
}

// Detection limits (issue 23) of every testable candidate of the last round that the final
// model does not carry, against the final model; when the last round named nothing, the rows
// that would bring the candidate most likely to be named at its default over its limit.
void add_detection_limits(const Evaluator& ev, const Stage& current, const NamingRule& rule,
                          const DiscoverOptions& opt, int threads,
                          const std::function<std::function<void()>(int)>& phase,
                          DiscoverReport& rep) {
  auto& last = rep.rounds.back();
  std::vector<int> unnamed;
  std::vector<EffectId> ids;
  for (int c = 0; c < static_cast<int>(last.size()); ++c) {
    const contact::EffectInfo* info = contact::find_effect(last[c].name);
    const auto& on = current.variant.effects;
    if (!last[c].testable || !info || std::find(on.begin(), on.end(), info->id) != on.end())
      continue;
    unnamed.push_back(c);
    ids.push_back(info->id);
  }
  const LimitFinder finder(ev, current.fit.config, current.variant, current.fit, rule, opt.limits);
  const int n = static_cast<int>(unnamed.size());
  const auto tick = phase(n);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
  for (int t = 0; t < n; ++t) {
    // The side below a neutral value inside the strength's range (crown_shape's n < 2) where the
    // candidate's own fit lies there (the side the data lean to), on the exact procedure's rows
    // as the profile bands (above them the approximations keep their cost: one side).
    const auto strength = effect_parameters(ids[t]);
    const auto& fitted = last[unnamed[t]].parameters;
    const auto it = strength.empty() ? fitted.end() : fitted.find(strength.front().key);
    const bool below = static_cast<int>(ev.data().rows.size()) <= opt.fit.exact_rows &&
                       it != fitted.end() && it->second < contact::effect_info(ids[t]).neutral;
    last[unnamed[t]].limit = finder.limit(ids[t], below);
    tick();
  }
  if (rep.effects.size() >= rep.rounds.size() || n == 0) return;  // the last round named one
  int best = -1;
  for (int t = 0; t < n; ++t) {
    const DetectionLimit& l = last[unnamed[t]].limit;
    if (l.parameter.empty() || l.reason.rfind("no value", 0) == 0) continue;
    if (best < 0 || l.power_at_default > last[unnamed[best]].limit.power_at_default) best = t;
  }
  if (best < 0) return;
  MoreRows& m = rep.more_rows;
  m.effect = last[unnamed[best]].name;
  m.condition = condition_info(contact::effect_info(ids[best]).regime).name;
  m.power_at_default = last[unnamed[best]].limit.power_at_default;
  m.replicas = finder.replicas_for_default(ids[best]);
  const int rows = static_cast<int>(ev.data().rows.size());
  m.extra_rows = m.replicas > 0 ? (m.replicas - 1) * rows : 0;
  std::ostringstream s;
  s << m.effect << " at its catalogue default would be named with probability "
    << std::lround(100 * m.power_at_default) << " % on these rows; ";
  if (m.replicas == 1) {
    s << "no more rows are needed for 80 %";
  } else if (m.replicas > 1) {
    s << m.extra_rows << " more rows at this noise (the " << rows << " rows' " << m.condition
      << " levels repeated " << m.replicas << " times in all) would name it with 80 %";
  } else {
    s << "repeating the rows " << opt.limits.max_replicas << " times at this noise would not "
      << "reach 80 %: widen the range of " << m.condition << " or measure more precisely";
  }
  m.text = s.str();
}

// A named parameter's band: its profile likelihood's (profile_band.h) on the exact procedure's
// rows, the Gauss-Newton one (value +- 2 standard errors, within the range) above them.
ParameterBand named_band(const Evaluator& ev, const TyreConfig& base, const Stage& chosen,
                         const std::vector<int>& rows, const DiscoverOptions& opt, int i) {
  if (static_cast<int>(rows.size()) <= opt.fit.exact_rows)
    return profile_band(ev, base, chosen.variant, chosen.fit, rows, i);
  const FreeParameter& p = chosen.variant.parameters[i];
  const double x = chosen.fit.values[i], se = chosen.fit.standard_errors[i];
  ParameterBand b;
  b.lower = std::max(x - 2 * se, p.min), b.upper = std::min(x + 2 * se, p.max);
  b.lower_at_bound = !(x - 2 * se > p.min), b.upper_at_bound = !(x + 2 * se < p.max);
  return b;
}

// The rows evaluated on half the evaluation unit length, for the mesh shift.
struct FineMesh {
  double unit_length_m = 0;
  std::unique_ptr<const contact::TyreModel> model;
  std::unique_ptr<const Evaluator> ev;
};

MeshBias named_mesh_bias(const Evaluator& ev, std::optional<FineMesh>& fine, const TyreConfig& base,
                         const Stage& chosen, const DiscoverOptions& opt, int threads) {
  const TyreConfig& eval = ev.model().config;
  const double h = 0.5 * ev.model().unit_length_m;
  MeshBias none;
  none.unit_length_mm = 1e3 * ev.model().unit_length_m;
  none.fine_unit_length_mm = 1e3 * h;
  if (!(eval.mesh.window_m / h <= 20000)) {  // the config reader's limit on the units
    none.note = "half the unit length would exceed 20000 candidate units: no mesh shift";
    return none;
  }
  // A check after the fit: whatever the fine mesh refuses or fails becomes its note, never the
  // run's error (the report above it stands).
  try {
    if (!fine) {
      TyreConfig c = eval;
      c.mesh.unit_length_m = h;
      FineMesh f;
      f.unit_length_m = h;
      f.model = std::make_unique<const contact::TyreModel>(contact::build_tyre_model(c));
      auto fine_ev = std::make_unique<Evaluator>(*f.model, ev.data(), opt.traction_flexing);
      fine_ev->set_threads(threads);
      f.ev = std::move(fine_ev);
      fine = std::move(f);
    }
    return mesh_bias(ev, *fine->ev, h, base, chosen.variant, chosen.fit);
  } catch (const std::exception& e) {
    none.note =
        std::string("the half mesh could not be evaluated (") + e.what() + "): no mesh shift";
    return none;
  }
}

std::string number_text(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

}  // namespace

void DiscoverOptions::validate() const {
  auto refuse = [](const char* option, const char* key, const std::string& why) {
    throw InputError({option, 0, key}, why);
  };
  auto range = [](double v, double lo, double hi) {
    std::ostringstream s;
    s << "value " << v << " is out of range [" << lo << ", " << hi << "]";
    return s.str();
  };
  if (!std::isfinite(unit_length_mm)) {
    refuse("--unit-length-mm", "unit_length_mm", "must be a finite number");
  }
  if (unit_length_mm < 0 || unit_length_mm > 50) {
    refuse("--unit-length-mm", "unit_length_mm", range(unit_length_mm, 0, 50));
  }
  if (max_effects < 1 || max_effects > 9) {
    refuse("--max-effects", "max_effects", range(max_effects, 1, 9));
  }
  if (threads < 0 || threads > 4096) refuse("--threads", "threads", range(threads, 0, 4096));
  if (fit.exact_rows < 4) refuse("--exact-rows", "exact_rows", range(fit.exact_rows, 4, 1e6));
}

DiscoverReport discover(const TyreConfig& config, const MeasurementSet& data,
                        const DiscoverOptions& opt) {
  opt.validate();
  if (data.rows.size() < 4) {
    throw InputError({data.path, 0, "load_N"},
                     "discover needs at least 4 measured rows (" +
                         std::to_string(data.rows.size()) +
                         " given): fewer cannot be "
                         "cross-validated against a 2-parameter baseline");
  }
  if (static_cast<int>(data.rows.size()) > kMaxRows) {
    throw InputError({data.path, 0, "load_N"},
                     "discover takes at most " + std::to_string(kMaxRows) + " measured rows (" +
                         std::to_string(data.rows.size()) +
                         " given): every candidate evaluates the model about 15 times on every "
                         "row (a 1000-row matrix takes about 20 s of CPU time); average repeated "
                         "measurements or thin the test matrix");
  }
  TyreConfig eval = config;
  if (opt.unit_length_mm > 0) {
    // The same limit the config reader puts on contact.unit_length_mm.
    const double units = config.mesh.window_m / (opt.unit_length_mm * 1e-3);
    if (!(units <= 20000)) {
      throw InputError({"--unit-length-mm", 0, "unit_length_mm"},
                       "window / unit length = " + std::to_string(static_cast<long>(units)) +
                           " candidate units; at most 20000 are supported");
    }
    eval.mesh.unit_length_m = opt.unit_length_mm * 1e-3;
  }
  const contact::TyreModel model = contact::build_tyre_model(eval);
  check_omp_num_threads();  // the default below reads it (a Python caller has no main())
  const int threads = opt.threads > 0 ? opt.threads : omp_get_max_threads();
  Evaluator ev(model, data, opt.traction_flexing);
  ev.set_threads(threads);
  std::vector<int> all(data.rows.size());
  std::iota(all.begin(), all.end(), 0);

  // The mesh of half the unit length for the named effects' mesh shift (mesh_bias.h), built
  // when first needed.
  std::optional<FineMesh> fine;
  DiscoverReport rep;
  {
    std::ostringstream s;
    s << model.unit_length_m * 1e3 << " mm units, " << model.candidates() << " candidate units";
    rep.evaluation_mesh = s.str();
  }
  rep.traction_windows = ev.traction_windows();
  const auto all_entries = ev.entries(all);
  int config_failures = 0;
  rep.gap_config =
      rms_by_observable(data, all_entries, ev.residuals(eval, all_entries, config_failures));

  if (static_cast<int>(data.rows.size()) <= opt.fit.exact_rows) {
    rep.method = "exact";
  } else {
    std::ostringstream s;
    s << "approximate on " << data.rows.size() << " rows (more than " << opt.fit.exact_rows
      << "): search on " << opt.fit.subset_rows
      << " evenly spread rows (at least 4 per parameter), finished by Gauss-Newton on all "
         "rows; cross-validation by one Gauss-Newton step per fold";
    rep.method = s.str();
  }
  std::atomic<int> done{0};
  // A phase starts with (phase, 0, total), then counts each fit and each cross-validation.
  auto ticker = [&](const std::string& phase, int total) {
    done = 0;
    if (opt.progress) opt.progress(phase, 0, total);
    return [&opt, &done, phase, total] {
      if (opt.progress) opt.progress(phase, ++done, total);
    };
  };

  const NamingRule rule{opt.min_delta_bic, opt.min_cv_gain, opt.max_cv_loss, opt.cv_gain_z};
  Stage current{make_variant(config, {}), {}, {}};
  {
    auto fc = fit_and_cross_validate(ev, eval, current.variant, opt.fit, ticker("baseline", 2));
    current.fit = std::move(fc.fit);
    current.cv = std::move(fc.cv);
  }
  rep.fits = 1 + (current.cv.one_step ? 0 : current.cv.folds);
  rep.evaluations = current.fit.evaluations + current.cv.evaluations;
  if (current.fit.failures > 0) {
    throw ComputationError(
        "the baseline cannot be fitted: " + std::to_string(current.fit.failures) +
        " rows fail to converge at its best parameters");
  }
  const Stage baseline = current;
  std::map<std::string, int> measured;  // entries per observable, for the rule's gain
  for (const auto& e : baseline.fit.entries) ++measured[data.observables[e.observable]];
  rep.gap_before = baseline.fit.rms;
  rep.cv_gap_before = baseline.cv.rms;
  rep.baseline_parameters = named_values(baseline.variant, baseline.fit.values, false);
  rep.regimes = locate(data, baseline.fit);
  rep.worst_rows = worst_rows(data, baseline.fit);

  for (int round = 0; round < opt.max_effects; ++round) {
    std::vector<EffectId> ids;
    std::vector<CandidateScore> scores;
    for (const auto& info : contact::effect_catalogue()) {
      if (contact::effect_enabled(config, info.id)) continue;  // already in the model
      if (std::find(current.variant.effects.begin(), current.variant.effects.end(), info.id) !=
          current.variant.effects.end()) {
        continue;
      }
      CandidateScore s;
      s.name = info.name;
      s.reason = untestable_reason(info.id, data, config);
      s.testable = s.reason.empty();
      scores.push_back(s);
      ids.push_back(info.id);
    }
    // The model's uncertainty at the current model's fit (model_uncertainty.h).
    ModelUncertainty mu;
    if (opt.model_uncertainty) {
      mu = model_uncertainty(ev, current.fit.config, current.variant, current.fit);
      rep.uncertainty_inputs = mu.names;
    }
    std::vector<Stage> stages(ids.size());
    const int total = static_cast<int>(ids.size());
    int testable = 0;
    for (const auto& s : scores) testable += s.testable;
    const auto tick = ticker("round " + std::to_string(round + 1), 2 * testable);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1)
    for (int c = 0; c < total; ++c) {
      if (!scores[c].testable) continue;
      std::vector<EffectId> effects = current.variant.effects;
      effects.push_back(ids[c]);
      Stage& st = stages[c];
      st.variant = make_variant(config, effects);
      auto fc = fit_and_cross_validate(ev, current.fit.config, st.variant, opt.fit, tick);
      st.fit = std::move(fc.fit);
      st.cv = std::move(fc.cv);
    }
    int best = -1;
    for (int c = 0; c < total; ++c) {
      CandidateScore& s = scores[c];
      if (!s.testable) continue;
      rep.fits += 1 + (stages[c].cv.one_step ? 0 : stages[c].cv.folds);
      rep.evaluations += stages[c].fit.evaluations + stages[c].cv.evaluations;
      s.parameters = named_values(stages[c].variant, stages[c].fit.values, false);
      s.delta_bic = current.fit.bic - stages[c].fit.bic;
      s.cv_rms_before = current.cv.rms_all;
      s.cv_rms_after = stages[c].cv.rms_all;
      s.rms_after = stages[c].fit.rms_all;
      s.failures = stages[c].fit.failures;
      s.cv_before = current.cv.rms;
      s.cv_after = stages[c].cv.rms;
      s.standard_errors = named_values(stages[c].variant, stages[c].fit.standard_errors, false);
      std::vector<double> cv_before, cv_after;
      std::vector<int> entries;
      for (const auto& kv : s.cv_before) {
        cv_before.push_back(kv.second);
        cv_after.push_back(s.cv_after.at(kv.first));
        entries.push_back(measured[kv.first]);
      }
      const auto& r0 = current.fit.residuals;
      const auto& r1 = stages[c].fit.residuals;
      if (opt.model_uncertainty && r0.size() == r1.size()) {
        const Eigen::VectorXd g =
            Eigen::Map<const Eigen::VectorXd>(r0.data(), static_cast<Eigen::Index>(r0.size())) -
            Eigen::Map<const Eigen::VectorXd>(r1.data(), static_cast<Eigen::Index>(r1.size()));
        // The likelihood-ratio part of Delta BIC (model_fit.h: k ln N per parameter).
        const double dk = static_cast<double>(stages[c].variant.parameters.size() -
                                              current.variant.parameters.size());
        const double lr = s.delta_bic + dk * std::log(static_cast<double>(r0.size()));
        s.uncertainty_discount = uncertain_share(mu, g) * std::max(lr, 0.0);
      }
      const double evidence = s.delta_bic - s.uncertainty_discount;
      s.significant = s.failures == 0 && rule.names(evidence, cv_before, cv_after, entries,
                                                    s.cv_rms_before, s.cv_rms_after);
      if (s.significant &&
          (best < 0 || evidence > scores[best].delta_bic - scores[best].uncertainty_discount))
        best = c;
    }
    std::stable_sort(scores.begin(), scores.end(),
                     [](const CandidateScore& a, const CandidateScore& b) {
                       if (a.testable != b.testable) return a.testable;
                       return a.delta_bic > b.delta_bic;
                     });
    rep.rounds.push_back(scores);
    if (best < 0) break;
    NamedEffect ne;
    ne.name = contact::effect_info(ids[best]).name;
    const Stage& chosen = stages[best];
    const auto se = named_values(chosen.variant, chosen.fit.standard_errors, true);
    const contact::EffectInfo& named_info = contact::effect_info(ids[best]);
    for (const auto& kv : named_values(chosen.variant, chosen.fit.values, true)) {
      for (const auto& p : named_info.parameters) {  // this effect's keys (effects.*, options)
        if (named_info.key(p) != kv.first) continue;
        ne.parameters[kv.first] = kv.second;
        ne.standard_errors[kv.first] = se.at(kv.first);
      }
    }
    for (std::size_t i = 0; i < chosen.variant.parameters.size(); ++i) {
      const auto& p = chosen.variant.parameters[i];
      if (!ne.parameters.count(p.key)) continue;
      ne.bands[p.key] = named_band(ev, current.fit.config, chosen, all, opt, static_cast<int>(i));
      if (!studies::range_bound_side(chosen.fit.values[i], p.min, p.max, p.log_scale).empty())
        ne.at_bound.push_back(p.key);
    }
    if (opt.mesh_check) {
      ne.mesh = named_mesh_bias(ev, fine, current.fit.config, chosen, opt, threads);
      for (std::size_t i = 0; i < chosen.variant.parameters.size(); ++i) {
        const auto& p = chosen.variant.parameters[i];
        const auto d = ne.mesh.shift.find(p.key);
        if (ne.bands.count(p.key) && d != ne.mesh.shift.end())
          ne.bands_with_mesh[p.key] = band_with_mesh(ne.bands.at(p.key), d->second, p);
      }
    }
    ne.delta_bic = current.fit.bic - chosen.fit.bic;
    ne.cv_rms_before = current.cv.rms_all;
    ne.cv_rms_after = chosen.cv.rms_all;
    rep.effects.push_back(ne);
    current = chosen;
    // Search again only if a clear structure is left: some observable's residual still
    // correlates with a condition (|r| >= opt.structure_correlation).
    const auto left = locate(data, current.fit);
    if (left.empty() || std::abs(left.front().correlation) < opt.structure_correlation) break;
  }

  if (opt.detection_limits && !rep.rounds.empty()) {
    add_detection_limits(
        ev, current, rule, opt, threads,
        [&](int total) { return ticker("detection limits", total); }, rep);
  }
  rep.footprints = ev.predictions();
  rep.traction_cases = ev.traction_cases();
  rep.gap_after = current.fit.rms;
  rep.cv_gap_after = current.cv.rms;
  rep.final_parameters = named_values(current.variant, current.fit.values, false);
  fill_rows(data, baseline, current, rep.rows);
  for (auto id : current.variant.effects) {
    for (auto& o : contact::effect_switch_overrides(current.fit.config, id))
      rep.out_overrides.push_back(std::move(o));
  }
  for (const auto& kv : rep.final_parameters) {
    rep.out_overrides.push_back(kv.first + "=" + number_text(kv.second));
  }

  std::ostringstream c;
  c.precision(3);
  if (rep.effects.empty()) {
    c << "No candidate effect explains the gap significantly";
    const auto& first = rep.rounds.front();
    if (!first.empty() && first.front().testable) {
      c << " (best: " << first.front().name << ", Delta BIC " << first.front().delta_bic
        << ", cross-validated RMS " << percent(first.front().cv_rms_before) << " -> "
        << percent(first.front().cv_rms_after) << ")";
    }
    c << "; the baseline stays.";
  } else {
    c << "Named: ";
    for (std::size_t i = 0; i < rep.effects.size(); ++i) {
      const auto& e = rep.effects[i];
      c << (i ? "; then " : "") << e.name << " (Delta BIC " << e.delta_bic
        << ", cross-validated RMS " << percent(e.cv_rms_before) << " -> " << percent(e.cv_rms_after)
        << ")";
    }
    c << ".";
  }
  rep.conclusion = c.str();
  return rep;
}

}  // namespace modaltyre::discover
