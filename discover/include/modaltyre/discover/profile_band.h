#pragma once
// The band of a named effect's fitted parameter from its profile likelihood: the values on
// either side of the optimum where the fit with that parameter held and every other one
// re-fitted loses two standard errors' worth of likelihood. The Gauss-Newton standard error is
// the band of the model linearised at the optimum; on a parameter the footprints follow
// non-linearly (the sidewall's c0 / L near its 0.88 bound, the belt foundation on a log scale)
// that band is too narrow and centred where the likelihood is not: on 13 noise draws of one
// planted sidewall set the fitted values lay (mean 0.73, spread 1.30) Gauss-Newton standard
// errors from the truth (docs/discover.md, "Parameter bands").
#include <vector>

#include "modaltyre/discover/model_fit.h"

namespace modaltyre::discover {

struct ParameterBand {
  double lower = 0, upper = 0;  ///< config units
  /// The profile does not rise by two standard errors' worth before the range's bound on that
  /// side: the band reaches the bound (the data bound the parameter from the other side only).
  bool lower_at_bound = false, upper_at_bound = false;
  int fits = 0;  ///< profile fits made (each a fit of the other parameters on `rows`)
};

/// Profile statistic of parameter `i` at `value`: the likelihood-ratio statistic with each
/// observable's noise level profiled out, sum_o n_o ln(RSS_o(value) / RSS_o(optimum)), times
/// (N - k) / N for the k fitted parameters of N entries (the first-order small-sample
/// correction that makes it the F test's t^2 on a linear model). About 1 per standard error
/// squared near the optimum.
double profile_statistic(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                         const FitResult& fit, const std::vector<int>& rows, int i, double value,
                         int* fits = nullptr);

/// Where profile_statistic() reaches 4 (two standard errors) on each side of `fit`'s optimum
/// (`fit` a full fit of v on `rows` with standard errors), found in the parameter's search
/// variable from the Gauss-Newton estimate by a safeguarded secant on its square root.
ParameterBand profile_band(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                           const FitResult& fit, const std::vector<int>& rows, int i);

}  // namespace modaltyre::discover
