#pragma once
// The free vibration's period and logarithmic decrement from the hub bounce (the definition of
// issue 21's reference metrics, tests/transient/decay_metrics.h and
// scripts/transient_reference_metrics.sh): maxima of z - mean(z over the last 20 % of the run),
// each refined by the parabola through its neighbours; least-squares slopes of their times and
// of the logarithms of their amplitudes over the first `max_peaks`.
#include "modaltyre/transient/driver.h"

namespace modaltyre::transient {

struct BounceDecay {
  int peaks = 0;  ///< maxima used (period and decrement need at least 2)
  double period_s = 0, log_decrement = 0;
};

BounceDecay bounce_decay(const TransientResult& r, int max_peaks = 8);

}  // namespace modaltyre::transient
