#pragma once
// Means over a time window (transient_test.cc, soil_transient_test.cc), and the free
// vibration's period and logarithmic decrement as issue 21 defines them (shared by
// reference_test.cc and tread_window_test.cc; scripts/transient_reference_metrics.sh computes
// the same from the CSV).
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "modaltyre/transient/driver.h"

namespace modaltyre::transient {

/// Mean of a sample quantity over [t0, t1] (NaN without samples there).
template <class F>
double mean_over(const TransientResult& r, double t0, double t1, F get) {
  double s = 0;
  int n = 0;
  for (const auto& x : r.samples)
    if (x.t_s >= t0 && x.t_s < t1 + 1e-12) s += get(x), ++n;
  return n ? s / n : NAN;
}

/// Least-squares slope of y over 0, 1, ..., n-1.
inline double least_squares_slope(const std::vector<double>& y) {
  const double n = static_cast<double>(y.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    sx += i, sy += y[i], sxx += double(i) * i, sxy += i * y[i];
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// Period and logarithmic decrement of the hub bounce: maxima of z - mean(z over t > 0.8 s),
/// each refined by the parabola through its neighbours; linear fits of their times and of the
/// logarithms of their amplitudes over the first `peaks`.
inline std::pair<double, double> bounce_period_and_decrement(const TransientResult& r, int peaks) {
  const auto& s = r.samples;
  double mean = 0;
  int n = 0;
  for (const auto& x : s)
    if (x.t_s > 0.8) mean += x.hub_displacement_m, ++n;
  mean /= n;
  std::vector<double> times, logs;
  for (std::size_t i = 1; i + 1 < s.size() && static_cast<int>(times.size()) < peaks; ++i) {
    const double a = s[i - 1].hub_displacement_m - mean, b = s[i].hub_displacement_m - mean,
                 c = s[i + 1].hub_displacement_m - mean;
    if (!(b > a && b >= c && b > 0)) continue;
    const double den = a - 2 * b + c;
    const double off = den != 0 ? 0.5 * (a - c) / den : 0.0;
    times.push_back(s[i].t_s + off * (s[1].t_s - s[0].t_s));
    logs.push_back(std::log(b - 0.25 * (a - c) * off));
  }
  EXPECT_EQ(static_cast<int>(times.size()), peaks);
  return {least_squares_slope(times), -least_squares_slope(logs)};
}

/// Peaks of the free vibration used for the period and decrement fits of the reference and
/// tread-window tests (the first eight: later ones are a few um, where the output's 2 ms
/// sampling limits the parabolic interpolation).
inline constexpr int kDecayPeaks = 8;

/// Period and logarithmic decrement of the hub bounce over the first kDecayPeaks maxima.
inline std::pair<double, double> period_and_decrement(const TransientResult& r) {
  return bounce_period_and_decrement(r, kDecayPeaks);
}

}  // namespace modaltyre::transient
