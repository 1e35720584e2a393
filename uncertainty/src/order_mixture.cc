#include "modaltyre/uncertainty/order_mixture.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace modaltyre::uncertainty {
namespace {

double normal_cdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

// The smallest x at which the weighted points' cumulative weight reaches q (a step CDF).
double weighted_quantile(std::vector<std::pair<double, double>> points, double q) {
  std::sort(points.begin(), points.end());
  double sum = 0;
  for (const auto& [x, w] : points) {
    sum += w;
    if (sum >= q - 1e-12) return x;
  }
  return points.back().first;
}

}  // namespace

Band mix_band(const Band& band, const std::vector<double>* samples,
              const std::vector<MixtureComponent>& components) {
  Band out = band;
  if (samples && !samples->empty()) {
    // Pooled samples, each alternative's copy shifted and weighted by its probability.
    const double m = static_cast<double>(samples->size());
    // Variance: the samples' own (unbiased) plus the shifts' spread about their weighted mean.
    std::vector<std::pair<double, double>> points;
    double sample_mean = 0, shift_mean = 0;
    for (double v : *samples) sample_mean += v / m;
    for (const auto& c : components) {
      shift_mean += c.weight * c.shift;
      for (double v : *samples) points.emplace_back(v + c.shift, c.weight / m);
    }
    double var = 0;
    for (double v : *samples) var += (v - sample_mean) * (v - sample_mean) / (m - 1);
    for (const auto& c : components)
      var += c.weight * (c.shift - shift_mean) * (c.shift - shift_mean);
    out.std = std::sqrt(var);
    out.p025 = weighted_quantile(points, 0.025);
    out.p975 = weighted_quantile(points, 0.975);
    return out;
  }
  double mean = 0;
  for (const auto& c : components) mean += c.weight * (band.value + c.shift);
  double var = band.std * band.std;
  for (const auto& c : components) {
    const double d = band.value + c.shift - mean;
    var += c.weight * d * d;
  }
  out.std = std::sqrt(var);
  if (!(band.std > 0)) {
    std::vector<std::pair<double, double>> points;
    for (const auto& c : components) points.emplace_back(band.value + c.shift, c.weight);
    out.p025 = weighted_quantile(points, 0.025);
    out.p975 = weighted_quantile(points, 0.975);
    return out;
  }
  // The mixture of normals' CDF by bisection: 60 halvings of a span of 16 sigma and the shifts
  // reach 1e-15 of it.
  double lo_all = band.value, hi_all = band.value;
  for (const auto& c : components) {
    lo_all = std::min(lo_all, band.value + c.shift);
    hi_all = std::max(hi_all, band.value + c.shift);
  }
  lo_all -= 8 * band.std;
  hi_all += 8 * band.std;
  const auto cdf = [&](double x) {
    double p = 0;
    for (const auto& c : components)
      p += c.weight * normal_cdf((x - band.value - c.shift) / band.std);
    return p;
  };
  const auto quantile = [&](double q) {
    double lo = lo_all, hi = hi_all;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (cdf(mid) < q ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  out.p025 = quantile(0.025);
  out.p975 = quantile(0.975);
  return out;
}

}  // namespace modaltyre::uncertainty
