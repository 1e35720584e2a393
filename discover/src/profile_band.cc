#include "modaltyre/discover/profile_band.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace modaltyre::discover {
namespace {

constexpr double kTwoStandardErrors = 4;  // profile statistic at two standard errors
constexpr double kEdge = 12;              // |u| beyond which the search variable is at a bound

// sum_o n_o ln RSS_o, the part of the log-likelihood that moves with the parameters.
double log_rss(const FitResult& f, int observables) {
  std::vector<double> rss(observables, 0.0);
  std::vector<int> n(observables, 0);
  for (std::size_t e = 0; e < f.entries.size(); ++e) {
    rss[f.entries[e].observable] += f.residuals[e] * f.residuals[e];
    ++n[f.entries[e].observable];
  }
  double s = 0;
  for (int o = 0; o < observables; ++o)
    if (n[o] > 0) s += n[o] * std::log(std::max(rss[o], 1e-300));
  return s;
}

}  // namespace

double profile_statistic(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                         const FitResult& fit, const std::vector<int>& rows, int i, double value,
                         int* fits) {
  // Parameter i held at `value` in the config the others are fitted on, from their optimum.
  std::vector<double> held = fit.values;
  held[i] = value;
  const contact::TyreConfig at = apply(base, v, held);
  Variant rest = v;
  rest.parameters.erase(rest.parameters.begin() + i);
  std::vector<double> start = fit.values;
  start.erase(start.begin() + i);
  const FitResult f = fit_variant(ev, at, rest, rows, start);
  if (fits) ++*fits;
  if (f.failures > 0) return std::numeric_limits<double>::infinity();
  const int observables = static_cast<int>(ev.data().observables.size());
  const double n = static_cast<double>(fit.entries.size());
  const double k = static_cast<double>(v.parameters.size());
  const double d = log_rss(f, observables) - log_rss(fit, observables);
  return std::max(d, 0.0) * std::max(n - k, 1.0) / n;
}

ParameterBand profile_band(const Evaluator& ev, const contact::TyreConfig& base, const Variant& v,
                           const FitResult& fit, const std::vector<int>& rows, int i) {
  const FreeParameter& p = v.parameters[i];
  const double u0 = to_search(p, fit.values[i]);
  // Two Gauss-Newton standard errors in the search variable: the first trial step.
  const double se = i < static_cast<int>(fit.standard_errors.size()) ? fit.standard_errors[i] : 0;
  double first = 2 * se / std::max(search_derivative(p, u0), 1e-300);
  if (!std::isfinite(first) || first <= 0) first = 1;
  first = std::clamp(first, 1e-3, 4.0);
  ParameterBand band;
  for (int side : {-1, 1}) {
    // Bracket [lo, hi] of the distance in u: statistic below 4 at lo, above at hi (hi = 0: none
    // yet). sqrt(statistic) is about linear in the distance (|u - u0| / se_u): secant steps on
    // it, bisection when a step leaves the bracket.
    double lo = 0, s_lo = 0, hi = 0, s_hi = 0, d = first;
    double found = 0;
    bool bound = false;
    for (int it = 0; it < 8; ++it) {
      if (std::abs(u0 + side * d) > kEdge) d = kEdge - side * u0, bound = true;
      const double stat =
          profile_statistic(ev, base, v, fit, rows, i, from_search(p, u0 + side * d), &band.fits);
      const double r = std::sqrt(stat) - 2;
      if (std::abs(r) < 0.05) {
        found = d, bound = false;
        break;
      }
      if (r < 0) {
        lo = d, s_lo = r, found = d;
        if (bound) break;  // below two standard errors at the range's bound
      } else {
        hi = d, s_hi = r, found = d, bound = false;
      }
      double next = hi == 0 ? d * std::clamp(2 / std::max(std::sqrt(stat), 1e-3), 1.5, 8.0)
                            : lo - s_lo * (hi - lo) / (s_hi - s_lo);
      if (hi > 0 && !(next > lo && next < hi)) next = 0.5 * (lo + hi);
      d = next;
    }
    const double value = from_search(p, u0 + side * found);
    (side < 0 ? band.lower : band.upper) = value;
    (side < 0 ? band.lower_at_bound : band.upper_at_bound) = bound;
  }
  return band;
}

}  // namespace modaltyre::discover
