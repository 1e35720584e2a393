#include "modaltyre/solvers/cvode_klu.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/instruction_set.h"
#include "serial_vector_ops.h"

static_assert(sizeof(sunindextype) == sizeof(int64_t), "SUNDIALS must use 64-bit indices");
static_assert(sizeof(realtype) == sizeof(double), "SUNDIALS must use double precision");

namespace modaltyre::solvers {

struct CvodeKlu::Impl {
  OdeProblem problem;
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector abstol = nullptr;
  N_Vector dky = nullptr;  // interpolate()'s output
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  void* mem = nullptr;
  CscMatrix jac;
  std::vector<int64_t> last_col_ptr, last_row;  // pattern KLU was analysed for
  std::string last_error;
  double stop_time = std::nan("");  // stop time CVODE currently holds (NaN: none)
  long root_returns = 0, reinits = 0, pattern_changes = 0, custom_setups = 0, custom_jacobians = 0;
  double setup_gamma = 0;      // gamma of the structured solver's last setup
  std::string callback_error;  // exception text from a callback
  OdeStats before_reinit;      // CVODE's counters restart at every CVodeReInit

  ~Impl() {
    if (mem) CVodeFree(&mem);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (abstol) N_VDestroy(abstol);
    if (dky) N_VDestroy(dky);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

namespace {

void check(int flag, const char* what, const CvodeKlu::Impl& impl) {
  if (flag < 0) {
    throw ComputationError(std::string("SUNDIALS ") + what + " failed (flag " +
                           std::to_string(flag) + ")" +
                           (impl.last_error.empty() ? "" : ": " + impl.last_error));
  }
}

extern "C" int rhs_trampoline(realtype t, N_Vector y, N_Vector ydot, void* user) {
  auto* impl = static_cast<CvodeKlu::Impl*>(user);
  try {
    return impl->problem.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  } catch (const std::exception& e) {
    impl->callback_error = e.what();
    return -1;
  }
}

extern "C" int root_trampoline(realtype t, N_Vector y, realtype* g, void* user) {
  auto* impl = static_cast<CvodeKlu::Impl*>(user);
  try {
    return impl->problem.root_functions(t, N_VGetArrayPointer(y), g);
  } catch (const std::exception& e) {
    impl->callback_error = e.what();
    return -1;
  }
}

/// Copies the user's CSC matrix into the SUNDIALS matrix, inserting explicit zero diagonal
/// entries where missing (CVODE forms I - gamma J in place; a missing diagonal would make it
/// reallocate the matrix at every setup).
int copy_with_diagonal(const CscMatrix& src, SUNMatrix A, CvodeKlu::Impl& impl) {
  const int64_t n = src.n;
  int64_t need = static_cast<int64_t>(src.row.size()) + n;
  if (SUNSparseMatrix_NNZ(A) < need) {
    if (SUNSparseMatrix_Reallocate(A, need) != SUNMAT_SUCCESS) return -1;
  }
  sunindextype* cp = SUNSparseMatrix_IndexPointers(A);
  sunindextype* ri = SUNSparseMatrix_IndexValues(A);
  realtype* v = SUNSparseMatrix_Data(A);
  int64_t k = 0;
  for (int64_t j = 0; j < n; ++j) {
    cp[j] = k;
    bool diag = false;
    for (int64_t p = src.col_ptr[j]; p < src.col_ptr[j + 1]; ++p) {
      const int64_t r = src.row[p];
      if (!diag && r > j) {
        ri[k] = j, v[k] = 0.0, ++k;
        diag = true;
      }
      if (r == j) diag = true;
      ri[k] = r, v[k] = src.value[p], ++k;
    }
    if (!diag) ri[k] = j, v[k] = 0.0, ++k;
  }
  cp[n] = k;
  // Pattern check against what KLU analysed.
  const bool same = static_cast<int64_t>(impl.last_col_ptr.size()) == n + 1 &&
                    std::equal(cp, cp + n + 1, impl.last_col_ptr.begin()) &&
                    static_cast<int64_t>(impl.last_row.size()) == k &&
                    std::equal(ri, ri + k, impl.last_row.begin());
  if (!same) {
    const bool first = impl.last_col_ptr.empty();
    impl.last_col_ptr.assign(cp, cp + n + 1);
    impl.last_row.assign(ri, ri + k);
    if (!first) {
      ++impl.pattern_changes;
      if (SUNLinSol_KLUReInit(impl.LS, A, SUNSparseMatrix_NNZ(A), SUNKLU_REINIT_PARTIAL) !=
          SUNLS_SUCCESS)
        return -1;
    }
  }
  return 0;
}

extern "C" int jac_trampoline(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user,
                              N_Vector, N_Vector, N_Vector) {
  auto* impl = static_cast<CvodeKlu::Impl*>(user);
  try {
    impl->jac.clear(impl->problem.size);
    const int flag =
        impl->problem.jacobian(t, N_VGetArrayPointer(y), N_VGetArrayPointer(fy), impl->jac);
    if (flag != 0) return flag;
    const CscMatrix& m = impl->jac;
    if (m.n != impl->problem.size || static_cast<int64_t>(m.col_ptr.size()) != m.n + 1 ||
        m.row.size() != m.value.size() ||
        static_cast<std::size_t>(m.col_ptr.back()) != m.row.size()) {
      impl->callback_error = "Jacobian callback returned an inconsistent CSC matrix";
      return -1;
    }
    return copy_with_diagonal(m, J, *impl);
  } catch (const std::exception& e) {
    impl->callback_error = e.what();
    return -1;
  }
}

// Structured linear solver (OdeProblem::linear_setup / linear_solve) as a SUNLinearSolver
// without a matrix. CVODE sets up such a solver only through its preconditioner hooks
// (CVodeSetPreconditioner; a matrix-embedded solver is never set up), which also pass t, y,
// gamma and whether the last Jacobian may be reused: the solver applies that "preconditioner",
// the exact inverse of Newton's matrix, once. Declared iterative for that reason, it does not
// iterate (no products with J are ever asked for).
struct CustomSolverContent {
  void* p_data = nullptr;
  SUNPSetupFn pset = nullptr;
  SUNPSolveFn psol = nullptr;
  /// cvLsSolve's solution vector, lent b's array at every solve (custom_solve()), and the array
  /// it was made with (freed by custom_free()).
  N_Vector x = nullptr;
  realtype* x_array = nullptr;
};

extern "C" SUNLinearSolver_Type custom_gettype(SUNLinearSolver) {
  return SUNLINEARSOLVER_ITERATIVE;
}

extern "C" int custom_setatimes(SUNLinearSolver, void*, SUNATimesFn) { return 0; }

extern "C" int custom_setpreconditioner(SUNLinearSolver S, void* p_data, SUNPSetupFn pset,
                                        SUNPSolveFn psol) {
  auto* c = static_cast<CustomSolverContent*>(S->content);
  c->p_data = p_data, c->pset = pset, c->psol = psol;
  return 0;
}

// Accepts CVODE's error weights and ignores them (the solve is exact). Declared so that
// cvLsSolve hands the weights over instead of estimating their mean for an iterative solver's
// tolerance (a pass setting a work vector to one and a weighted norm of it, at every Newton
// iteration; the tolerance is never read here).
extern "C" int custom_setscalingvectors(SUNLinearSolver, N_Vector, N_Vector) { return 0; }

extern "C" int custom_setup(SUNLinearSolver S, SUNMatrix) {
  auto* c = static_cast<CustomSolverContent*>(S->content);
  return c->pset ? c->pset(c->p_data) : -1;
}

// x's initial guess (cvLsSolve zeroes x before each solve; the exact solve never reads it).
extern "C" void skip_constant(realtype, N_Vector) {}

// Around each solve cvLsSolve zeroes x and copies x into b after it, and the solve itself began
// with a copy of b into x: three passes over the state per Newton iteration (free vibration:
// 1442 iterations of 2023 states). The solve runs in b's own array instead, and x is lent that
// array, so that the copy x -> b is of an array onto itself, which the vector kernels skip
// (serial_vector_ops.cc); x's zeroing is skipped (skip_constant), its own array kept for
// custom_free(). The same operations on b's values: the same bits.
extern "C" int custom_solve(SUNLinearSolver S, SUNMatrix, N_Vector x, N_Vector b, realtype tol) {
  auto* c = static_cast<CustomSolverContent*>(S->content);
  if (!c->psol) return -1;
  if (c->x != x) {
    if (c->x) return c->psol(c->p_data, b, x, tol, 1);  // another x: solved into it (not seen)
    c->x = x;
    c->x_array = N_VGetArrayPointer(x);
    NV_OWN_DATA_S(x) = SUNFALSE;  // its destructor leaves the lent array alone
    x->ops->nvconst = skip_constant;
  }
  N_VSetArrayPointer(N_VGetArrayPointer(b), x);
  return c->psol(c->p_data, b, b, tol, 1);
}

extern "C" int custom_free(SUNLinearSolver S) {
  auto* c = static_cast<CustomSolverContent*>(S->content);
  if (c) std::free(c->x_array);  // NOLINT: SUNDIALS' serial vectors allocate with malloc
  delete c;
  S->content = nullptr;
  SUNLinSolFreeEmpty(S);
  return 0;
}

extern "C" int precond_setup(realtype t, N_Vector y, N_Vector, booleantype jok, booleantype* jcur,
                             realtype gamma, void* user) {
  auto* impl = static_cast<CvodeKlu::Impl*>(user);
  try {
    ++impl->custom_setups;
    if (!jok) ++impl->custom_jacobians;
    impl->setup_gamma = gamma;
    *jcur = jok ? SUNFALSE : SUNTRUE;
    return impl->problem.linear_setup(t, N_VGetArrayPointer(y), gamma, jok != SUNFALSE);
  } catch (const std::exception& e) {
    impl->callback_error = e.what();
    return -1;
  }
}

extern "C" int precond_solve(realtype, N_Vector, N_Vector, N_Vector r, N_Vector z, realtype gamma,
                             realtype, int, void* user) {
  auto* impl = static_cast<CvodeKlu::Impl*>(user);
  try {
    if (N_VGetArrayPointer(r) != N_VGetArrayPointer(z)) N_VScale(1.0, r, z);
    const int flag = impl->problem.linear_solve(N_VGetArrayPointer(z));
    // As CVODE does for its direct solvers with BDF: a matrix set up at gamma_setup, used at
    // gamma, gives a correction too large by ~gamma / gamma_setup in the stiff components;
    // scale it by 2 / (1 + gamma / gamma_setup). An iterative solver type gets no such
    // correction from CVODE, and without it a very stiff tread (glassy ratio 10^4) made Newton
    // accept growing oscillations.
    if (flag == 0 && impl->setup_gamma > 0 && gamma != impl->setup_gamma)
      N_VScale(2.0 / (1.0 + gamma / impl->setup_gamma), z, z);
    return flag;
  } catch (const std::exception& e) {
    impl->callback_error = e.what();
    return -1;
  }
}

extern "C" void error_trampoline(int code, const char* module, const char* function, char* msg,
                                 void* user) {
  auto* impl = static_cast<CvodeKlu::Impl*>(user);
  if (code >= 0) return;  // warnings are not failures; the library never prints
  impl->last_error = std::string(module ? module : "") + "::" + (function ? function : "") + ": " +
                     (msg ? msg : "");
}

}  // namespace

CvodeKlu::CvodeKlu(OdeProblem problem, const OdeOptions& opt, double t0,
                   const std::vector<double>& y0, int64_t nnz_hint)
    : impl_(std::make_unique<Impl>()), y_(y0), t_(t0) {
  check_instruction_set_variable();  // the vector kernels' MODALTYRE_ISA (instruction_set.h)
  Impl& I = *impl_;
  I.problem = std::move(problem);
  const int64_t n = I.problem.size;
  MODALTYRE_CHECK(n > 0 && static_cast<int64_t>(y0.size()) == n, "ODE size and y0 disagree");
  // The sparse Jacobian is needed by KLU only; a structured solver forms its own matrices.
  MODALTYRE_CHECK(I.problem.rhs && (I.problem.jacobian || I.problem.linear_setup),
                  "ODE problem needs rhs and a Jacobian or a structured linear solver");
  MODALTYRE_CHECK(I.problem.roots == 0 || I.problem.root_functions, "root functions missing");
  if (SUNContext_Create(nullptr, &I.ctx) != 0) throw ComputationError("SUNContext_Create failed");
  // CVODE's output vector is state()'s memory (y_, never resized): a returned step needs no
  // copy. (CVODE also iterates in it during a call; state() is read between calls only.)
  I.y = N_VMake_Serial(n, y_.data(), I.ctx);
  if (!I.y) throw ComputationError("N_VMake_Serial failed (out of memory?)");
  // CVODE clones all its work vectors from y0: they inherit the faster kernels.
  install_serial_vector_ops(I.y);
  I.dky = N_VClone(I.y);  // interpolate()'s output, with the same kernels
  if (!I.dky) throw ComputationError("N_VClone failed (out of memory?)");
  I.mem = CVodeCreate(CV_BDF, I.ctx);
  if (!I.mem) throw ComputationError("CVodeCreate failed");
  check(CVodeSetErrHandlerFn(I.mem, error_trampoline, &I), "CVodeSetErrHandlerFn", I);
  check(CVodeInit(I.mem, rhs_trampoline, t0, I.y), "CVodeInit", I);
  check(CVodeSetUserData(I.mem, &I), "CVodeSetUserData", I);
  if (opt.absolute_tolerance.size() == static_cast<std::size_t>(n)) {
    I.abstol = N_VNew_Serial(n, I.ctx);
    if (!I.abstol) throw ComputationError("N_VNew_Serial failed");
    std::copy(opt.absolute_tolerance.begin(), opt.absolute_tolerance.end(),
              N_VGetArrayPointer(I.abstol));
    check(CVodeSVtolerances(I.mem, opt.relative_tolerance, I.abstol), "CVodeSVtolerances", I);
  } else {
    MODALTYRE_CHECK(opt.absolute_tolerance.size() <= 1, "absolute tolerance size");
    const double a = opt.absolute_tolerance.empty() ? 1e-10 : opt.absolute_tolerance[0];
    check(CVodeSStolerances(I.mem, opt.relative_tolerance, a), "CVodeSStolerances", I);
  }
  const bool custom = static_cast<bool>(I.problem.linear_setup);
  MODALTYRE_CHECK(custom == static_cast<bool>(I.problem.linear_solve),
                  "linear_setup and linear_solve go together");
  if (custom) {
    I.LS = SUNLinSolNewEmpty(I.ctx);
    if (!I.LS) throw ComputationError("SUNLinSolNewEmpty failed");
    I.LS->content = new CustomSolverContent;
    I.LS->ops->gettype = custom_gettype;
    I.LS->ops->setpreconditioner = custom_setpreconditioner;
    I.LS->ops->setatimes = custom_setatimes;
    I.LS->ops->setscalingvectors = custom_setscalingvectors;
    I.LS->ops->setup = custom_setup;
    I.LS->ops->solve = custom_solve;
    I.LS->ops->free = custom_free;
    check(CVodeSetLinearSolver(I.mem, I.LS, nullptr), "CVodeSetLinearSolver", I);
    check(CVodeSetPreconditioner(I.mem, precond_setup, precond_solve), "CVodeSetPreconditioner", I);
  } else {
    I.A = SUNSparseMatrix(n, n, std::max<int64_t>(nnz_hint, n), CSC_MAT, I.ctx);
    if (!I.A) throw ComputationError("SUNSparseMatrix failed (out of memory?)");
    I.LS = SUNLinSol_KLU(I.y, I.A, I.ctx);
    if (!I.LS) throw ComputationError("SUNLinSol_KLU failed");
    check(CVodeSetLinearSolver(I.mem, I.LS, I.A), "CVodeSetLinearSolver", I);
    check(CVodeSetJacFn(I.mem, jac_trampoline), "CVodeSetJacFn", I);
  }
  check(CVodeSetMaxNumSteps(I.mem, opt.max_steps_per_call), "CVodeSetMaxNumSteps", I);
  check(CVodeSetMaxOrd(I.mem, opt.max_order), "CVodeSetMaxOrd", I);
  if (opt.max_step > 0) check(CVodeSetMaxStep(I.mem, opt.max_step), "CVodeSetMaxStep", I);
  if (opt.initial_step > 0) check(CVodeSetInitStep(I.mem, opt.initial_step), "CVodeSetInitStep", I);
  if (opt.stability_limit_detection)
    check(CVodeSetStabLimDet(I.mem, SUNTRUE), "CVodeSetStabLimDet", I);
  if (opt.lsetup_frequency > 0)
    check(CVodeSetLSetupFrequency(I.mem, opt.lsetup_frequency), "CVodeSetLSetupFrequency", I);
  if (opt.delta_gamma_max > 0)
    check(CVodeSetDeltaGammaMaxLSetup(I.mem, opt.delta_gamma_max), "CVodeSetDeltaGammaMaxLSetup",
          I);
  if (opt.max_nonlinear_iterations > 0)
    check(CVodeSetMaxNonlinIters(I.mem, opt.max_nonlinear_iterations), "CVodeSetMaxNonlinIters", I);
  if (opt.nonlinear_convergence_coefficient > 0)
    check(CVodeSetNonlinConvCoef(I.mem, opt.nonlinear_convergence_coefficient),
          "CVodeSetNonlinConvCoef", I);
  if (I.problem.roots > 0) {
    check(CVodeRootInit(I.mem, I.problem.roots, root_trampoline), "CVodeRootInit", I);
    check(CVodeSetNoInactiveRootWarn(I.mem), "CVodeSetNoInactiveRootWarn", I);
  }
}

CvodeKlu::~CvodeKlu() = default;

OdeStatus CvodeKlu::advance(double t_out) { return advance(t_out, t_out); }

OdeStatus CvodeKlu::advance(double t_out, double t_stop) {
  if (t_out <= t_) {
    OdeStatus st;
    st.t = t_;
    return st;
  }
  MODALTYRE_CHECK(t_stop >= t_out, "stop time before the output time");
  return call_cvode(t_out, t_stop, CV_NORMAL);
}

OdeStatus CvodeKlu::step(double t_stop) {
  MODALTYRE_CHECK(t_stop > t_, "step: stop time not ahead of the integrator");
  return call_cvode(t_stop, t_stop, CV_ONE_STEP);
}

void CvodeKlu::interpolate(double t, std::vector<double>& y) const {
  Impl& I = *impl_;
  // Into y's own memory (the work vector lent it for the call): no copy of the state after.
  y.resize(static_cast<std::size_t>(I.problem.size));
  double* own = N_VGetArrayPointer(I.dky);
  N_VSetArrayPointer(y.data(), I.dky);
  const int flag = CVodeGetDky(I.mem, t, 0, I.dky);
  N_VSetArrayPointer(own, I.dky);
  if (flag < 0)
    throw ComputationError("CVodeGetDky at t = " + std::to_string(t) + " s: outside the last step" +
                           (I.last_error.empty() ? "" : ": " + I.last_error));
}

OdeStatus CvodeKlu::call_cvode(double t_out, double t_stop, int task) {
  Impl& I = *impl_;
  OdeStatus st;
  I.last_error.clear();
  I.callback_error.clear();
  // CVODE disables the stop time once reached; set it again whenever it differs.
  if (t_stop != I.stop_time) {
    const int sflag = CVodeSetStopTime(I.mem, t_stop);
    if (sflag < 0) {
      st.outcome = OdeOutcome::failed;
      st.t = t_;
      st.message = "CVodeSetStopTime failed" + (I.last_error.empty() ? "" : ": " + I.last_error);
      return st;
    }
    I.stop_time = t_stop;
  }
  int flag = 0;
  realtype t_reached = t_;
  flag = CVode(I.mem, t_out, I.y, &t_reached, task);  // into y_ (the constructor)
  t_ = t_reached;
  st.t = t_reached;
  if (flag == CV_TSTOP_RETURN) I.stop_time = std::nan("");  // reached: CVODE disabled it
  if (flag == CV_ROOT_RETURN) {
    st.outcome = OdeOutcome::root;
    st.roots.assign(static_cast<std::size_t>(I.problem.roots), 0);
    if (CVodeGetRootInfo(I.mem, st.roots.data()) < 0) {
      st.outcome = OdeOutcome::failed;
      st.message = "CVodeGetRootInfo failed";
    }
    ++I.root_returns;
  } else if (flag < 0) {
    st.outcome = OdeOutcome::failed;
    // CVodeGetReturnFlagName returns a malloc'ed string that the caller frees.
    char* name = CVodeGetReturnFlagName(flag);
    st.message = "CVODE flag " + std::to_string(flag) + " (" + (name ? name : "?") + ")";
    std::free(name);
    if (!I.last_error.empty()) st.message += ": " + I.last_error;
    if (!I.callback_error.empty()) st.message += ": " + I.callback_error;
  }
  return st;
}

void CvodeKlu::set_max_step(double h) {
  Impl& I = *impl_;
  // CVODE: hmax <= 0 restores the default, no bound.
  check(CVodeSetMaxStep(I.mem, h > 0 ? h : 0.0), "CVodeSetMaxStep", I);
}

void CvodeKlu::reinit(double t, const std::vector<double>& y) {
  Impl& I = *impl_;
  MODALTYRE_CHECK(static_cast<int64_t>(y.size()) == I.problem.size, "reinit size");
  if (y.data() != y_.data()) std::copy(y.begin(), y.end(), y_.begin());  // I.y's memory
  const OdeStats now = stats();
  I.before_reinit = now;
  check(CVodeReInit(I.mem, t, I.y), "CVodeReInit", I);
  I.stop_time = std::nan("");  // a re-initialisation clears the stop time
  t_ = t;
  ++I.reinits;
}

OdeStats CvodeKlu::stats() const {
  const Impl& I = *impl_;
  OdeStats s = I.before_reinit;
  long v = 0;
  if (CVodeGetNumSteps(I.mem, &v) == CV_SUCCESS) s.steps += v;
  if (CVodeGetNumRhsEvals(I.mem, &v) == CV_SUCCESS) s.rhs_evals += v;
  if (CVodeGetNumJacEvals(I.mem, &v) == CV_SUCCESS) s.jac_evals += v;
  // CVODE counts no Jacobian evaluations of a structured solver: its own count.
  if (I.problem.linear_setup) s.jac_evals = I.custom_jacobians;
  if (CVodeGetNumLinSolvSetups(I.mem, &v) == CV_SUCCESS) s.lin_setups += v;
  if (CVodeGetNumNonlinSolvIters(I.mem, &v) == CV_SUCCESS) s.nonlin_iters += v;
  if (CVodeGetNumNonlinSolvConvFails(I.mem, &v) == CV_SUCCESS) s.nonlin_fails += v;
  if (CVodeGetNumErrTestFails(I.mem, &v) == CV_SUCCESS) s.error_test_fails += v;
  realtype h = 0;
  if (CVodeGetLastStep(I.mem, &h) == CV_SUCCESS) s.last_step = h;
  int q = 0;
  if (CVodeGetLastOrder(I.mem, &q) == CV_SUCCESS) s.last_order = q;
  s.root_returns = I.root_returns;
  s.reinits = I.reinits;
  s.pattern_changes = I.pattern_changes;
  return s;
}

}  // namespace modaltyre::solvers
