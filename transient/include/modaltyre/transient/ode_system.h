#pragma once
// The ODE of a transient model under a scenario (state layout and equations: model.h).
//
// Contact switches: one CVODE root function per unit, g_i = p_i - e_i (on) or p_i (off): the
// tip of tread unit i touches the road when g_i rises through 0 and leaves when it falls
// through 0 (with the tread force f_i = k_g g_i this is also the force's sign). CVODE locates
// every root and returns there; the right-hand side is continuous across a switch (a kink of
// max(0, .)), so the driver counts the switch and continues the integration (BDF's error test
// shortens the steps over the kink) unless TransientRunOptions::restart_at_switches asks for a
// re-initialisation. No state jump is needed.
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "modaltyre/solvers/cvode_klu.h"
#include "modaltyre/transient/model.h"
#include "modaltyre/transient/scenario.h"
#include "modaltyre/transient/tread_window.h"

namespace modaltyre::transient {

class SoilContact;

/// Upwind stencil of the tread advection, de/dtheta ~ (c0 e_i + c1 e_{i+1} + c2 e_{i+2}) / dtheta:
/// second-order one-sided from the front. First order (-1, 1, 0) converged the rolling resistance
/// at O(dtheta): 59.3 / 60.6 / 61.2 / 61.5 N at 2 / 1 / 0.5 / 0.25 mm, against 61.3 / 61.6 /
/// 61.7 / 61.8 N with this one (60 km/h, docs/transient.md section 1).
inline constexpr double kUpwind[3] = {-1.5, 2.0, -0.5};

/// Derivatives of the acceleration v_j' of dynamic coordinate j with respect to q_j, v_j and its
/// pair partner's q_p, v_p (ground-frame rolling terms; 0 without a partner or at rest).
struct ModalRow {
  double dq = 0, dv = 0, dq_p = 0, dv_p = 0;
};
ModalRow modal_row(const TransientModel& M, int j, double Omega, double dOmega);

/// The ODE of a model under a scenario (public for tests: energy, Jacobian checks).
///
/// Only the units of `units` (tread_window.h: those that can touch in the scenario; all
/// candidates by default) carry forces and tread states: the state is
/// y = [q | v | r | z, w | e of units.lo .. units.hi], size() = model.e_index() + tread_states().
/// Units outside are checked against the road (escaped()) but never get a force.
class TransientSystem {
 public:
  TransientSystem(const TransientModel& model, const ScenarioPlan& plan, UnitRange units = {});
  int size() const { return model_.e_index() + ne_; }
  /// The units that carry forces and tread states.
  const UnitRange& units() const { return units_; }
  /// Tread states (relaxation on: units().size(), else 0); e_i is y[model.e_index() + i - lo].
  int tread_states() const { return ne_; }
  /// A unit outside units() had a positive penetration at an evaluated state: the trajectory is
  /// not the one of all units, and the run has to be repeated with all of them.
  bool escaped() const { return escaped_; }
  void rhs(double t, const double* y, double* ydot) const;
  void jacobian(double t, const double* y, solvers::CscMatrix& J) const;
  void roots(double t, const double* y, double* g) const;
  /// d f_i / d g_i for Newton's matrix: k_contact on the units in contact, and, while units are
  /// switching (contact_switched() since the last call), on those within 2 mm beyond the patch
  /// ends too; 0 elsewhere (m entries).
  void jacobian_stiffness(double t, const double* y, Eigen::VectorXd& kd) const;
  /// Rolling speed of the carcass Omega = V / R0 (or the prescribed hub's spin) and its rate.
  double spin(double t) const;
  double spin_rate(double t) const;
  /// The hub's displacement z at (t, y): the state's, or the prescribed hub's (scenario.h).
  double hub_z(double t, const double* y) const { return plan_.hub_z(t, y[model_.z_index()]); }
  const ScenarioPlan& plan() const { return plan_; }
  /// The contact forces of the last rhs() (the Newton iterate CVODE evaluated last) over units()
  /// (m entries; zero outside the reach; on a soil update_contact_set() also writes them).
  const Eigen::VectorXd& last_forces() const { return scratch_f_; }
  /// The contact forces at the state update_contact_set() accepted at t, from the penetration
  /// (on a soil the forces) it computed there, into f (m entries, as forces_into()); false when
  /// it accepted no state at t.
  bool accepted_forces(double t, Eigen::VectorXd& f) const;
  /// Contact forces f_i at (t, y).
  Eigen::VectorXd forces(double t, const double* y) const;
  /// forces() into `f` (m entries; only units() is written, so a reused `f` costs no
  /// allocation and no pass over all m units: the driver's output samples).
  void forces_into(double t, const double* y, Eigen::VectorXd& f) const;
  /// Road height and slope at unit i at time t.
  double road(double t, int i, double* slope = nullptr) const;
  /// State of static equilibrium under `load_N` (footprint solver, relaxed tread).
  std::vector<double> static_state(double load_N) const;
  /// The state of a static contact (static_state() from an already solved footprint).
  std::vector<double> state_from(const StaticContact& c) const;
  /// Kinetic + elastic energy (carcass, hub, contact springs; residual and Kelvin-Voigt parts
  /// excluded), for energy checks of undamped models without residual orders.
  double energy(double t, const double* y) const;
  std::vector<double> absolute_tolerances() const;
  /// Tells the system that a unit switched (a root was located): the next Jacobian treats the
  /// units next to the patch ends as in contact (see jacobian()).
  void contact_switched() const { ++switches_since_jacobian_; }
  /// Contact set at an accepted step's end (units with tip penetration > 0) against the one at
  /// the previous accepted step: returns how many units entered or left, and flags the next
  /// Jacobian as contact_switched() does when any did. This replaces the m root functions
  /// (the default, TransientRunOptions::locate_switches off): the kinks of max(0, g) are solved
  /// inside the implicit steps, and the root finder's passes over m functions per step are
  /// saved.
  int update_contact_set(double t, const double* y) const;
  /// g_i where a unit can touch, -1 m elsewhere: units whose sag exceeds z + max h + a bound of
  /// |u_i| + e_i from the state (reach()) have g_i < 0 for certain. The forces need only these;
  /// the m x nq product over the whole window was a third of a step.
  void tip_penetration_in_reach(double t, const double* y, Eigen::VectorXd& g) const;
  /// Adds the road height h(x_i, t) to g over the units [lo, hi] (cleat only).
  void add_road(double t, int lo, int hi, Eigen::VectorXd& g) const;
  /// g_i of one unit. xi_of_y: the last forces_into() / forces() call was at this y, whose
  /// contact coordinates are then reused (an output sample's edge interpolation).
  double tip_penetration_at(double t, const double* y, int i, bool xi_of_y = false) const;
  int64_t nnz() const;
  /// A deformable soil in series with every unit's contact spring (soil_contact.h; null: the
  /// rigid road): forces phi_i(g_i), Newton's stiffness d phi / d g, and the soil's memory
  /// recorded at every accepted step (update_contact_set()). Not owned.
  void set_soil(SoilContact* soil) { soil_ = soil; }
  const SoilContact* soil() const { return soil_; }

 private:
  /// g_i = z + h_i - s_i - u_i (- e_i): the tread tip's penetration (root functions).
  void tip_penetration(double t, const double* y, Eigen::VectorXd& g) const;
  /// xi = Cq q + Cr r into scratch_xi_ (u = T xi, model.h's contact basis).
  void contact_coordinates(const double* y) const;
  /// Units [lo, hi] that can touch at y (empty if hi < lo; within units()), xi from
  /// contact_coordinates(): bounds of g from the last accepted state (update_contact_set()) or,
  /// before one, from rest. Checks the units outside units() too (check_outside()).
  void reach(double t, const double* y, int& lo, int& hi) const;
  /// Penetration of the units outside units() at (t, y): refreshes their bound's reference
  /// (p_out_ref_ ...) and sets escaped_ if any is positive. xi from contact_coordinates().
  void check_outside(double t, const double* y) const;
  /// forces_into() that also returns the reach [lo, hi] (f = 0 outside; empty if hi < lo).
  void forces_band(double t, const double* y, Eigen::VectorXd& f, int& lo, int& hi) const;
  /// g over the reach [lo, hi] (entries outside untouched), as tip_penetration_in_reach();
  /// xi_ready: contact_coordinates(y) is already in scratch_xi_; forces: k max(0, g) instead
  /// of g (forces_band()).
  void penetration_band(double t, const double* y, Eigen::VectorXd& g, int& lo, int& hi,
                        bool xi_ready = false, bool forces = false) const;

  const TransientModel& model_;
  const ScenarioPlan& plan_;
  // Work vectors of rhs() and roots(): the integrator calls them thousands of times, so they
  // are not allocated per call (one TransientSystem per run and thread).
  mutable Eigen::VectorXd scratch_f_, scratch_G_, scratch_Vf_, scratch_g_, scratch_xi_,
      scratch_phi_;
  Eigen::MatrixXd CqT_, CrT_;  ///< Cq^T (nq x rank), Cr^T (nr x rank)
  /// rhs()'s modal rows at the spin (rows_Omega_, rows_dOmega_).
  mutable std::vector<ModalRow> modal_rows_;
  mutable double rows_Omega_ = 0, rows_dOmega_ = 0;
  /// Units in the Jacobian's sparsity pattern (ever in contact at a Jacobian evaluation).
  mutable std::vector<char> in_pattern_;
  /// Contact set at the last accepted step (update_contact_set()).
  mutable Eigen::ArrayXd in_contact_;  ///< 1 in contact, 0 not (empty before the first call)
  /// First and last unit of in_contact_ (empty: first > last).
  mutable int contact_first_ = 0, contact_last_ = -1;
  /// The last accepted state's time and the range of its penetration (or, on a soil, forces)
  /// in scratch_g_ (scratch_f_): accepted_forces().
  mutable double accepted_t_ = -1;
  mutable int accepted_lo_ = 0, accepted_hi_ = -1;
  mutable long switches_since_jacobian_ = 0;
  /// Reach reference (update_contact_set()): p_ref = z - s - T xi over the window at an accepted
  /// state (refreshed when the state has moved by kReachRefresh_m), and its xi and z (empty
  /// before the first accepted step).
  mutable Eigen::VectorXd p_ref_, xi_ref_;
  mutable double z_ref_ = 0;
  Eigen::VectorXd inv_c_kv_, k_over_c_kv_;  ///< 1 / c' and k' / c' per unit (relaxation on)
  /// max_i |T_i|: |u_i| <= basis_row_norm_max_ |xi| for every unit.
  double basis_row_norm_max_ = 0;
  int centre_ = 0;  ///< unit of least sag (the sag grows on both sides of it)
  UnitRange units_;
  int ne_ = 0;  ///< tread states
  /// Units outside units_: max of p = z - s_i - T_i xi over them at a reference state (xi, z),
  /// the largest |T_i| among them, and whether there are any.
  mutable double p_out_ref_ = 0, z_out_ref_ = 0;
  mutable Eigen::VectorXd xi_out_ref_;
  double out_row_norm_max_ = 0;
  bool has_outside_ = false;
  mutable bool escaped_ = false;
  SoilContact* soil_ = nullptr;
};

}  // namespace modaltyre::transient
