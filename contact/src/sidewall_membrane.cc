#include "modaltyre/contact/sidewall_membrane.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace modaltyre::contact {

void SidewallMembrane::validate() const {
  if (!(chord_m > 0) || !(length_m > chord_m) || !std::isfinite(length_m)) {
    throw std::invalid_argument("sidewall meridian: need 0 < chord < length");
  }
}

double meridian_half_angle(double ratio) {
  if (!(ratio > 0 && ratio < 1)) return std::numeric_limits<double>::quiet_NaN();
  // h(a) = sin(a) - ratio a: positive below the root, negative above it on (0, pi) (sin(a) / a
  // falls from 1 to 0). Newton steps from the small-angle root sqrt(6 (1 - ratio)), kept inside
  // the bracket by bisection: 4-6 steps where plain bisection takes about 55 (the 3D patch's
  // fixed point evaluates this for every section at every step).
  double lo = 0, hi = M_PI;
  double a = std::min(std::sqrt(6 * (1 - ratio)), 0.5 * M_PI);
  for (int k = 0; k < 200; ++k) {
    const double h = std::sin(a) - ratio * a;
    (h > 0 ? lo : hi) = a;
    if (h == 0) return a;
    double next = a - h / (std::cos(a) - ratio);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - a) <= 4 * std::numeric_limits<double>::epsilon() * a || next <= lo ||
        next >= hi) {
      return next;
    }
    a = next;
  }
  return a;
}

double sidewall_pull_N_per_m(double pressure_Pa, double length_m, double chord_m) {
  const double a = meridian_half_angle(chord_m / length_m);
  return 0.5 * pressure_Pa * length_m * std::cos(a) / a;
}

double sidewall_stiffness_N_per_m2(double pressure_Pa, double length_m, double chord_m) {
  // dF/dc = (dF/da) / (dc/da), c = L sin(a) / a.
  const double a = meridian_half_angle(chord_m / length_m);
  const double s = std::sin(a), c = std::cos(a);
  return 0.5 * pressure_Pa * (a * s + c) / (s - a * c);
}

SidewallLostForce::SidewallLostForce(const SidewallMembrane& s, double pressure_Pa)
    : active_(s.enabled && pressure_Pa != 0),
      pressure_Pa_(pressure_Pa),
      chord_m_(s.chord_m),
      length_m_(s.length_m) {
  if (!active_) return;
  pull0_N_per_m_ = sidewall_pull_N_per_m(pressure_Pa_, length_m_, chord_m_);
  stiffness0_N_per_m2_ = sidewall_stiffness_N_per_m2(pressure_Pa_, length_m_, chord_m_);
}

double SidewallLostForce::operator()(double u_m) const {
  if (!active_ || u_m == 0) return 0;
  const double linear = stiffness0_N_per_m2_ * u_m;
  const double restoring =
      pull0_N_per_m_ - sidewall_pull_N_per_m(pressure_Pa_, length_m_, chord_m_ - u_m);
  return 2 * (linear - restoring);
}

double sidewall_lost_force_N_per_m(const SidewallMembrane& s, double pressure_Pa, double u_m) {
  return SidewallLostForce(s, pressure_Pa)(u_m);
}

}  // namespace modaltyre::contact
