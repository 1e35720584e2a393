#pragma once
// Transient (time-domain) tyre on a rigid road: modal carcass, Kelvin-Voigt tread, hub DOF,
// unilateral contact; integrated with CVODE (BDF) + KLU. Derivations in docs/transient.md.
//
// State y = [q (nq) | v = q' (nq) | r (nr) | z, w = z' | e (m, tread relaxation on only)].
//
// Carcass, dynamic part (orders <= transient.dynamic_max_order). Every modal term (order k,
// weight w, 2x2 Hermitian shape matrix P = [P_rr P_rt; P_rt* P_tt]) is split into rank-one
// pieces P = sum a a^H (Cholesky of the 2x2); a piece of order k >= 1 gives two real
// coordinates with shapes sqrt(w) Re(a e^{ik theta}) and sqrt(w) Im(a e^{ik theta}) (order 0:
// the real one only), so that sum phi(theta_i) phi(theta_j) / omega^2 is exactly the term's
// contribution to the static kernel (modal_basis.h). Unit modal mass:
//   q'' + 2 zeta omega q' + omega^2 q = psi^T f      (seed 001 eq. 2, one mode)
// psi = phi_r cos theta + phi_t sin theta is the vertical shape at the candidate units and f
// the vertical contact forces (upward on the tyre, seed 001 eq. 12). Rolling at Omega(t) = V/R0
// is written in the ground (hub) frame: a pair (c, s) of order k obeys, with b = k Omega and
// a = k Omega',
//   q_c'' = G_c - 2 zeta omega q_c' + 2 b q_s' - (omega^2 - b^2) q_c + (2 zeta omega b + a) q_s
//   q_s'' = G_s - 2 zeta omega q_s' - 2 b q_c' - (omega^2 - b^2) q_s - (2 zeta omega b + a) q_c
// whose steady state is the rolling receptance 1/(omega^2 - b^2 - 2i zeta omega b) of
// carcass_kernel.h (gyroscopic terms neglected there and here).
//
// Carcass, residual part (orders above the dynamic truncation): quasi-static. Their vertical
// static compliance on the candidates, R = V diag(lambda) V^T (eigen-decomposition), is carried
// by first-order coordinates tau r' + r = diag(lambda) V^T f, tau = 2 zeta / omega_(K+1)
// (the residual modes without their inertia, keeping their damping). Only the eigenpairs with
// lambda >= 0.3 lambda_max are integrated; the others' diagonal (residual_lumped) acts in series
// with the tread spring and their off-diagonal coupling is dropped, so the model's at-rest
// compliance has the static kernel's diagonal exactly and moves the static footprint by
// truncation_error() (0.01 % at the default mesh; docs/transient.md section 1).
//
// Tread, per unit, vertical: relaxed stiffness k_i = 1 / (cos^2/k_r + sin^2/k_t) (the static
// footprint's tread, tyre_model.h). Relaxation off (seed 001 eq. 6): f_i = k_i max(0, p_i).
// Relaxation on (eq. 9-10): a Kelvin-Voigt element (k', c' = k' tan(delta)/Omega_ref) in series
// with an instantaneous spring k_g = ratio k_i (k' = k_i ratio/(ratio-1), so 1/k_g + 1/k' =
// 1/k_i: the static limit is again k_i); e_i is the Kelvin-Voigt deformation:
//   f_i = k_g max(0, p_i - e_i),   c' De_i/Dt + k' e_i = f_i,
//   De/Dt = de/dt - Omega de/dtheta (material flows backward through the ground-fixed units;
//   second-order upwind difference, undeformed rubber enters at the front of the window).
// Penetration of the undeformed tread surface: p_i = z + h(x_i, t) - s_i - u_i, z the hub's
// downward displacement, s_i the sag R0 (1 - cos theta_i), h the road profile (cleat), u_i =
// psi_i q + V_i r the carcass's upward displacement.
//
// Hub: m z'' = F(t) - sum f_i (load control; the scenario gives F and Omega).
//
// Contact switches: one CVODE root function per unit, g_i = p_i - e_i (on) or p_i (off): the
// tip of tread unit i touches the road when g_i rises through 0 and leaves when it falls
// through 0 (with the tread force f_i = k_g g_i this is also the force's sign). CVODE locates
// every root and returns there; the right-hand side is continuous across a switch (a kink of
// max(0, .)), so the driver counts the switch and continues the integration (BDF's error test
// shortens the steps over the kink) unless TransientRunOptions::restart_at_switches asks for a
// re-initialisation. No state jump is needed.
#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/solvers/cvode_klu.h"

namespace modaltyre::contact {

enum class Scenario { load_hold, free_vibration, rolling, cleat };
/// "load-hold", "free-vibration", "rolling", "cleat"; anything else is an InputError.
Scenario parse_scenario(const std::string& name);
const char* to_string(Scenario s);

struct TransientModel {
  TyreModel tyre;
  TransientSettings settings;
  int m = 0;   ///< candidate units
  int nq = 0;  ///< dynamic modal coordinates
  int nr = 0;  ///< residual (quasi-static) coordinates
  // Dynamic coordinates.
  std::vector<double> omega, zeta;
  std::vector<int> order;
  std::vector<int> partner;       ///< the other member of a (cos, sin) pair, -1 if none
  std::vector<double> pair_sign;  ///< +1 for the cos member, -1 for the sin member, 0 if none
  Eigen::MatrixXd psi;            ///< m x nq vertical shapes
  Eigen::MatrixXd phi_r, phi_t;   ///< m x nq radial and tangential shapes
  // Residual.
  Eigen::MatrixXd V;                       ///< m x nr
  Eigen::MatrixXd psi_by_unit, V_by_unit;  ///< psi^T (nq x m) and V^T (nr x m): a unit per column
  Eigen::VectorXd lambda;                  ///< nr, [m/N]
  /// Diagonal of the residual eigenpairs not integrated (lambda below the truncation), lumped
  /// in series with the tread spring [m/N]; m entries.
  Eigen::VectorXd residual_lumped;
  double tau_residual_s = 0;
  modal::LagKernels residual_kernels;  ///< radial/tangential kernels of the residual orders
  int residual_min_order = 0;
  double residual_min_omega = 0;
  // Tread.
  Eigen::VectorXd k_relaxed;         ///< k_i [N/m]
  Eigen::VectorXd k_contact;         ///< spring between penetration and force: k_i (off) or k_g
  Eigen::VectorXd k_kv, c_kv;        ///< Kelvin-Voigt element (relaxation on)
  double tread_time_constant_s = 0;  ///< c'/k' = tan(delta) / Omega_ref
  Eigen::VectorXd x_road;            ///< R0 sin theta_i

  int state_size() const { return 2 * nq + nr + 2 + (settings.relaxation ? m : 0); }
  int z_index() const { return 2 * nq + nr; }
  int e_index() const { return 2 * nq + nr + 2; }
  /// Vertical compliance of the model at rest (carcass dynamic + residual + tread) [m/N].
  Eigen::MatrixXd at_rest_compliance() const;
};

/// How far the truncated residual moves the model from the static kernel at rest: the static
/// footprint under `load_N` solved with at_rest_compliance() against the one solved with
/// TyreModel::vertical_compliance (relative differences of sinking and length), and the largest
/// entry of the compliance difference relative to the largest compliance.
struct TruncationError {
  double sinking_rel = 0, length_rel = 0, compliance_rel = 0;
};
TruncationError truncation_error(const TransientModel& model, double load_N);

/// Builds the transient model (settings from tyre.config.transient).
TransientModel build_transient_model(const TyreModel& tyre);

/// Time functions and initial condition of a scenario.
struct ScenarioPlan {
  Scenario scenario = Scenario::load_hold;
  double duration_s = 0;
  double initial_load_N = 0;           ///< 0: start undeformed, touching the road
  std::vector<double> breakpoints;     ///< times where F or Omega change slope (restarts)
  std::function<double(double)> load;  ///< F(t) [N]
  double speed_m_s = 0;                ///< final rolling speed
  double ramp_s = 0;                   ///< speed ramp from 0 (0: at speed from t = 0)
  bool cleat = false;
  double cleat_height_m = 0, cleat_length_m = 0, cleat_start_m = 0;  ///< centre at t = 0
  /// Step-size bound while a cleat crosses the window, in force over [from, until) [s].
  double step_limit_s = 0, step_limit_from_s = 0, step_limit_until_s = 0;
  double step_limit(double t) const;    ///< the bound in force at t (0 = none)
  double speed(double t) const;         ///< V(t), smoothstep ramp from rest
  double acceleration(double t) const;  ///< V'(t)
  double distance(double t) const;      ///< integral of V
};

/// The plan of a scenario from the settings; InputError for an ill-posed one.
ScenarioPlan plan_scenario(const TransientModel& model, Scenario s);

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
  int64_t nnz() const;

 private:
  /// g_i = z + h_i - s_i - u_i (- e_i): the tread tip's penetration (root functions).
  void tip_penetration(double t, const double* y, Eigen::VectorXd& g) const;
  void forces_into(double t, const double* y, Eigen::VectorXd& f) const;

  const TransientModel& model_;
  const ScenarioPlan& plan_;
  // Work vectors of rhs() and roots(): the integrator calls them thousands of times, so they
  // are not allocated per call (one TransientSystem per run and thread).
  mutable Eigen::VectorXd scratch_f_, scratch_G_, scratch_Vf_, scratch_g_;
  /// Units in the Jacobian's sparsity pattern (ever in contact at a Jacobian evaluation).
  mutable std::vector<char> in_pattern_;
  mutable long switches_since_jacobian_ = 0;
};

struct TransientSample {
  double t_s = 0;
  double load_N = 0;              ///< sum of contact forces (road reaction)
  double applied_load_N = 0;      ///< F(t) at the hub
  double hub_displacement_m = 0;  ///< z, downward
  double sinking_m = 0;           ///< max_i (z + h_i - s_i): deflection of the tyre at the road
  double contact_length_m = 0;
  double longitudinal_force_N = 0;  ///< -(sum f x)/(R0 - z) - sum f h'(x)
  double pressure_centre_m = 0;     ///< sum f x / sum f (+ forward)
  double speed_m_s = 0;
  int contact_units = 0;
};

enum class TransientStatus { completed, failed };

struct TransientResult {
  Scenario scenario = Scenario::load_hold;
  TransientStatus status = TransientStatus::failed;
  std::string message;
  double simulated_s = 0;  ///< time reached
  double wall_s = 0;
  solvers::OdeStats stats;
  int contact_events = 0;  ///< root returns (units entering or leaving)
  std::vector<TransientSample> samples;
  /// Mean of -longitudinal force over the last 10 % of the run (rolling resistance) [N].
  double rolling_resistance_N = 0;
  bool ok() const { return status == TransientStatus::completed; }
  double real_time_factor() const { return wall_s > 0 ? simulated_s / wall_s : 0; }
};

struct TransientRunOptions {
  /// Called after every output sample with (t, duration); return false to stop (cancel).
  std::function<bool(double, double)> progress;
  std::vector<double> final_state;  ///< filled with the last state if non-null-sized request
  bool keep_final_state = false;
  /// Re-initialise CVODE at every contact switch (BDF history discarded) instead of continuing
  /// over the kink; slower, kept for comparisons.
  bool restart_at_switches = false;
};

/// Runs a scenario. Failures of the integrator are reported in the result (message and time
/// reached), never thrown; ill-posed settings are InputErrors.
TransientResult run_transient(const TransientModel& model, Scenario scenario,
                              TransientRunOptions* options = nullptr);

}  // namespace modaltyre::contact
