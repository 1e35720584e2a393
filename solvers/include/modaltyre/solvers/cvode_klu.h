#pragma once
// Generic adapter around SUNDIALS CVODE (BDF, Newton) with the KLU sparse direct solver.
//
// The problem is y' = f(t, y) with an analytic sparse Jacobian J = df/dy given in compressed
// sparse column form (64-bit indices, the SUNDIALS 6 sunindextype), and optional root functions
// g(t, y) whose sign changes stop the integration (events, e.g. contact switches).
//
// Ownership and threads: every integrator owns its own SUNContext, vectors, matrix, linear solver
// and CVODE memory; integrators may run concurrently on different threads, one each.
//
// Errors: nothing is printed. Every SUNDIALS return flag is checked; a failure inside advance()
// becomes a Status with the message CVODE gave and the time it reached. Setup failures (out of
// memory, inconsistent sizes) throw ComputationError. A callback may return a positive value to
// request a smaller step (recoverable) or a negative one to stop the run.
//
// Problems with a known block structure may bring their own Newton solver (OdeProblem::
// linear_setup/linear_solve); CVODE then sees a matrix-embedded linear solver.
//
// Sparsity pattern: KLU analyses the pattern once (ordering, symbolic factorisation) and then only
// refactors numerically. If the Jacobian callback produces a different pattern, the adapter asks
// KLU for a new analysis (SUNLinSol_KLUReInit, partial), so the pattern may change, but keeping it
// fixed (explicit zeros) is cheaper.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace modaltyre::solvers {

/// Compressed sparse column matrix (n x n); column j holds rows row[col_ptr[j] .. col_ptr[j+1]).
struct CscMatrix {
  int64_t n = 0;
  std::vector<int64_t> col_ptr;  ///< n + 1 entries
  std::vector<int64_t> row;
  std::vector<double> value;
  void clear(int64_t size) {
    n = size;
    col_ptr.assign(static_cast<std::size_t>(size) + 1, 0);
    row.clear();
    value.clear();
  }
};

struct OdeProblem {
  int64_t size = 0;
  /// ydot = f(t, y); returns 0 on success, > 0 recoverable failure, < 0 fatal.
  std::function<int(double t, const double* y, double* ydot)> rhs;
  /// Fills J = df/dy at (t, y) (fy = f(t, y) given). Same return convention.
  std::function<int(double t, const double* y, const double* fy, CscMatrix& jac)> jacobian;
  /// Optional structured solver of Newton's linear systems, in place of KLU: linear_setup
  /// prepares M = I - gamma J at (t, y) (evaluating its own Jacobian unless `jacobian_ok`: CVODE
  /// judges the last one still good), linear_solve overwrites b with M^-1 b. Both or neither;
  /// same return convention. With them CVODE runs a matrix-embedded linear solver and
  /// `jacobian` is not called.
  std::function<int(double t, const double* y, double gamma, bool jacobian_ok)> linear_setup;
  std::function<int(double* x)> linear_solve;
  int roots = 0;
  /// g(t, y) for `roots` root functions; may be empty when roots == 0.
  std::function<int(double t, const double* y, double* g)> root_functions;
};

struct OdeOptions {
  double relative_tolerance = 1e-6;
  std::vector<double> absolute_tolerance;  ///< per component (size n), or one value for all
  long max_steps_per_call = 100000;
  int max_order = 5;        ///< BDF order limit (2 keeps BDF A-stable for light damping)
  double max_step = 0;      ///< 0 = unlimited
  double initial_step = 0;  ///< 0 = CVODE's estimate
  bool stability_limit_detection = false;
  /// Linear-solver setups (KLU refactorisations) at most every this many steps (CVODE: 20) and
  /// when gamma = h * beta changed by more than delta_gamma_max (CVODE: 0.3). Larger values
  /// trade Newton iterations for fewer factorisations, which dominate when the Jacobian has
  /// dense blocks. 0 = CVODE's default.
  long lsetup_frequency = 0;
  double delta_gamma_max = 0;
  /// Newton iterations per step before CVODE declares a convergence failure (CVODE: 3); a
  /// failure with a stale Jacobian costs a new Jacobian and factorisation. 0 = CVODE's default.
  int max_nonlinear_iterations = 0;
  /// Newton's convergence test: the iteration stops when its estimated error, in the WRMS norm
  /// of the error test, is below this coefficient (CVODE: 0.1). 0 = CVODE's default.
  double nonlinear_convergence_coefficient = 0;
};

struct OdeStats {
  long steps = 0, rhs_evals = 0, jac_evals = 0, lin_setups = 0, nonlin_iters = 0, nonlin_fails = 0,
       error_test_fails = 0, root_returns = 0, reinits = 0, pattern_changes = 0;
  double last_step = 0;  ///< size of the last successful step (diagnostics)
  int last_order = 0;    ///< BDF order of the last successful step
};

enum class OdeOutcome { reached, root, failed };

struct OdeStatus {
  OdeOutcome outcome = OdeOutcome::reached;
  double t = 0;            ///< time reached
  std::vector<int> roots;  ///< per root function: 0, +1 (rising) or -1 (falling) at a root
  std::string message;     ///< CVODE's message on failure
  bool ok() const { return outcome != OdeOutcome::failed; }
};

class CvodeKlu {
 public:
  /// Sets the problem up at (t0, y0); `nnz_hint` sizes the sparse matrix (it grows if needed).
  CvodeKlu(OdeProblem problem, const OdeOptions& options, double t0, const std::vector<double>& y0,
           int64_t nnz_hint);
  ~CvodeKlu();
  CvodeKlu(const CvodeKlu&) = delete;
  CvodeKlu& operator=(const CvodeKlu&) = delete;

  /// Integrates towards t_out (never past it: it is also the stop time). Returns when t_out is
  /// reached, a root is found (status.t < t_out) or the integrator fails.
  OdeStatus advance(double t_out);
  /// Integrates towards t_out without stepping past t_stop >= t_out: the integrator may step
  /// beyond t_out (up to t_stop) and returns the state at t_out interpolated from its BDF
  /// history (CV_NORMAL), so dense output does not limit the step size. A later call continues
  /// from the integrator's internal time, not from t_out.
  OdeStatus advance(double t_out, double t_stop);
  /// One internal step (CV_ONE_STEP), not beyond t_stop > time(): returns at the end of the
  /// step, at a root inside it, or at t_stop. Outputs inside the step come from interpolate(),
  /// which (unlike advance() to each output time) does not evaluate the root functions.
  OdeStatus step(double t_stop);
  /// State at t within the last internal step (CVodeGetDky, the BDF interpolant).
  /// ComputationError for t outside it.
  void interpolate(double t, std::vector<double>& y) const;
  /// Bounds the step size from now on (0 = unlimited), e.g. while a forcing moves fast.
  void set_max_step(double h);
  /// Restarts the integrator at (t, y): BDF history and step size are discarded (order 1).
  /// Used after events where the right-hand side changes non-smoothly.
  void reinit(double t, const std::vector<double>& y);

  const std::vector<double>& state() const { return y_; }
  double time() const { return t_; }
  OdeStats stats() const;

  // C trampolines' access (public for the callbacks in the .cc; not part of the API).
  struct Impl;

 private:
  OdeStatus call_cvode(double t_out, double t_stop, int task);

  std::unique_ptr<Impl> impl_;
  std::vector<double> y_;  ///< the state; CVODE's output vector wraps its memory (never resized)
  double t_ = 0;
};

}  // namespace modaltyre::solvers
