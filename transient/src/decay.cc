#include "modaltyre/transient/decay.h"

#include <cmath>
#include <vector>

namespace modaltyre::transient {
namespace {

double slope(const std::vector<double>& y) {
  const double n = static_cast<double>(y.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double x = static_cast<double>(i);
    sx += x, sy += y[i], sxx += x * x, sxy += x * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

BounceDecay bounce_decay(const TransientResult& r, int max_peaks) {
  BounceDecay d;
  const auto& s = r.samples;
  if (s.size() < 3) return d;
  const double t_end = s.back().t_s;
  double mean = 0;
  int n = 0;
  for (const auto& x : s)
    if (x.t_s > 0.8 * t_end) mean += x.hub_displacement_m, ++n;
  if (n == 0) return d;
  mean /= n;
  std::vector<double> times, logs;
  const double dt = s[1].t_s - s[0].t_s;
  for (std::size_t i = 1; i + 1 < s.size() && static_cast<int>(times.size()) < max_peaks; ++i) {
    const double a = s[i - 1].hub_displacement_m - mean, b = s[i].hub_displacement_m - mean,
                 c = s[i + 1].hub_displacement_m - mean;
    if (!(b > a && b >= c && b > 0)) continue;
    const double den = a - 2 * b + c;
    const double off = den != 0 ? 0.5 * (a - c) / den : 0.0;
    times.push_back(s[i].t_s + off * dt);
    logs.push_back(std::log(b - 0.25 * (a - c) * off));
  }
  d.peaks = static_cast<int>(times.size());
  if (d.peaks < 2) return d;
  d.period_s = slope(times);
  d.log_decrement = -slope(logs);
  return d;
}

}  // namespace modaltyre::transient
