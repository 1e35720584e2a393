#pragma once
// The tangential (longitudinal) contact of the tyre on the road in co-simulation: the tread's
// tangential springs with stick and slip at mu sigma (ground::CoulombFriction, the one
// tangential-contact law of the project, shared with the soil's Janosi-Hanamoto shear), carried
// through the patch by the rolling, in series with the carcass's longitudinal compliance.
//
// Each ground-fixed patch unit i (transient/, x_i = R0 sin theta_i) holds the tread element over
// it: a ground::ShearPoint (its shear displacement j and elastic part e). Material moves
// backward through the units at the tread base's speed Omega R_b (R_b = R0 - tread thickness:
// the inextensible belt under the tread carries the base at the belt's speed; slip ratio
// (Omega R_b - V) / V), fresh elements (j = e = 0) entering at the front. Over a time dt an
// element in contact shears by
//   dj = (Omega R_b - V) dt - du_x      (seed 001's horizontal tread force f_x = k_t e, eq. 6;
//                                       the ground module's sign: j > 0 pushes the tyre forward)
// where u_x = C_x F_x is the carcass's longitudinal displacement at the patch under the total
// tangential force F_x (quasi-static, lumped: C_x is the mean over the static patch of the
// horizontal-from-horizontal compliance of seed 001's transfer functions, eq. 1-4 with the
// horizontal forces of eq. 12). Its stress is the Coulomb law's tau(sigma_i, e) with sigma_i =
// f_i / A (f_i the unit's vertical force from the transient, A its area); F_x = sum tau_i A.
// F_x and u_x are solved together at each sub-step of at most one unit of travel: a trial pass
// at the last force gives the sticking elements' stiffness K, F = (F_trial + C_x K F_old) /
// (1 + C_x K) (exact while no element changes between stick and slip in the sub-step), and the
// commit pass applies the law at that F. Steady state:
// the brush model, C_kappa = 2 c_px a^2 (Pacejka, Tyre and Vehicle Dynamics, 3rd ed., sec. 3.2)
// for c_px = k_t / ds the tread's stiffness per unit length.
//
// What this leaves out (docs/fmu.md): the tangential forces do not act back on the transient's
// modal carcass (its modal equations take vertical forces only), so F_x changes neither F_z
// nor the pressure distribution; u_x is quasi-static (no longitudinal carcass inertia).
#include <Eigen/Dense>
#include <vector>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/ground/shear.h"

namespace modaltyre::fmu {

struct LongitudinalProperties {
  double stick_stiffness_Pa_m = 0;    ///< k_t per unit area: G / h
  double unit_area_m2 = 0;            ///< tread width x unit length
  double unit_length_m = 0;           ///< ds = R0 dtheta
  double base_radius_m = 0;           ///< R_b = R0 - tread thickness
  double carcass_compliance_m_N = 0;  ///< C_x
};

/// The properties of a tyre model; C_x averaged over the units with a positive force in
/// `static_forces` (m entries: a static patch).
LongitudinalProperties longitudinal_properties(const contact::TyreModel& model,
                                               const Eigen::VectorXd& static_forces);

class LongitudinalContact {
 public:
  /// Units [lo, hi] of the model's candidates carry tread elements (the units that can touch).
  LongitudinalContact(const LongitudinalProperties& p, int lo, int hi);
  /// Advances over dt at spin Omega [rad/s] and forward speed V [m/s] with the vertical unit
  /// forces f (indexed by unit, entries lo..hi read) and friction coefficient mu (the road's
  /// ground::CoulombFriction with the tread's stick stiffness).
  void advance(double dt, const double* f, double spin_rad_s, double speed_m_s, double mu);
  /// The same with any tangential law: a soil's ground::JanosiHanamoto, whose stress is a
  /// function of the element's total shear displacement j.
  void advance(double dt, const double* f, double spin_rad_s, double speed_m_s,
               const ground::ShearLaw& law);
  /// Tangential force of the road on the tyre, forward + [N].
  double force_N() const { return force_N_; }
  /// Share of the loaded elements that slid in the last sub-step.
  double sliding_share() const { return sliding_share_; }
  double carcass_displacement_m() const { return ux_m_; }
  const LongitudinalProperties& properties() const { return p_; }

 private:
  /// The element over unit i (a ring buffer: shifting moves the head, not the elements).
  ground::ShearPoint& point(int i) {
    int k = head_ + (i - lo_);
    if (k >= n_) k -= n_;
    return points_[k];
  }
  /// Material moves `units` units backward (forward rolling: > 0); fresh elements enter.
  void shift(int units);
  /// The sub-step's trial (stiffness of the sticking elements) and commit passes over [a, b].
  void substep(double dj0, const double* f, const ground::ShearLaw& law,
               const ground::CoulombFriction* coulomb, int a, int b);

  LongitudinalProperties p_;
  int lo_ = 0, hi_ = -1, n_ = 0, head_ = 0;
  std::vector<ground::ShearPoint> points_;  ///< ring buffer over the units lo..hi
  int sheared_lo_ = 0, sheared_hi_ = -1;    ///< units whose element may be sheared (e != 0)
  double carry_ = 0;                        ///< material travel not yet shifted [units]
  double force_N_ = 0, ux_m_ = 0, sliding_share_ = 0;
};

}  // namespace modaltyre::fmu
