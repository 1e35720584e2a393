#include "modaltyre/fmu/longitudinal_contact.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::fmu {
namespace {

/// Newton iterations on the scalar force equation before bisection takes over; the residual
/// is piecewise linear in F, so Newton ends in as many steps as elements change between
/// stick and slip, usually one or two.
constexpr int kNewtonIterations = 30;
/// The force equation is solved to this fraction of the largest element force plus 1e-9 N.
constexpr double kForceTolerance = 1e-12;

}  // namespace

LongitudinalProperties longitudinal_properties(const contact::TyreModel& m,
                                               const Eigen::VectorXd& f) {
  LongitudinalProperties p;
  const double area = m.config.tread.width_m * m.unit_length_m;
  p.unit_area_m2 = area;
  p.unit_length_m = m.unit_length_m;
  p.stick_stiffness_Pa_m = m.k_tangential_N_m / area;
  p.base_radius_m = m.config.outer_radius_m - m.config.tread.thickness_m;
  // Mean horizontal displacement of the loaded units per unit total horizontal force spread
  // evenly over them: a horizontal (+x) force at j has f_r = -sin theta_j, f_t = cos theta_j;
  // the horizontal displacement at i is -u_r sin theta_i + u_t cos theta_i.
  std::vector<int> loaded;
  for (int i = 0; i < m.candidates(); ++i)
    if (f(i) > 0) loaded.push_back(i);
  MODALTYRE_CHECK(!loaded.empty(), "longitudinal_properties: no unit in contact");
  double sum = 0;
  for (int j : loaded) {
    const double cj = std::cos(m.theta[j]), sj = std::sin(m.theta[j]);
    for (int i : loaded) {
      const double ci = std::cos(m.theta[i]), si = std::sin(m.theta[i]);
      const modal::Transfer2x2 h = m.kernels.at(i - j);
      const double ur = -h.r_from_r * sj + h.r_from_t * cj;
      const double ut = -h.t_from_r * sj + h.t_from_t * cj;
      sum += -ur * si + ut * ci;
    }
  }
  const double n = static_cast<double>(loaded.size());
  p.carcass_compliance_m_N = std::max(0.0, sum / (n * n));
  return p;
}

LongitudinalContact::LongitudinalContact(const LongitudinalProperties& p, int lo, int hi)
    : p_(p),
      lo_(lo),
      hi_(hi),
      points_(std::max(0, hi - lo + 1)),
      unit_force_N_(std::max(0, hi - lo + 1), 0.0) {}

void LongitudinalContact::shift(int units) {
  // Material moves backward (toward lower theta) for forward rolling: element i takes element
  // i + 1's place; fresh rubber enters at the front (hi). Reverse rolling the other way.
  const int n = static_cast<int>(points_.size());
  if (units > 0) {
    const int k = std::min(units, n);
    std::move(points_.begin() + k, points_.end(), points_.begin());
    std::fill(points_.end() - k, points_.end(), ground::ShearPoint{});
  } else if (units < 0) {
    const int k = std::min(-units, n);
    std::move_backward(points_.begin(), points_.end() - k, points_.end());
    std::fill(points_.begin(), points_.begin() + k, ground::ShearPoint{});
  }
}

double LongitudinalContact::residual(double F, double dj0, const double* f,
                                     const ground::CoulombFriction& law, double* slope) {
  const double dj = dj0 - p_.carcass_compliance_m_N * (F - force_N_);
  const double A = p_.unit_area_m2;
  double sum = 0, stick = 0;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const double fk = f[lo_ + static_cast<int>(k)];
    ground::ShearPoint trial = points_[k];
    if (!(fk > 0) && trial.elastic_m == 0) continue;
    const double tau = law.advance(trial, std::max(fk, 0.0) / A, dj);
    sum += tau * A;
    if (!trial.sliding) stick += p_.stick_stiffness_Pa_m * A;
  }
  *slope = 1 + p_.carcass_compliance_m_N * stick;
  return F - sum;
}

void LongitudinalContact::commit(double F, double dj0, const double* f,
                                 const ground::CoulombFriction& law) {
  const double dj = dj0 - p_.carcass_compliance_m_N * (F - force_N_);
  const double A = p_.unit_area_m2;
  double sum = 0;
  int loaded = 0, sliding = 0;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const double fk = f[lo_ + static_cast<int>(k)];
    ground::ShearPoint& pt = points_[k];
    if (!(fk > 0) && pt.elastic_m == 0) {
      unit_force_N_[k] = 0;
      continue;
    }
    const double tau = law.advance(pt, std::max(fk, 0.0) / A, dj);
    unit_force_N_[k] = tau * A;
    sum += tau * A;
    if (fk > 0) {
      ++loaded;
      sliding += pt.sliding;
    }
  }
  ux_m_ = p_.carcass_compliance_m_N * sum;
  force_N_ = sum;
  sliding_share_ = loaded > 0 ? double(sliding) / loaded : 0;
}

void LongitudinalContact::advance(double dt, const double* f, double spin, double speed,
                                  double mu) {
  if (points_.empty() || !(dt > 0)) return;
  const ground::CoulombFriction law(mu, p_.stick_stiffness_Pa_m);
  const double material = spin * p_.base_radius_m;  // backward through the units [m/s]
  // Sub-steps of at most one unit of travel, so that an element's shear follows its position.
  const int sub =
      std::max(1, static_cast<int>(std::ceil(std::abs(material) * dt / p_.unit_length_m)));
  const double h = dt / sub;
  for (int s = 0; s < sub; ++s) {
    carry_ += material * h / p_.unit_length_m;
    const int whole = static_cast<int>(carry_);  // toward zero
    if (whole != 0) {
      shift(whole);
      carry_ -= whole;
    }
    const double dj0 = (material - speed) * h;
    // Solve F = sum tau(dj0 - C (F - F_old)) A: Newton on the piecewise-linear monotone
    // residual (slope >= 1), bracketed and bisected if it ever fails to contract.
    double F = force_N_, slope = 1;
    double r = residual(F, dj0, f, law, &slope);
    double lo = -1e300, hi = 1e300;
    const double tol = kForceTolerance * (std::abs(F) + 1) + 1e-9;
    for (int it = 0; it < kNewtonIterations && std::abs(r) > tol; ++it) {
      (r > 0 ? hi : lo) = F;
      double next = F - r / slope;
      if (!(next > lo && next < hi) && lo > -1e300 && hi < 1e300) next = 0.5 * (lo + hi);
      F = next;
      r = residual(F, dj0, f, law, &slope);
    }
    commit(F, dj0, f, law);
  }
}

}  // namespace modaltyre::fmu
