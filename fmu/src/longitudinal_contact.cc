#include "modaltyre/fmu/longitudinal_contact.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::fmu {
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
    : p_(p), lo_(lo), hi_(hi), n_(std::max(0, hi - lo + 1)), points_(n_) {}

void LongitudinalContact::shift(int units) {
  if (n_ == 0 || units == 0) return;
  // Forward rolling (units > 0): the element over unit i moves to unit i - units; the slots
  // that left at the rear (the lowest units) come back at the front as fresh rubber.
  const int k = std::min(std::abs(units), n_);
  if (units > 0) {
    for (int j = 0; j < k; ++j) point(lo_ + j) = ground::ShearPoint{};
    head_ = (head_ + k) % n_;
    sheared_lo_ -= k, sheared_hi_ -= k;
  } else {
    for (int j = 0; j < k; ++j) point(hi_ - j) = ground::ShearPoint{};
    head_ = (head_ - k + n_) % n_;
    sheared_lo_ += k, sheared_hi_ += k;
  }
  sheared_lo_ = std::max(sheared_lo_, lo_);
  sheared_hi_ = std::min(sheared_hi_, hi_);
}

void LongitudinalContact::substep(double dj0, const double* f, const ground::ShearLaw& law,
                                  const ground::CoulombFriction* coulomb, int a, int b) {
  const double A = p_.unit_area_m2, kA = p_.stick_stiffness_Pa_m * A, C = p_.carcass_compliance_m_N;
  // Trial at the last force (du = 0) and the elements' stiffness dF/dj there: on the road the
  // sticking elements' k_t A (exact while no element switches within the sub-step); on a soil
  // (Janosi-Hanamoto, a function of the total j) the slope of the law over a tenth of a
  // micrometre (one Newton step of the carcass coupling: the sub-step moves j by a unit's
  // length at most, against the soil's K of millimetres).
  constexpr double kSlopeStep_m = 1e-7;
  double trial = 0, stick = 0;
  for (int i = a; i <= b; ++i) {
    // A soil's law has a strength c at zero normal stress: only the loaded elements shear it.
    if (!coulomb && !(f[i] > 0)) continue;
    ground::ShearPoint pt = point(i);
    const double sigma = f[i] > 0 ? f[i] / A : 0.0;
    const double tau = law.advance(pt, sigma, dj0);
    trial += tau * A;
    if (coulomb) {
      if (!pt.sliding) stick += kA;
    } else {
      ground::ShearPoint q = point(i);
      stick += (law.advance(q, sigma, dj0 + kSlopeStep_m) - tau) * A / kSlopeStep_m;
    }
  }
  // F = F_trial - C K (F - F_old).
  const double F = (trial + C * stick * force_N_) / (1 + C * stick);
  const double dj = dj0 - C * (F - force_N_);
  double sum = 0;
  int loaded = 0, sliding = 0, first = -1, last = -1;
  for (int i = a; i <= b; ++i) {
    if (!coulomb && !(f[i] > 0)) continue;
    ground::ShearPoint& pt = point(i);
    const double fi = f[i] > 0 ? f[i] : 0.0;
    sum += law.advance(pt, fi / A, dj) * A;
    // On the road an element out of contact keeps its spring's shear until it slides back;
    // on a soil the loaded range is the sheared one.
    if (coulomb && pt.elastic_m != 0) {
      first = first < 0 ? i : first;
      last = i;
    }
    if (fi > 0) {
      ++loaded;
      sliding += pt.sliding;
    }
  }
  force_N_ = sum;
  ux_m_ = C * sum;
  sliding_share_ = loaded > 0 ? double(sliding) / loaded : 0;
  sheared_lo_ = first < 0 ? 0 : first;
  sheared_hi_ = first < 0 ? -1 : last;
}

void LongitudinalContact::advance(double dt, const double* f, double spin, double speed,
                                  double mu) {
  const ground::CoulombFriction law(mu, p_.stick_stiffness_Pa_m);
  advance(dt, f, spin, speed, law);
}

void LongitudinalContact::advance(double dt, const double* f, double spin, double speed,
                                  const ground::ShearLaw& law) {
  if (n_ == 0 || !(dt > 0)) return;
  const auto* coulomb = dynamic_cast<const ground::CoulombFriction*>(&law);
  // The loaded units (the forces hold over the whole advance).
  int a = -1, b = -2;
  for (int i = lo_; i <= hi_; ++i)
    if (f[i] > 0) {
      a = a < 0 ? i : a;
      b = i;
    }
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
    // Elements that carry no force and no shear stay as they are: skip them.
    int from = a, to = b;
    if (sheared_hi_ >= sheared_lo_) {
      from = from < 0 ? sheared_lo_ : std::min(from, sheared_lo_);
      to = std::max(to, sheared_hi_);
    }
    if (from < 0 || to < from) {
      force_N_ = ux_m_ = sliding_share_ = 0;
      continue;
    }
    substep((material - speed) * h, f, law, coulomb, from, to);
  }
}

}  // namespace modaltyre::fmu
