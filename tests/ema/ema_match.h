#pragma once
// Matching identified modes to planted ones, and the figures the EMA tests check: frequency
// and damping errors, MAC of the 2N-vector (radial then tangential), the mass-normalised
// amplitude as the least-squares scale between identified and planted shapes (1 = exact), and
// the driving-point value.
#include <cmath>
#include <vector>

#include "modaltyre/ema/ema.h"
#include "synthetic_frf.h"

namespace modaltyre_test {

struct ModeMatch {
  const PlantedMode* planted = nullptr;
  const modaltyre::ema::EmaMode* found = nullptr;
  double freq_err = 0, damping_err = 0;  ///< relative
  double mac = 0;
  double scale = 0;        ///< |<found, planted>| / <planted, planted>
  double driving_err = 0;  ///< relative error of the value at the reference DOF
};

inline std::vector<double> stacked(const std::vector<double>& r, const std::vector<double>& t) {
  std::vector<double> v = r;
  v.insert(v.end(), t.begin(), t.end());
  return v;
}

/// The identified mode nearest in frequency to `p`, with its figures; found == nullptr when no
/// identified mode lies within `window` (relative) of it.
inline ModeMatch match(const PlantedMode& p, const modaltyre::ema::EmaResult& r,
                       double driving_planted, int driving_index, double window = 0.02) {
  ModeMatch m;
  m.planted = &p;
  for (const auto& e : r.modes) {
    if (std::abs(e.freq_hz / p.freq_hz - 1) > window) continue;
    if (!m.found || std::abs(e.freq_hz - p.freq_hz) < std::abs(m.found->freq_hz - p.freq_hz))
      m.found = &e;
  }
  if (!m.found) return m;
  const auto a = stacked(m.found->radial, m.found->tangential);
  const auto b = stacked(p.radial, p.tangential);
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::isnan(a[i])) continue;  // a DOF no FRF measured (ema leaves it out of the shape)
    ab += a[i] * b[i], aa += a[i] * a[i], bb += b[i] * b[i];
  }
  m.freq_err = m.found->freq_hz / p.freq_hz - 1;
  m.damping_err = m.found->damping_ratio / p.damping_ratio - 1;
  m.mac = ab * ab / (aa * bb);
  m.scale = std::abs(ab) / bb;
  m.driving_err = std::abs(m.found->radial[driving_index]) / std::abs(driving_planted) - 1;
  return m;
}

}  // namespace modaltyre_test
