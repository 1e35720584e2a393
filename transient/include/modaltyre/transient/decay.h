#pragma once
// The free vibration's period and logarithmic decrement from the hub bounce (the definition of
// issue 21's reference metrics, tests/transient/decay_metrics.h and
// scripts/transient_reference_metrics.sh): maxima of z - mean(z over the last 20 % of the run);
// least-squares slopes of their times and of the logarithms of their amplitudes over the first
// `max_peaks`. From the integrator's step ends when the run kept the hub's trace
// (TransientResult::hub_steps; one peak per excursion above the mean), else from the output
// samples; each maximum refined by the parabola through its neighbours (issue 44: on a 10 ms
// grid the samples read 0.098 for a decrement of 0.0914).
#include "modaltyre/transient/driver.h"

namespace modaltyre::transient {

struct BounceDecay {
  int peaks = 0;  ///< maxima used (period and decrement need at least 2)
  double period_s = 0, log_decrement = 0;
  bool from_steps = false;  ///< from the integrator's steps (else the output samples)
  /// The damping ratio of a single-degree oscillator with this decrement:
  /// zeta = delta / sqrt(4 pi^2 + delta^2).
  double damping_ratio() const;
};

BounceDecay bounce_decay(const TransientResult& r, int max_peaks = 8);
/// The same on the output samples only (the definition at the output grid).
BounceDecay sampled_bounce_decay(const TransientResult& r, int max_peaks = 8);

}  // namespace modaltyre::transient
