// CVODE + KLU adapter against closed-form solutions.
#include "modaltyre/solvers/cvode_klu.h"

#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::solvers {
namespace {

// Tolerances: the integrator runs at rtol 1e-9 / atol 1e-12; the global error of BDF with error
// control is a small multiple of the local tolerance over a few periods.
constexpr double kRtol = 1e-9;
constexpr double kClosedFormTol = 1e-6;  // relative to the amplitude

// x'' + 2 zeta w x' + w^2 x = 0, x(0) = 1, x'(0) = 0: the problem, its analytic Jacobian and
// the closed-form solution, shared by the step-to-output and the interpolated-output tests.
struct DampedOscillator {
  double w = 2 * M_PI * 5, zeta = 0.05;
  OdeProblem problem() const {
    OdeProblem p;
    p.size = 2;
    p.rhs = [w = w, zeta = zeta](double, const double* y, double* yd) {
      yd[0] = y[1];
      yd[1] = -2 * zeta * w * y[1] - w * w * y[0];
      return 0;
    };
    p.jacobian = [w = w, zeta = zeta](double, const double*, const double*, CscMatrix& J) {
      J.col_ptr = {0, 1, 3};
      J.row = {1, 0, 1};
      J.value = {-w * w, 1.0, -2 * zeta * w};
      return 0;
    };
    return p;
  }
  double exact(double t) const {
    const double wd = w * std::sqrt(1 - zeta * zeta);
    return std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
  }
};

// max_newton: Newton iterations per step (0 = CVODE's 3), 6 as the transient driver uses.
OdeOptions oscillator_options(int max_newton = 0) {
  OdeOptions o;
  o.relative_tolerance = kRtol;
  o.absolute_tolerance = {1e-12};
  o.max_nonlinear_iterations = max_newton;
  return o;
}

TEST(CvodeKluTest, DampedOscillatorMatchesClosedForm) {
  const DampedOscillator osc;
  CvodeKlu ode(osc.problem(), oscillator_options(), 0.0, {1.0, 0.0}, 4);
  for (double t = 0.05; t <= 1.0 + 1e-12; t += 0.05) {
    const OdeStatus st = ode.advance(t);
    ASSERT_TRUE(st.ok()) << st.message;
    EXPECT_NEAR(ode.state()[0], osc.exact(t), kClosedFormTol) << "t = " << t;
  }
  EXPECT_GT(ode.stats().jac_evals, 0);
}

// Interpolated output: the integrator steps past the output times (stop time only at the end)
// and returns the state there from its BDF history; same closed form, same tolerance.
TEST(CvodeKluTest, InterpolatedOutputMatchesClosedForm) {
  const DampedOscillator osc;
  CvodeKlu ode(osc.problem(), oscillator_options(6), 0.0, {1.0, 0.0}, 4);
  const double t_end = 1.0;
  for (int k = 1; k <= 200; ++k) {
    const double t = k * 0.005;
    const OdeStatus st = ode.advance(t, t_end);
    ASSERT_TRUE(st.ok()) << st.message;
    ASSERT_EQ(st.t, t);
    EXPECT_NEAR(ode.state()[0], osc.exact(t), kClosedFormTol) << "t = " << t;
  }
  // Fewer steps than outputs would have forced with the output time as stop time.
  EXPECT_LT(ode.stats().steps, 20000);
  EXPECT_GT(ode.stats().last_step, 0.0);
}

// One internal step at a time, outputs interpolated inside each step (what the transient driver
// does): every output matches the closed form, and the steps stop exactly at the stop time.
TEST(CvodeKluTest, OneStepWithInterpolatedOutputsMatchesClosedForm) {
  const DampedOscillator osc;
  CvodeKlu ode(osc.problem(), oscillator_options(6), 0.0, {1.0, 0.0}, 4);
  const double t_end = 1.0, dt = 0.005;
  std::vector<double> y;
  int k = 1, outputs = 0, steps = 0;
  while (ode.time() < t_end) {
    const double before = ode.time();
    const OdeStatus st = ode.step(t_end);
    ASSERT_TRUE(st.ok()) << st.message;
    ASSERT_GT(st.t, before);
    ASSERT_LE(st.t, t_end);
    ++steps;
    for (; k * dt <= st.t * (1 + 1e-14) && k <= 200; ++k, ++outputs) {
      ode.interpolate(std::min(k * dt, st.t), y);
      EXPECT_NEAR(y[0], osc.exact(k * dt), kClosedFormTol) << "t = " << k * dt;
    }
  }
  EXPECT_EQ(ode.time(), t_end);
  EXPECT_EQ(outputs, 200);
  EXPECT_EQ(steps, ode.stats().steps);  // each call took exactly one internal step
  // A time outside the last step cannot be interpolated.
  EXPECT_THROW(ode.interpolate(0.0, y), modaltyre::ComputationError);
}

// First-order relaxation (seed 001 eq. 10): c t' + K t = f, t(0) = 0 -> t = f/K (1 - e^{-K t/c}).
// Many independent units: a diagonal Jacobian.
TEST(CvodeKluTest, FirstOrderRelaxationMatchesClosedForm) {
  const int n = 50;
  const double K = 5e4, f = 100;
  std::vector<double> c(n);
  for (int i = 0; i < n; ++i) c[i] = K * 0.01 * (1 + i);  // time constants 0.01 .. 0.5 s
  OdeProblem p;
  p.size = n;
  p.rhs = [&](double, const double* y, double* yd) {
    for (int i = 0; i < n; ++i) yd[i] = (f - K * y[i]) / c[i];
    return 0;
  };
  p.jacobian = [&](double, const double*, const double*, CscMatrix& J) {
    for (int i = 0; i < n; ++i) {
      J.col_ptr[i] = i;
      J.row.push_back(i);
      J.value.push_back(-K / c[i]);
    }
    J.col_ptr[n] = n;
    return 0;
  };
  OdeOptions o;
  o.relative_tolerance = kRtol;
  o.absolute_tolerance = {1e-14};
  CvodeKlu ode(p, o, 0.0, std::vector<double>(n, 0.0), n);
  const OdeStatus st = ode.advance(0.3);
  ASSERT_TRUE(st.ok()) << st.message;
  for (int i = 0; i < n; ++i) {
    const double exact = f / K * (1 - std::exp(-K * 0.3 / c[i]));
    EXPECT_NEAR(ode.state()[i], exact, kClosedFormTol * f / K) << i;
  }
}

// Root finding: free fall from 1 m hits y = 0 at sqrt(2/g); after a restart the integration
// continues (as the transient driver does at contact switches).
TEST(CvodeKluTest, RootIsLocatedAndIntegrationRestarts) {
  const double g = 9.81;
  OdeProblem p;
  p.size = 2;
  p.rhs = [&](double, const double* y, double* yd) {
    yd[0] = y[1];
    yd[1] = -g;
    return 0;
  };
  p.jacobian = [&](double, const double*, const double*, CscMatrix& J) {
    J.col_ptr = {0, 0, 1};
    J.row = {0};
    J.value = {1.0};
    return 0;
  };
  p.roots = 1;
  p.root_functions = [](double, const double* y, double* r) {
    r[0] = y[0];
    return 0;
  };
  OdeOptions o;
  o.relative_tolerance = kRtol;
  o.absolute_tolerance = {1e-12};
  CvodeKlu ode(p, o, 0.0, {1.0, 0.0}, 4);
  OdeStatus st = ode.advance(2.0);
  ASSERT_EQ(st.outcome, OdeOutcome::root);
  EXPECT_NEAR(st.t, std::sqrt(2 / g), 1e-7);
  EXPECT_EQ(st.roots[0], -1);  // falling through zero
  ode.reinit(st.t, ode.state());
  st = ode.advance(0.6);
  EXPECT_EQ(st.outcome, OdeOutcome::reached);
  EXPECT_NEAR(ode.state()[0], 1 - 0.5 * g * 0.36, 1e-6);
}

// A failing right-hand side becomes a status with a message and the time reached, not a throw.
TEST(CvodeKluTest, CallbackFailureIsReportedAsStatus) {
  OdeProblem p;
  p.size = 1;
  p.rhs = [](double t, const double*, double* yd) {
    yd[0] = 1;
    return t > 0.5 ? -1 : 0;
  };
  p.jacobian = [](double, const double*, const double*, CscMatrix& J) {
    J.col_ptr = {0, 0};
    return 0;
  };
  CvodeKlu ode(p, OdeOptions{}, 0.0, {0.0}, 1);
  const OdeStatus st = ode.advance(1.0);
  EXPECT_EQ(st.outcome, OdeOutcome::failed);
  EXPECT_FALSE(st.message.empty());
  EXPECT_LE(st.t, 0.5 + 1e-9);
}

}  // namespace
}  // namespace modaltyre::solvers
