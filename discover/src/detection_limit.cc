#include "modaltyre/discover/detection_limit.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "modaltyre/contact/effects.h"

namespace modaltyre::discover {

using contact::EffectId;

// A signal of RMS s over noise sigma on n held-out entries lowers their mean squared error by
// s^2, with a sampling spread of about 2 sigma s / sqrt(n) (the cross term of each entry,
// d_i = (e_i + s_i)^2 - e_i^2): the paired test reaches z at s / sigma = 2 z / sqrt(n), where
// the RMS falls by 1 - 1 / sqrt(1 + (s / sigma)^2).
double NamingRule::gain_needed(int entries) const {
  if (cv_gain_z <= 0 || entries <= 0) return min_cv_gain;
  const double x2 = 4 * cv_gain_z * cv_gain_z / entries;
  return std::min(min_cv_gain, 1 - 1 / std::sqrt(1 + x2));
}

bool NamingRule::names(double delta_bic, const std::vector<double>& cv_before,
                       const std::vector<double>& cv_after, const std::vector<int>& entries,
                       double pooled_before, double pooled_after) const {
  bool gain = false;
  double worst_loss = 0;
  for (std::size_t o = 0; o < cv_before.size(); ++o) {
    if (cv_before[o] <= 0) continue;
    gain = gain || 1 - cv_after[o] / cv_before[o] >= gain_needed(entries[o]);
    worst_loss = std::max(worst_loss, cv_after[o] / cv_before[o] - 1);
  }
  return delta_bic > min_delta_bic && gain && worst_loss <= max_cv_loss &&
         pooled_after <= pooled_before;
}

// The path from "off" to the catalogue default and beyond: the strength parameter is the
// effect's first fitted one, value(m) = off + m (default - off), or default / m for a modulus
// whose effect vanishes as it grows (the soil's: Winkler compliance ~ layer / E2, seed 000
// eq. (23)). The effect's other fitted parameters stay at their defaults.
struct LimitFinder::Path {
  Variant effect;             ///< the candidate's own parameters only (base_ has the rest)
  std::vector<double> start;  ///< the effect's parameters at the default
  int strength = 0;           ///< index into effect.parameters
  double off = 0;
  bool inverse = false;
  double m_max = 0;  ///< strength at the parameter's range bound
  std::string reason;
  Eigen::MatrixXd b;  ///< Jacobian of the effect's parameters at the default
  double value(double m) const {
    const double d = start[strength];
    return inverse ? d / m : off + m * (d - off);
  }
};

namespace {

// Unit-norm columns (the parameters' units differ by orders of magnitude) and the
// pseudo-inverse, so that rank-deficient designs (a parameter the rows do not determine) work.
Eigen::MatrixXd pseudo_inverse(const Eigen::MatrixXd& x) {
  Eigen::VectorXd scale = x.colwise().norm().transpose();
  for (int j = 0; j < scale.size(); ++j) scale(j) = scale(j) > 0 ? 1 / scale(j) : 0;
  const Eigen::MatrixXd xs = x * scale.asDiagonal();
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(xs);
  cod.setThreshold(1e-10);
  return scale.asDiagonal() * cod.pseudoInverse();
}

Eigen::MatrixXd stacked(const Eigen::MatrixXd& x, int replicas) {
  Eigen::MatrixXd out(x.rows() * replicas, x.cols());
  for (int r = 0; r < replicas; ++r) out.middleRows(r * x.rows(), x.rows()) = x;
  return out;
}

// Least-squares residuals of Y (entries x draws) on the design x: in sample, and held out on
// the given folds (entries' fold index), each fold fitted on the others.
struct LinearFit {
  Eigen::MatrixXd in_sample, held_out;
};

LinearFit fit_linear(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y,
                     const std::vector<int>& fold, int folds) {
  LinearFit f;
  f.in_sample = y - x * (pseudo_inverse(x) * y);
  f.held_out.resize(y.rows(), y.cols());
  for (int k = 0; k < folds; ++k) {
    std::vector<int> train, test;
    for (int i = 0; i < static_cast<int>(fold.size()); ++i)
      (fold[i] == k ? test : train).push_back(i);
    if (test.empty()) continue;
    const Eigen::MatrixXd p = pseudo_inverse(x(train, Eigen::all));
    const Eigen::MatrixXd beta = p * y(train, Eigen::all);
    f.held_out(test, Eigen::all) = y(test, Eigen::all) - x(test, Eigen::all) * beta;
  }
  return f;
}

}  // namespace

LimitFinder::LimitFinder(const Evaluator& ev, const contact::TyreConfig& base,
                         const Variant& current, const FitResult& fit, const NamingRule& rule,
                         const LimitOptions& options)
    : ev_(ev),
      base_(base),
      current_(current),
      values_(fit.values),
      rule_(rule),
      opt_(options),
      entries_(fit.entries),
      residuals_(fit.residuals),
      rows_(static_cast<int>(ev.data().rows.size())) {
  // The current parameters' Jacobian, on the config they were applied to (base = apply(...)).
  a_ = jacobian(ev_, base_, current_, values_, entries_);
  // Noise per observable from the current fit, its RMS corrected for the fitted parameters.
  const int n = static_cast<int>(entries_.size());
  const int p = static_cast<int>(current_.parameters.size());
  const double dof = n > p ? std::sqrt(static_cast<double>(n) / (n - p)) : 1.0;
  const auto& obs = ev_.data().observables;
  sigma_.assign(obs.size(), 0.0);
  for (std::size_t o = 0; o < obs.size(); ++o) {
    const auto it = fit.rms.find(obs[o]);
    if (it != fit.rms.end()) sigma_[o] = std::max(it->second * dof, 1e-4);
  }
}

LimitFinder::Path LimitFinder::path(EffectId id, bool lower) const {
  Path p;
  const contact::EffectInfo& info = contact::effect_info(id);
  p.effect.effects = {id};
  p.effect.parameters = effect_parameters(id);
  // The catalogue defaults, as fit_variant starts a new effect from them.
  for (const auto& fp : p.effect.parameters) p.start.push_back(fp.catalogue_default);
  if (p.effect.parameters.empty()) {
    p.reason = "it has no fitted parameter";
    return p;
  }
  const FreeParameter& s = p.effect.parameters[p.strength];
  const double d = p.start[p.strength];
  if (info.strength == contact::EffectStrength::none) {
    // E.g. contact_width: its width replaces the config's fixed one at every strength.
    p.reason = "no value of " + s.key + " switches it off (" + info.no_strength + ")";
    return p;
  }
  p.inverse = info.strength == contact::EffectStrength::inverse;
  p.off = info.neutral;
  if (lower) {
    // The mirror image of the default about the neutral value, or half-way to the range's
    // lower bound when the mirror lies beyond it.
    const double mirror = 2 * p.off - d;
    p.start[p.strength] = mirror > s.min ? mirror : 0.5 * (s.min + p.off);
    p.m_max = (s.min - p.off) / (p.start[p.strength] - p.off);
  } else if (p.inverse) {
    p.m_max = d / s.min;
  } else if (d > p.off && s.max > p.off) {
    p.m_max = (s.max - p.off) / (d - p.off);
  } else {
    p.reason = "its strength " + s.key + " does not grow from " + std::to_string(p.off) +
               " to its default in its range";
    return p;
  }
  p.b = jacobian(ev_, base_, p.effect, p.start, entries_);
  return p;
}

Eigen::VectorXd LimitFinder::signal(const Path& p, double m) const {
  std::vector<double> v = p.start;
  v[p.strength] = p.value(m);
  int failures = 0;
  const auto r = ev_.residuals(apply(base_, p.effect, v), entries_, failures);
  Eigen::VectorXd s(static_cast<int>(r.size()));
  for (int i = 0; i < s.size(); ++i) s(i) = r[i] - residuals_[i];
  if (failures > 0) s.setConstant(std::nan(""));
  return s;
}

double LimitFinder::power(const Path& p, const Eigen::VectorXd& s, int replicas) const {
  if (!s.allFinite()) return 0;
  const int n = static_cast<int>(entries_.size()) * replicas;
  const int rows = rows_ * replicas;
  const int folds = rows <= 8 ? rows : 6;  // as cross_validate() and large_fit.h
  std::vector<int> fold(n);
  std::vector<Evaluator::Entry> entries(n);
  for (int r = 0; r < replicas; ++r) {
    for (std::size_t i = 0; i < entries_.size(); ++i) {
      const int j = r * static_cast<int>(entries_.size()) + static_cast<int>(i);
      entries[j] = {entries_[i].row + r * rows_, entries_[i].observable};
      fold[j] = entries[j].row % folds;
    }
  }
  const Eigen::MatrixXd x0 = stacked(a_, replicas);
  Eigen::MatrixXd x1(n, a_.cols() + p.b.cols());
  x1 << x0, stacked(p.b, replicas);
  const Eigen::VectorXd signal = stacked(s, replicas);
  const int observables = static_cast<int>(sigma_.size());
  const int k0 = static_cast<int>(x0.cols()), k1 = static_cast<int>(x1.cols());

  std::mt19937 rng(opt_.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  Eigen::MatrixXd noise(n, opt_.draws);
  for (int d = 0; d < opt_.draws; ++d) {
    for (int i = 0; i < n; ++i) noise(i, d) = sigma_[entries[i].observable] * unit(rng);
  }
  // The current model on data with the effect (signal + noise); the candidate, linearised at
  // the planted truth, on the noise alone.
  const LinearFit before = fit_linear(x0, noise.colwise() + signal, fold, folds);
  const LinearFit after = fit_linear(x1, noise, fold, folds);
  std::vector<int> count(observables, 0);
  for (int i = 0; i < n; ++i) ++count[entries[i].observable];
  auto rms = [&](const Eigen::MatrixXd& r, int d, std::vector<double>& per_obs) {
    per_obs.assign(observables, 0.0);
    double all = 0;
    for (int i = 0; i < n; ++i) {
      per_obs[entries[i].observable] += r(i, d) * r(i, d);
      all += r(i, d) * r(i, d);
    }
    for (int o = 0; o < observables; ++o)
      per_obs[o] = count[o] ? std::sqrt(per_obs[o] / count[o]) : 0;
    return std::sqrt(all / n);
  };
  int named = 0;
  std::vector<double> cv0, cv1, r0(n), r1(n);
  for (int d = 0; d < opt_.draws; ++d) {
    for (int i = 0; i < n; ++i) r0[i] = before.in_sample(i, d), r1[i] = after.in_sample(i, d);
    const double dbic = bic(entries, r0, observables, k0) - bic(entries, r1, observables, k1);
    const double pooled0 = rms(before.held_out, d, cv0);
    const double pooled1 = rms(after.held_out, d, cv1);
    named += rule_.names(dbic, cv0, cv1, count, pooled0, pooled1);
  }
  return static_cast<double>(named) / opt_.draws;
}

double LimitFinder::power(EffectId id, double m, int replicas) const {
  const Path p = path(id);
  if (!p.reason.empty()) return 0;
  return power(p, signal(p, m), replicas);
}

DetectionLimit LimitFinder::limit(EffectId id, bool below_neutral) const {
  DetectionLimit out;
  const contact::EffectInfo& info = contact::effect_info(id);
  out.effect = info.name;
  const Path p = path(id);
  if (!p.effect.parameters.empty()) {
    out.parameter = p.effect.parameters[p.strength].key;
    for (const auto& ep : info.parameters) {
      if (info.key(ep) == out.parameter) out.unit = ep.unit;
    }
  }
  if (!p.reason.empty()) {
    out.reason = p.reason;
    return out;
  }
  search(p, out);
  // Both sides of a neutral value inside the strength parameter's range (from_neutral only: an
  // inverse strength vanishes at its range's far end).
  const FreeParameter& s = p.effect.parameters[p.strength];
  if (!below_neutral || p.inverse || !(s.min < p.off && p.off < p.start[p.strength])) return out;
  const Path q = path(id, true);
  DetectionLimit lower;
  search(q, lower);
  out.two_sided = true;
  out.lower_reference_value = q.start[q.strength];
  out.lower_value = lower.value;
  out.lower_magnitude = lower.magnitude;
  out.lower_reason = lower.reason;
  out.power_at_lower_reference = lower.power_at_default;
  return out;
}

void LimitFinder::search(const Path& p, DetectionLimit& out) const {
  const double target = opt_.power;
  auto power_at = [&](double m) { return power(p, signal(p, m), 1); };
  out.power_at_default = power_at(1);
  // Bracket the limit [lo, hi] (power(lo) < target <= power(hi)) by halving or doubling from
  // the default, then bisect it geometrically to 4 %.
  double lo = 1, hi = 1;
  if (out.power_at_default >= target) {
    do {
      hi = lo;
      lo /= 2;
    } while (lo > 1e-3 && power_at(lo) >= target);
  } else {
    for (;;) {
      lo = hi;
      hi = std::min(2 * hi, p.m_max);
      if (hi <= lo * 1.0001) {
        std::ostringstream s;
        s.precision(3);
        s << "not named with " << 100 * target << " % probability anywhere in the range of "
          << p.effect.parameters[p.strength].key << " (at its bound " << p.value(p.m_max) << ": "
          << 100 * power_at(p.m_max) << " %)";
        out.reason = s.str();
        return;
      }
      if (power_at(hi) >= target) break;
    }
  }
  while (hi / lo > 1.04) {
    const double mid = std::sqrt(lo * hi);
    (power_at(mid) >= target ? hi : lo) = mid;
  }
  out.magnitude = hi;
  out.at_most = p.inverse || p.start[p.strength] < p.off;
  out.value = p.value(hi);
  // The change at the limit beyond what the re-fitted baseline absorbs (its Jacobian's span).
  const Eigen::VectorXd sig = signal(p, hi);
  const Eigen::VectorXd left = sig - a_ * (pseudo_inverse(a_) * sig);
  std::vector<double> sum(sigma_.size(), 0.0);
  std::vector<int> count(sigma_.size(), 0);
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    sum[entries_[i].observable] += left(static_cast<int>(i)) * left(static_cast<int>(i));
    ++count[entries_[i].observable];
  }
  for (std::size_t o = 0; o < sum.size(); ++o) {
    if (count[o]) out.observable_rms_rel[ev_.data().observables[o]] = std::sqrt(sum[o] / count[o]);
  }
}

int LimitFinder::replicas_for_default(EffectId id) const {
  const Path p = path(id);
  if (!p.reason.empty()) return 0;
  const Eigen::VectorXd s = signal(p, 1);
  for (int r : {1, 2, 3, 4, 6, 8, 12, 16, 24, 32}) {
    if (r > opt_.max_replicas) break;
    if (power(p, s, r) >= opt_.power) return r;
  }
  return 0;
}

}  // namespace modaltyre::discover
