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

namespace modaltyre::transient {

/// The ODE of a model under a scenario (public for tests: energy, Jacobian checks).
class TransientSystem {
 public:
  TransientSystem(const TransientModel& model, const ScenarioPlan& plan);
  int size() const { return model_.state_size(); }
  void rhs(double t, const double* y, double* ydot) const;
  void jacobian(double t, const double* y, solvers::CscMatrix& J) const;
  void roots(double t, const double* y, double* g) const;
  /// Contact forces f_i at (t, y).
  Eigen::VectorXd forces(double t, const double* y) const;
  /// Road height and slope at unit i at time t.
  double road(double t, int i, double* slope = nullptr) const;
  /// State of static equilibrium under `load_N` (footprint solver, relaxed tread).
  std::vector<double> static_state(double load_N) const;
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
  int64_t nnz() const;

 private:
  /// g_i = z + h_i - s_i - u_i (- e_i): the tread tip's penetration (root functions).
  void tip_penetration(double t, const double* y, Eigen::VectorXd& g) const;
  /// The same where a unit can touch, -1 m elsewhere: units whose sag exceeds z + max h + a
  /// bound of |u_i| + e_i from the state (reach_bound()) have g_i < 0 for certain. The forces
  /// need only these; the m x nq product over the whole window was a third of a step.
  void tip_penetration_in_reach(double t, const double* y, Eigen::VectorXd& g) const;
  /// Units [lo, hi] that can touch at (t, y) (empty if hi < lo).
  void reach(double t, const double* y, int& lo, int& hi) const;
  /// Adds the road height h(x_i, t) to g over the units [lo, hi] (cleat only).
  void add_road(double t, int lo, int hi, Eigen::VectorXd& g) const;
  void forces_into(double t, const double* y, Eigen::VectorXd& f) const;

  const TransientModel& model_;
  const ScenarioPlan& plan_;
  // Work vectors of rhs() and roots(): the integrator calls them thousands of times, so they
  // are not allocated per call (one TransientSystem per run and thread).
  mutable Eigen::VectorXd scratch_f_, scratch_G_, scratch_Vf_, scratch_g_;
  /// Units in the Jacobian's sparsity pattern (ever in contact at a Jacobian evaluation).
  mutable std::vector<char> in_pattern_;
  /// Contact set at the last accepted step (update_contact_set()).
  mutable std::vector<char> in_contact_;
  mutable long switches_since_jacobian_ = 0;
  /// max_i |psi_ij| and max_i |V_il|: |u_i| <= sum_j shape_max_j |q_j| for every unit.
  Eigen::VectorXd shape_max_;
  int centre_ = 0;  ///< unit of least sag (the sag grows on both sides of it)
};

}  // namespace modaltyre::transient
