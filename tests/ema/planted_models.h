#pragma once
// Planted modal models for the EMA tests: the bundled SF-350 hammer data (16 modes, 12
// points, radial and tangential; configs/data/sf350_hammer_12pt.csv) and a ring-like model
// after issue 19 (one mode per harmonic order, >= 8 % apart, 1-5 % damping, modes outside the
// band on both sides).
#include <cmath>
#include <string>

#include "modaltyre/modal/hammer_data.h"
#include "synthetic_frf.h"

namespace modaltyre_test {

inline std::string bundled_hammer_path() {
  return std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_hammer_12pt.csv";
}

inline PlantedModel bundled_model() {
  const auto data = modaltyre::modal::read_hammer_csv(bundled_hammer_path());
  PlantedModel m;
  m.points = data.points;
  for (const auto& mode : data.modes) {
    m.modes.push_back({mode.freq_hz, mode.damping_ratio, mode.radial, mode.tangential});
  }
  return m;
}

/// Ring modes of order k: radial a cos k(theta - psi), tangential -(a/k) sin k(theta - psi)
/// (inextensional ring), a^2 = 1 / (pi mu R) (half for k = 0), mu = 2.5 kg/m, R = 0.3 m.
/// In band (60-330 Hz): orders 0, 2, 3, 4, 5 and a second order-1 family at 98 ... 275 Hz, each
/// >= 8 % from the next; out of band: an order-1 support mode at 25 Hz and order 3 at 420 Hz.
inline PlantedModel ring_model(int points = 12) {
  constexpr double kPi = 3.14159265358979323846;
  const double mu = 2.5, R = 0.3;
  struct Spec {
    int k;
    double f, zeta, psi;
  };
  const Spec specs[] = {{0, 98, 0.05, 0},     {1, 25, 0.04, 0.2},   {2, 121, 0.03, 0.3},
                        {3, 150, 0.025, 0.1}, {4, 186, 0.02, -0.2}, {5, 228, 0.015, 0.05},
                        {1, 275, 0.012, 1.1}, {3, 420, 0.02, 0.0}};
  PlantedModel m;
  m.points = points;
  for (const auto& s : specs) {
    const double a = std::sqrt((s.k == 0 ? 0.5 : 1.0) / (kPi * mu * R));
    PlantedMode mode{s.f, s.zeta, {}, {}};
    for (int i = 0; i < points; ++i) {
      const double th = 2 * kPi * i / points;
      mode.radial.push_back(a * std::cos(s.k * (th - s.psi)));
      mode.tangential.push_back(s.k == 0 ? 0.1 * a : -a / s.k * std::sin(s.k * (th - s.psi)));
    }
    m.modes.push_back(mode);
  }
  return m;
}

}  // namespace modaltyre_test
