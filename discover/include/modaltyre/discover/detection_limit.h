#pragma once
// What a data set could have shown (issue 23): for a candidate effect that is not named, the
// smallest strength that these rows, at their noise, would name under the workflow's own rule
// with 80 % probability, and how many more rows would bring the catalogue default over it.
//
// Method (docs/discover.md, "Detection limits"): the naming rule is simulated on the model
// linearised at the current fit. For a strength m (a multiple of the catalogue default's
// strength) the planted signal s(m) is the exact change of the relative residuals of every
// entry when the effect is switched on at m over the current model (one evaluation of all rows);
// the re-fitted baseline is the span of the current parameters' Jacobian A, the candidate's
// re-fit the span of [A, B] (B: the effect's parameters' Jacobian at the default). Noise is
// Gaussian per observable at the level the current fit's residuals give. Each draw fits both
// models by least squares, in sample and on the workflow's own cross-validation folds, and
// applies the rule (Delta BIC and the cross-validated gains) exactly as discover does; the
// power is the named fraction of a fixed set of draws (common random numbers for every m, so
// that the power is a smooth function of m for the search).
#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

#include "modaltyre/discover/model_fit.h"

namespace modaltyre::discover {

/// discover's naming rule: Delta BIC above min_delta_bic, the cross-validated RMS falling by
/// at least gain_needed() on some observable, growing by at most max_cv_loss on any and not at
/// all pooled over all observables.
struct NamingRule {
  double min_delta_bic = 10;
  double min_cv_gain = 0.25;
  double max_cv_loss = 0.10;
  /// 0: the gain must reach min_cv_gain whatever the rows. > 0: the smaller of min_cv_gain and
  /// the gain at which a paired test of the held-out squared errors of n entries reaches
  /// z = cv_gain_z (docs/discover.md, "The naming rule's power"). The default is discover's
  /// (DiscoverOptions::cv_gain_z).
  double cv_gain_z = 2;
  double gain_needed(int entries) const;
  /// Per-observable cross-validated RMS before and after and the entries they are taken over
  /// (same order; a zero "before" is skipped), and pooled.
  bool names(double delta_bic, const std::vector<double>& cv_before,
             const std::vector<double>& cv_after, const std::vector<int>& entries,
             double pooled_before, double pooled_after) const;
};

struct LimitOptions {
  double power = 0.8;     ///< probability of naming that defines the limit
  int draws = 300;        ///< noise draws per strength
  unsigned seed = 20231;  ///< fixed: results are deterministic
  int max_replicas = 16;  ///< "more rows": the rows repeated up to this many times
};

struct DetectionLimit {
  std::string effect;
  /// Empty when computed; else why not (no strength at which the effect vanishes, not
  /// reached within the parameter's range, ...).
  std::string reason;
  std::string parameter;  ///< config key of the strength parameter
  std::string unit;
  double value = 0;      ///< the strength parameter at the limit
  double magnitude = 0;  ///< the limit's strength over the catalogue default's (1 = default)
  /// The effect grows as the parameter falls (a modulus): revealed at values <= value.
  bool at_most = false;
  /// RMS relative change of each observable the effect causes at the limit on these rows,
  /// beyond what the re-fitted baseline absorbs.
  std::map<std::string, double> observable_rms_rel;
  double power_at_default = 0;  ///< probability of naming it at the catalogue default
  /// Times the rows (same condition grid, same noise) must be repeated for the default to be
  /// named with `power` probability; 0 when max_replicas do not suffice or not asked
  /// (LimitFinder::replicas_for_default).
  int replicas_for_default = 0;
  /// An effect that grows on both sides of its neutral value (crown_shape's exponent below and
  /// above the circular crown's 2, load_stiffening's exponent of either sign): the limit on the
  /// side the catalogue default is not on, searched from the default's mirror image about the
  /// neutral value (reference_value; half-way to the range's bound when the mirror lies beyond
  /// it). Revealed at values <= lower_value below the neutral value.
  bool two_sided = false;
  double lower_value = 0;
  double lower_reference_value = 0;
  double lower_magnitude = 0;  ///< over the reference's strength
  std::string lower_reason;    ///< empty when computed
  double power_at_lower_reference = 0;
  bool computed() const { return reason.empty(); }
};

/// Limits for candidates on top of a current fit (the model discover ends with).
class LimitFinder {
 public:
  /// `current`: the variant and its fit on all rows of ev.data(); `base`: the config the
  /// candidates are fitted from (discover's current fitted config).
  LimitFinder(const Evaluator& ev, const contact::TyreConfig& base, const Variant& current,
              const FitResult& fit, const NamingRule& rule, const LimitOptions& options = {});

  /// Thread-safe (candidates may run in parallel). About 2 k + 10 evaluations of all rows
  /// (k: the effect's fitted parameters).
  /// `below_neutral`: search the side below a neutral value inside the range too (discover asks
  /// it where the candidate's own fit lies on that side).
  DetectionLimit limit(contact::EffectId id, bool below_neutral = true) const;

  /// Times the rows must be repeated (1 = as they are, up to options.max_replicas; 0 = not
  /// enough) for the effect at its catalogue default to be named with options.power
  /// probability.
  int replicas_for_default(contact::EffectId id) const;

  /// Probability of naming the effect planted at strength m (x default) with the rows
  /// repeated `replicas` times. Exposed for the tests and the bench.
  double power(contact::EffectId id, double m, int replicas = 1) const;

  /// Noise level per observable (index into the data's observables) the simulation uses.
  const std::vector<double>& sigma() const { return sigma_; }

 private:
  struct Path;
  /// `lower`: the side below the neutral value of a two-sided effect.
  Path path(contact::EffectId id, bool lower = false) const;
  /// The limit along one path: value, magnitude, power at m = 1 and the reason when none.
  void search(const Path& p, DetectionLimit& out) const;
  double power(const Path& p, const Eigen::VectorXd& signal, int replicas) const;
  Eigen::VectorXd signal(const Path& p, double m) const;

  const Evaluator& ev_;
  contact::TyreConfig base_;
  Variant current_;
  std::vector<double> values_;
  NamingRule rule_;
  LimitOptions opt_;
  std::vector<Evaluator::Entry> entries_;
  std::vector<double> residuals_;  ///< of the current fit
  Eigen::MatrixXd a_;              ///< Jacobian of the current parameters
  std::vector<double> sigma_;
  int rows_ = 0;
};

}  // namespace modaltyre::discover
