#include "modaltyre/modal/mode_identification.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace modaltyre::modal {

const char* to_string(ModeKind kind) {
  switch (kind) {
    case ModeKind::radial:
      return "radial";
    case ModeKind::rotation:
      return "rotation";
    case ModeKind::unresolved:
      return "unresolved";
  }
  return "unresolved";
}

namespace {

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s / std::max<std::size_t>(v.size(), 1));
}

/// Orders that show up as apparent order k with N points, from `at_least` upwards.
std::vector<int> alias_candidates(int k, int N, int at_least) {
  std::vector<int> out;
  for (int j = 0; j <= 4; ++j) {
    for (int c : {j * N - k, j * N + k}) {
      if (c >= std::max(at_least, 0) && c != k && std::find(out.begin(), out.end(), c) == out.end())
        out.push_back(c);
    }
  }
  if (k == N / 2 && N % 2 == 0 && k >= at_least) out.insert(out.begin(), k);
  std::sort(out.begin(), out.end());
  return out;
}

// The one-harmonic model's residual as the shapes' noise and the covariance of its
// coefficient (orthogonal columns at equally spaced points: |cos|^2 = N/2, N at order 0 and N/2).
void set_shape_noise(IdentifiedMode& id, int N) {
  const int k = id.apparent_order;
  const bool single = k == 0 || (N % 2 == 0 && k == N / 2);
  const int p = single ? 1 : 2;
  if (N <= p) return;
  const double norm2 = single ? N : 0.5 * N;
  auto noise = [&](const HarmonicSeries& h) {
    const double residual = std::max(h.energy - h.order_energy(k), 0.0);
    return std::sqrt(residual / (N - p));
  };
  // Both estimate the same noise; the residual also holds what is not one ring harmonic, the
  // EMA's covariance the FRFs' noise only: the larger is kept (docs/uncertainty.md section 5).
  id.radial_noise = std::max(noise(id.radial), id.radial_noise_stated);
  id.tangential_noise = std::max(noise(id.tangential), id.tangential_noise_stated);
  id.c_radial_std = id.radial_noise / std::sqrt(norm2);
  id.c_tangential_std = id.tangential_noise / std::sqrt(norm2);
  // |c|^2 = A^2 + B^2: var = 4 |c|^2 var(A) for two components (4 A^2 var(A) for one).
  const double amp =
      std::abs(id.kind == ModeKind::rotation ? id.tangential.coefficient(0) : id.c_radial);
  const double std_c = id.kind == ModeKind::rotation ? id.c_tangential_std : id.c_radial_std;
  id.amplitude2_rel_std = amp > 0 ? 2 * std_c / amp : 0;
}

}  // namespace

ModeIdentification identify_modes(const HammerData& data, const IdentificationOptions& opts) {
  ModeIdentification out;
  out.points = data.points;
  const int N = data.points;
  const int nyquist = (N % 2 == 0) ? N / 2 : -1;

  for (const auto& m : data.modes) {
    IdentifiedMode id;
    id.id = m.id;
    id.freq_hz = m.freq_hz;
    id.damping_ratio = m.damping_ratio;
    id.radial = fit_harmonics(m.angle_rad, m.radial);
    id.tangential = fit_harmonics(m.angle_rad, m.tangential);
    const double r_rms = rms(m.radial), t_rms = rms(m.tangential);
    if (r_rms < opts.rotation_radial_ratio * t_rms && id.tangential.r2(0) >= opts.rotation_min_r2) {
      id.kind = ModeKind::rotation;
      id.apparent_order = 0;
      id.r2 = id.tangential.r2(0);
      id.note = "rigid rotation about the axle (tangential, no radial motion)";
    } else {
      id.apparent_order = id.radial.dominant_order();
      id.r2 = id.radial.r2(id.apparent_order);
      id.kind = id.r2 >= opts.min_harmonic_r2 ? ModeKind::radial : ModeKind::unresolved;
      if (id.kind == ModeKind::unresolved) id.note = "no single harmonic dominates the shape";
      if (id.apparent_order == nyquist) {
        id.aliased = true;
        id.note = "fits at the Nyquist order N/2 = " + std::to_string(nyquist) +
                  ": true order is N/2 or higher";
      }
    }
    id.c_radial = id.radial.coefficient(id.apparent_order);
    id.c_tangential = id.tangential.coefficient(id.apparent_order);
    id.freq_std_hz = m.freq_std_hz;
    id.damping_std = m.damping_std;
    id.radial_noise_stated = rms(m.radial_std);
    id.tangential_noise_stated = rms(m.tangential_std);
    set_shape_noise(id, N);
    out.modes.push_back(std::move(id));
  }

  // Aliasing by frequency ordering along the radial family (orders >= 2).
  std::vector<std::size_t> by_freq(out.modes.size());
  std::iota(by_freq.begin(), by_freq.end(), 0);
  std::stable_sort(by_freq.begin(), by_freq.end(), [&](std::size_t a, std::size_t b) {
    return out.modes[a].freq_hz < out.modes[b].freq_hz;
  });
  int highest_below = 0;  // smallest possible true order of the highest mode seen so far
  int highest_id = 0;
  for (std::size_t idx : by_freq) {
    auto& m = out.modes[idx];
    if (m.kind != ModeKind::radial) continue;
    const int k = m.apparent_order;
    if (m.aliased) {
      if (k > highest_below) highest_below = k, highest_id = m.id;
      continue;
    }
    // Apparent orders 0 and 1 are also breathing and rigid translation, which are not in the
    // radial family and may lie above its low orders: they count as folded only above the
    // family order just below the lowest order that folds onto them (N - k - 1).
    const bool family_evidence = k >= 2 || highest_below >= N - k - 1;
    if (highest_below >= 2 && k < highest_below && family_evidence) {
      m.aliased = true;
      m.note = "fits as order " + std::to_string(k) + " but lies above mode " +
               std::to_string(highest_id) + " of order " + std::to_string(highest_below) +
               ": aliased from a higher order";
      const auto c = alias_candidates(k, N, highest_below);
      const int floor_k = c.empty() ? k : c.front();
      if (floor_k > highest_below) highest_below = floor_k, highest_id = m.id;
    } else if (k > highest_below) {
      highest_below = k;
      highest_id = m.id;
    }
  }

  std::vector<int> orders;
  std::vector<double> freqs;
  for (const auto& m : out.modes) {
    if (m.kind == ModeKind::radial && !m.aliased) {
      orders.push_back(m.apparent_order);
      freqs.push_back(m.freq_hz);
    }
  }
  out.dispersion = fit_dispersion(orders, freqs);

  int floor_order = 0;
  for (std::size_t idx : by_freq) {
    auto& m = out.modes[idx];
    if (m.kind != ModeKind::radial) continue;
    if (!m.aliased) {
      floor_order = std::max(floor_order, m.apparent_order);
      continue;
    }
    m.alias_candidates = alias_candidates(m.apparent_order, N, floor_order);
    // Keep only candidates that cannot be resolved with N points.
    std::erase_if(m.alias_candidates, [&](int c) { return 2 * c < N; });
    if (out.dispersion.valid && !m.alias_candidates.empty()) {
      double best = 1e300;
      for (int c : m.alias_candidates) {
        if (c < floor_order) continue;
        const double err = std::abs(std::log(out.dispersion.freq_hz(c) / m.freq_hz));
        if (err < best) {
          best = err;
          m.likely_order = c;
        }
      }
      if (m.likely_order >= 0) floor_order = std::max(floor_order, m.likely_order);
    }
  }
  return out;
}

}  // namespace modaltyre::modal
