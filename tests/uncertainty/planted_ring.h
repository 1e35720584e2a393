#pragma once
// A planted 12-point hammer set for the uncertainty tests (data/README's recipe: radial
// a cos k(theta - psi), tangential (a/k) sin, a^2 = 1 / (pi mu R), order 0 1 / (2 pi mu R)),
// orders 0-5, mu 2.5 kg/m, R 0.2948 m, frequencies of a ring with foundation and tension;
// Gaussian noise sigma on every value, optionally the standard-deviation columns `ema` writes.
#include <cmath>
#include <random>
#include <sstream>
#include <string>

namespace modaltyre_test {

struct PlantedRing {
  double sigma = 0;  ///< shape noise [kg^-1/2]
  unsigned seed = 1;
  int precision = 6;  ///< digits of the CSV's numbers
  /// >= 0: the columns freq_std_hz (= freq_std_rel f), damping_std, radial_std, tangential_std
  /// (= shape_std); radial_std left out of the header when !radial_std_column.
  double freq_std_rel = -1, shape_std = 0;
  bool radial_std_column = true;
};

inline std::string planted_ring_csv(const PlantedRing& o) {
  constexpr double kTwoPi = 6.28318530717958647692;
  const double mu = 2.5, R = 0.2948;
  const bool with_std = o.freq_std_rel >= 0;
  std::mt19937 rng(o.seed);
  std::normal_distribution<double> noise(0.0, o.sigma);
  std::ostringstream s;
  s.precision(o.precision);
  s << "mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential";
  if (with_std) {
    s << ",freq_std_hz,damping_std," << (o.radial_std_column ? "radial_std," : "")
      << "tangential_std";
  }
  s << "\n";
  const int orders[] = {1, 0, 2, 3, 4, 5};
  for (int i = 0; i < 6; ++i) {
    const int k = orders[i];
    const double w2 = 1.9e6 / mu + 4.3e4 * k * k + 90.0 * std::pow(k, 4);
    const double f = std::sqrt(w2) / kTwoPi + (k == 0 ? 5.0 : 0.0);
    const double a = std::sqrt(1 / ((k == 0 ? 2 : 1) * M_PI * mu * R));
    const double psi = 0.3 * i;
    for (int p = 0; p < 12; ++p) {
      const double th = kTwoPi * p / 12;
      const double r = a * std::cos(k * (th - psi)) + (o.sigma > 0 ? noise(rng) : 0.0);
      const double t =
          (k > 0 ? a / k * std::sin(k * (th - psi)) : 0.0) + (o.sigma > 0 ? noise(rng) : 0.0);
      s << i + 1 << "," << f << ",0.03," << p + 1 << "," << 30.0 * p << "," << r << "," << t;
      if (with_std) {
        s << "," << o.freq_std_rel * f << ",0.001,";
        if (o.radial_std_column) s << o.shape_std << ",";
        s << o.shape_std;
      }
      s << "\n";
    }
  }
  return s.str();
}

}  // namespace modaltyre_test
