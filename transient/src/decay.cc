#include "modaltyre/transient/decay.h"

#include <algorithm>
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

BounceDecay fit(const std::vector<double>& times, const std::vector<double>& amplitudes) {
  BounceDecay d;
  d.peaks = static_cast<int>(times.size());
  if (d.peaks < 2) return d;
  std::vector<double> logs;
  for (double a : amplitudes) logs.push_back(std::log(a));
  d.period_s = slope(times);
  d.log_decrement = -slope(logs);
  return d;
}

/// The hub trace at the integrator's step ends: its mean over the last 20 % of the run (the
/// trapezoidal rule over the steps), then one peak per excursion above that mean: the largest
/// local maximum of the step ends there, refined by the parabola through it and its two
/// neighbours (unequally spaced). The excursion that starts at rest at t = 0 is left out, as the
/// sampled definition leaves it out (its first sample cannot be a maximum).
BounceDecay dense_decay(const std::vector<HubStep>& z, int max_peaks) {
  const std::size_t n = z.size();
  if (n < 3) return {};
  const double t_end = z.back().t_s, t_from = 0.8 * t_end;
  double area = 0;
  for (std::size_t i = 1; i < n; ++i) {
    const double a = std::max(z[i - 1].t_s, t_from), b = z[i].t_s;
    if (!(b > a)) continue;
    // The trace linear over the step; the part after t_from.
    const double h = z[i].t_s - z[i - 1].t_s;
    const double za = z[i - 1].z_m + (z[i].z_m - z[i - 1].z_m) * (a - z[i - 1].t_s) / h;
    area += 0.5 * (za + z[i].z_m) * (b - a);
  }
  const double mean = area / (t_end - t_from);
  std::vector<double> times, amplitudes;
  bool in_lobe = z.front().z_m - mean > 0;  // the release's excursion: no peak of its own
  bool skip = in_lobe;
  double best = 0, t_best = 0;
  for (std::size_t i = 1; i < n && static_cast<int>(times.size()) < max_peaks; ++i) {
    const double y = z[i].z_m - mean;
    if (!(y > 0)) {  // the excursion ends
      if (in_lobe && !skip && best > 0) times.push_back(t_best), amplitudes.push_back(best);
      in_lobe = false, skip = false, best = 0;
      continue;
    }
    in_lobe = true;
    if (i + 1 >= n) break;
    const double ya = z[i - 1].z_m - mean, yc = z[i + 1].z_m - mean;
    if (!(y > ya && y >= yc)) continue;
    // The parabola through the three ends: y = y + p u + q u^2, u = t - t_i.
    const double u0 = z[i - 1].t_s - z[i].t_s, u2 = z[i + 1].t_s - z[i].t_s;
    const double q = ((ya - y) / u0 - (yc - y) / u2) / (u0 - u2);
    const double p = (ya - y) / u0 - q * u0;
    double tp = z[i].t_s, yp = y;
    if (q < 0) {
      const double u = -p / (2 * q);
      if (u > u0 && u < u2) tp = z[i].t_s + u, yp = y + p * u + q * u * u;
    }
    if (yp > best) best = yp, t_best = tp;
  }
  return fit(times, amplitudes);
}

/// The definition on the output samples (issue 21's reference metrics, decay.h).
BounceDecay sampled_decay(const TransientResult& r, int max_peaks) {
  const auto& s = r.samples;
  if (s.size() < 3) return {};
  const double t_end = s.back().t_s;
  double mean = 0;
  int n = 0;
  for (const auto& x : s)
    if (x.t_s > 0.8 * t_end) mean += x.hub_displacement_m, ++n;
  if (n == 0) return {};
  mean /= n;
  std::vector<double> times, amplitudes;
  const double dt = s[1].t_s - s[0].t_s;
  for (std::size_t i = 1; i + 1 < s.size() && static_cast<int>(times.size()) < max_peaks; ++i) {
    const double a = s[i - 1].hub_displacement_m - mean, b = s[i].hub_displacement_m - mean,
                 c = s[i + 1].hub_displacement_m - mean;
    if (!(b > a && b >= c && b > 0)) continue;
    const double den = a - 2 * b + c;
    const double off = den != 0 ? 0.5 * (a - c) / den : 0.0;
    times.push_back(s[i].t_s + off * dt);
    amplitudes.push_back(b - 0.25 * (a - c) * off);
  }
  return fit(times, amplitudes);
}

}  // namespace

double BounceDecay::damping_ratio() const {
  return log_decrement / std::sqrt(4 * M_PI * M_PI + log_decrement * log_decrement);
}

BounceDecay bounce_decay(const TransientResult& r, int max_peaks) {
  if (!r.hub_steps.empty()) {
    BounceDecay d = dense_decay(r.hub_steps, max_peaks);
    d.from_steps = true;
    return d;
  }
  return sampled_decay(r, max_peaks);
}

BounceDecay sampled_bounce_decay(const TransientResult& r, int max_peaks) {
  return sampled_decay(r, max_peaks);
}

}  // namespace modaltyre::transient
