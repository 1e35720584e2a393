#include "modaltyre/modal/ring_model.h"

#include <Eigen/Dense>
#include <cmath>
#include <set>

#include "modaltyre/core/errors.h"
#include "small_nnls.h"

namespace modaltyre::modal {
namespace {
constexpr double kTwoPi = 6.28318530717958647692;
constexpr int kCoefficients = 4;

// The four basis functions of K_n / mu at order n.
Eigen::Vector4d basis_row(int n) {
  const double n2 = double(n) * n;
  return {1.0, n2 - 1.0, (n2 - 1.0) * (n2 - 1.0), 1.0 / n2};
}
}  // namespace

double ring_mass_factor(int n) {
  MODALTYRE_CHECK(n >= 1, "ring mass factor of order < 1");
  return 1.0 + 1.0 / (double(n) * n);
}

double RingCoefficients::stiffness_per_mass(int n) const {
  const Eigen::Vector4d r = basis_row(n);
  return radial_foundation * r(0) + tension * r(1) + bending * r(2) + tangential_foundation * r(3);
}

double RingCoefficients::omega_sq(int n) const {
  return stiffness_per_mass(n) / ring_mass_factor(n);
}

RingFit fit_ring(const std::vector<int>& orders, const std::vector<double>& freq_hz) {
  RingFit fit;
  MODALTYRE_CHECK(orders.size() == freq_hz.size(), "orders and frequencies differ in length");
  std::vector<int> ns;
  std::vector<double> y;
  std::set<int> distinct;
  for (std::size_t i = 0; i < orders.size(); ++i) {
    if (orders[i] < 1) continue;
    MODALTYRE_CHECK(freq_hz[i] > 0 && std::isfinite(freq_hz[i]), "non-positive frequency");
    ns.push_back(orders[i]);
    y.push_back(std::pow(kTwoPi * freq_hz[i], 2) * ring_mass_factor(orders[i]));
    distinct.insert(orders[i]);
  }
  fit.orders_used = static_cast<int>(distinct.size());
  if (distinct.size() < 2) {
    fit.reason = "needs modes of at least two orders >= 1, got " + std::to_string(distinct.size());
    return fit;
  }
  const int m = static_cast<int>(ns.size());
  Eigen::MatrixXd X(m, kCoefficients);
  for (int i = 0; i < m; ++i) X.row(i) = basis_row(ns[i]).transpose() / y[i];
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m);
  Eigen::VectorXd best_c;
  if (!detail::small_nnls(X, ones, fit.orders_used, best_c)) {
    fit.reason = "no non-negative ring fit exists for these frequencies";
    return fit;
  }
  fit.valid = true;
  fit.coefficients = {best_c(0), best_c(1), best_c(2), best_c(3)};
  double se = 0;
  for (int i = 0; i < m; ++i) {
    const double rel = std::sqrt(fit.coefficients.stiffness_per_mass(ns[i]) / y[i]) - 1.0;
    se += rel * rel;
  }
  fit.rms_rel_error = std::sqrt(se / m);
  return fit;
}

double mass_per_length_from_tension(const RingCoefficients& c, double pressure_Pa,
                                    double belt_width_m, double radius_m) {
  MODALTYRE_CHECK(c.tension > 0 && pressure_Pa > 0 && belt_width_m > 0 && radius_m > 0,
                  "mass from tension needs a positive tension term, pressure, width and radius");
  return pressure_Pa * belt_width_m / (radius_m * c.tension);
}

double implied_tension_N(const RingCoefficients& c, double mass_per_length_kg_m, double radius_m) {
  return mass_per_length_kg_m * radius_m * radius_m * c.tension;
}

double net_hoop_tension_N(double pressure_Pa, const BeltSection& s) {
  MODALTYRE_CHECK(pressure_Pa > 0 && s.belt_width_m > 0 && s.edge_radius_m > 0 &&
                      s.max_width_radius_m > 0 && s.max_width_radius_m <= s.edge_radius_m &&
                      s.edge_angle_rad >= 0 && s.edge_angle_rad < M_PI / 2,
                  "net hoop tension needs p, b > 0, 0 < r_m <= r_e and 0 <= psi_e < 90 deg");
  const double re = s.edge_radius_m, rm = s.max_width_radius_m;
  return pressure_Pa * (s.belt_width_m * re - (re * re - rm * rm) * std::tan(s.edge_angle_rad));
}

double rim_held_frequency_hz(double free_hz, double belt_mass, double wheel_mass) {
  MODALTYRE_CHECK(belt_mass > 0 && wheel_mass > 0, "masses must be positive");
  return free_hz * std::sqrt(wheel_mass / (belt_mass + wheel_mass));
}

RingCoefficients at_pressure(const RingCoefficients& c, double test_pressure_Pa, double pressure_Pa,
                             double foundation_pneumatic_fraction) {
  MODALTYRE_CHECK(test_pressure_Pa > 0 && pressure_Pa > 0, "pressures must be positive");
  const double ratio = pressure_Pa / test_pressure_Pa;
  const double f = foundation_pneumatic_fraction;
  const double foundation = (1 - f) + f * ratio;
  return {c.radial_foundation * foundation, c.tension * ratio, c.bending,
          c.tangential_foundation * foundation};
}

}  // namespace modaltyre::modal
