#include "modaltyre/ground/shear.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace modaltyre::ground {

void JanosiParams::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(cohesion_kPa >= 0 && cohesion_kPa <= 1e5)) bad("cohesion_kPa must be in [0, 1e5] kPa");
  if (!(friction_angle_deg >= 0 && friction_angle_deg <= 89))
    bad("friction_angle_deg must be in [0, 89] deg");
  if (!(shear_modulus_K_mm > 0 && shear_modulus_K_mm <= 1e4))
    bad("shear_modulus_K_mm must be in (0, 1e4] mm");
}

JanosiHanamoto::JanosiHanamoto(const JanosiParams& p)
    : c_Pa_(p.cohesion_kPa * 1e3),
      tan_phi_(std::tan(p.friction_angle_deg * M_PI / 180.0)),
      K_m_(p.shear_modulus_K_mm * 1e-3) {
  p.validate();
}

double JanosiHanamoto::strength_Pa(double sigma) const {
  return c_Pa_ + std::max(sigma, 0.0) * tan_phi_;
}

double JanosiHanamoto::stress_Pa(double sigma, double j) const {
  // -expm1(-x) = 1 - e^-x without cancellation at small j.
  return std::copysign(strength_Pa(sigma) * -std::expm1(-std::abs(j) / K_m_), j);
}

double JanosiHanamoto::advance(ShearPoint& point, double sigma, double dj) const {
  point.displacement_m += dj;
  point.elastic_m = point.displacement_m;
  return stress_Pa(sigma, point.displacement_m);
}

CoulombFriction::CoulombFriction(double mu, double k) : mu_(mu), k_(k) {
  if (!(mu >= 0 && mu <= 10))
    throw std::invalid_argument("friction coefficient must be in [0, 10]");
  if (!(k > 0 && std::isfinite(k)))
    throw std::invalid_argument("stick stiffness must be > 0 and finite");
}

double CoulombFriction::strength_Pa(double sigma) const { return mu_ * std::max(sigma, 0.0); }

double CoulombFriction::advance(ShearPoint& point, double sigma, double dj) const {
  point.displacement_m += dj;
  const double trial = point.elastic_m + dj;
  const double limit = strength_Pa(sigma) / k_;
  point.sliding = std::abs(trial) > limit;
  point.elastic_m = point.sliding ? std::copysign(limit, trial) : trial;
  return k_ * point.elastic_m;
}

}  // namespace modaltyre::ground
