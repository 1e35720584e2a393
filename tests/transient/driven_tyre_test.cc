// The tyre driven by its hub (driven_tyre.h, docs/transient.md section 8): a press (hub held at a
// deflection) settles to the static footprint's load at that sinking, a slow prescribed ramp
// follows the static load-deflection curve, the load control's own hub trajectory prescribed
// gives back its load, a step-by-step drive equals the same motion as a function, and instances
// are independent and reset cleanly. Coarse meshes (2 mm sections, 7.5 mm columns).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/data_paths.h"
#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/patch3d.h"
#include "modaltyre/transient/transient.h"
#include "transient_models.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig3d;
using test::Built;
using test::coarse_3d;
using test::rel;

// Issue 34's press test: the held hub's load equals the static footprint's load at the sinking
// within 1 %. Measured after a 0.5 s hold at 12 mm: 0.004 % (2D), 0.02 % (3D): the truncated
// residual (docs/transient.md section 1).
constexpr double kPressTol = 0.01;
// A ramp of 20 mm over 2 s (10 mm/s; the tread's relaxation time 2.4 ms lags it by 24 um, 0.2 %
// of 10 mm) against the static curve, at 25 % of the ramp and beyond; measured 0.17 % at most
// (3D at 5 mm).
constexpr double kRampTol = 0.01;
// The free vibration's hub trajectory prescribed (interpolated between 0.1 ms samples, see the
// test) against the load control's contact load, relative to the load: the two integrations'
// errors (tolerances kTight) and the interpolation's; measured 5.6 N (0.14 %).
constexpr double kTrajectoryTol = 0.005;
// A step-by-step drive (1 ms linear steps) against the same piecewise linear motion as a
// function: the same trajectory, integrated with a stop at every communication point or over the
// motion's kinks (tolerances kTight, where 0.01 um of tread is ~1 N); measured 4.9 N (0.18 % of
// the first load).
constexpr double kStepwiseTol = 5e-3;

// Integration tolerances 100 times tighter than the config's for the comparisons of two
// integrations of one trajectory: the contact's short-time stiffness (~90 kN/mm, the glassy tread
// behind the carcass's inertia) turns the default tread tolerance of 1 um into ~90 N.
const std::vector<std::string> kTight = {"transient.relative_tolerance=1e-7",
                                         "transient.tread_tolerance_um=0.01"};

Built build_coarse(std::vector<std::string> extra = {}) {
  Built b{build_tyre_model(load_tyre_config(kConfig3d, coarse_3d(std::move(extra)))), {}};
  b.model = build_transient_model(b.tyre);
  return b;
}

/// The static footprint's load at sinking `d` (bisection on the static solver of the patch).
double static_load_at(const TyreModel& tyre, double d, bool three_d) {
  const Patch3d patch(tyre, *tyre.config.footprint_3d);
  auto sinking = [&](double load) {
    if (three_d) return patch.solve(load).sinking_m;
    return solve_footprint(tyre, LoadCase{load, 0}).sinking_m;
  };
  double lo = 0, hi = 20000;
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (sinking(mid) < d ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

class Press : public ::testing::TestWithParam<bool> {};

// The hub pressed from touching to 12 mm in 20 ms and held: the load settles to the static
// footprint's at 12 mm sinking; a reset at 12 mm starts there.
TEST_P(Press, SettlesToTheStaticFootprintLoadAtTheSinking) {
  const bool three_d = GetParam();
  const Built b = build_coarse();
  DrivenTyreOptions opt;
  opt.force_2d = !three_d;
  opt.max_deflection_m = 0.015;
  DrivenTyre tyre(b.model, opt);
  ASSERT_EQ(tyre.patch_3d(), three_d);
  const double d = 0.012;
  HubState held;
  held.deflection_m = d;
  ASSERT_TRUE(tyre.advance(0.02, held).ok);
  const DriveStatus st = tyre.advance(0.5, held, HubInterpolation::hold);
  ASSERT_TRUE(st.ok) << st.message;
  const double F = static_load_at(b.tyre, d, three_d);
  const WheelLoad w = tyre.load();
  EXPECT_NEAR(w.t_s, 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(w.deflection_m, d);
  EXPECT_LT(rel(w.fz_N, F), kPressTol) << w.fz_N << " against " << F;
  EXPECT_NEAR(w.fx_N, 0, 1e-3 * F);  // standing: a symmetric patch
  EXPECT_NEAR(w.my_Nm, 0, 1e-5 * F);
  if (three_d) {
    EXPECT_GT(w.width_m, 0);
  }
  // A reset at the deflection starts in the static equilibrium.
  tyre.reset(held);
  EXPECT_LT(rel(tyre.load().fz_N, F), kPressTol);
  EXPECT_FALSE(tyre.widened());
}

INSTANTIATE_TEST_SUITE_P(BothPatches, Press, ::testing::Values(false, true));

class Ramp : public ::testing::TestWithParam<bool> {};

// A slow prescribed ramp of the deflection reproduces the static load-deflection curve.
TEST_P(Ramp, ReproducesTheStaticLoadDeflectionCurve) {
  const bool three_d = GetParam();
  const Built b = build_coarse();
  const double rate = 0.01, T = 2.0;  // 10 mm/s to 20 mm
  const TransientResult r = run_prescribed(
      b.model,
      [rate](double t) {
        return HubState{rate * t, 0, 0};
      },
      T, {}, !three_d);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.patch_3d, three_d);
  for (double d : {0.005, 0.010, 0.015, 0.020}) {
    const auto& s = r.samples[static_cast<std::size_t>(std::lround(d / rate / 0.002))];
    ASSERT_NEAR(s.hub_displacement_m, d, 1e-9);
    const double F = static_load_at(b.tyre, d, three_d);
    EXPECT_LT(rel(s.load_N, F), kRampTol) << "deflection " << d << ": " << s.load_N << " / " << F;
  }
}

INSTANTIATE_TEST_SUITE_P(BothPatches, Ramp, ::testing::Values(false, true));

// Load control and displacement control agree on one trajectory: the free vibration's hub
// motion, prescribed, gives back its contact load at every sample (3D patch). The hub's motion
// is interpolated between 0.1 ms samples by Catmull-Rom cubics: the contact's stiffness at short
// times is the glassy tread's (ratio 20) behind the carcass's inertia, ~90 kN/mm at 4 kN, so a
// linear interpolation between 2 ms samples (an error (dt^2 / 8) z'' = 25 um at the release)
// would move the load by kilonewtons.
TEST(DrivenTyre, ThePrescribedFreeVibrationTrajectoryGivesItsLoad) {
  const Built b = build_coarse({"transient.free_vibration.duration_s=0.2",
                                "transient.output_step_ms=0.1", kTight[0], kTight[1]});
  const TransientResult fv = run_transient_3d(b.model, Scenario::free_vibration);
  ASSERT_TRUE(fv.ok()) << fv.message;
  const double dt = b.model.settings.output_step_s;
  const auto& S = fv.samples;
  const int n = static_cast<int>(S.size());
  auto z_at = [&](double t) {
    const double u = std::clamp(t / dt, 0.0, static_cast<double>(n - 1));
    const int k = std::min(static_cast<int>(u), n - 2);
    const double a = u - k;
    auto z = [&](int i) {
      // Beyond the ends: the mirror image at the start (the release starts at rest, z'(0) = 0),
      // the linear extrapolation at the end (the hub still moves there: the last sample
      // repeated gave the last interval a wrong slope, and the glassy contact turned the ~0.3 um
      // into 5-27 N, depending on rounding-level changes of the trajectory).
      if (i < 0) return S[static_cast<std::size_t>(-i)].hub_displacement_m;
      if (i > n - 1)
        return 2 * S[static_cast<std::size_t>(n - 1)].hub_displacement_m -
               S[static_cast<std::size_t>(n - 2)].hub_displacement_m;
      return S[static_cast<std::size_t>(i)].hub_displacement_m;
    };
    const double p0 = z(k - 1), p1 = z(k), p2 = z(k + 1), p3 = z(k + 2);
    return 0.5 * (2 * p1 + (p2 - p0) * a + (2 * p0 - 5 * p1 + 4 * p2 - p3) * a * a +
                  (3 * p1 - p0 - 3 * p2 + p3) * a * a * a);
  };
  const TransientResult pr = run_prescribed(
      b.model,
      [&](double t) {
        return HubState{z_at(t), 0, 0};
      },
      fv.simulated_s);
  ASSERT_TRUE(pr.ok()) << pr.message;
  ASSERT_EQ(pr.samples.size(), S.size());
  const double F = b.model.settings.free_vibration.load_N;
  double worst = 0, swing = 0;
  for (std::size_t k = 0; k < S.size(); ++k) {
    worst = std::max(worst, std::abs(pr.samples[k].load_N - S[k].load_N));
    swing = std::max(swing, std::abs(S[k].load_N - F));
  }
  EXPECT_GT(swing, 0.1 * F);  // the tyre did vibrate
  EXPECT_LT(worst, kTrajectoryTol * F) << "largest load difference " << worst << " N";
}

// A step-by-step drive (1 ms communication steps, linear) equals the same piecewise linear motion
// given as a function; two instances interleaved run as one alone; a reset repeats the run
// exactly.
TEST(DrivenTyre, StepwiseEqualsTheFunctionAndInstancesAreIndependent) {
  const Built b = build_coarse(kTight);
  auto knot = [](int k) {
    const double t = 1e-3 * k;
    HubState s;
    s.deflection_m = 0.010 + 0.002 * std::sin(2 * M_PI * 15 * t);
    s.speed_m_s = 5 * t;
    return s;
  };
  auto motion = [&](double t) {  // the knots' linear interpolant
    const int k = std::min(static_cast<int>(t / 1e-3), 199);
    const double a = t / 1e-3 - k;
    const HubState s0 = knot(k), s1 = knot(k + 1);
    return HubState{s0.deflection_m + a * (s1.deflection_m - s0.deflection_m),
                    s0.speed_m_s + a * (s1.speed_m_s - s0.speed_m_s), NAN};
  };
  DrivenTyreOptions opt;
  opt.max_deflection_m = 0.013;
  DrivenTyre a(b.model, opt), c(b.model, opt), f(b.model, opt);
  a.reset(knot(0));
  c.reset(knot(0));
  f.reset(knot(0));
  f.follow(motion);
  std::vector<double> fa;
  double worst = 0;
  for (int k = 1; k <= 200; ++k) {
    const double t = 1e-3 * k;
    ASSERT_TRUE(a.advance(t, knot(k)).ok);
    ASSERT_TRUE(c.advance(t, knot(k)).ok);
    ASSERT_TRUE(f.advance(t).ok);
    fa.push_back(a.load().fz_N);
    EXPECT_EQ(a.load().fz_N, c.load().fz_N);  // bit for bit
    worst = std::max(worst, std::abs(f.load().fz_N - fa.back()));
  }
  EXPECT_LT(worst, kStepwiseTol * fa.front()) << "largest load difference " << worst << " N";
  // The spin followed the speed (free rolling: V / R0).
  EXPECT_NEAR(a.hub().spin_rad_s, 1.0 / b.model.tyre.config.outer_radius_m, 1e-12);
  // Reset and run again: the same loads.
  a.reset(knot(0));
  for (int k = 1; k <= 200; ++k) {
    const double t = 1e-3 * k;
    ASSERT_TRUE(a.advance(t, knot(k)).ok);
    ASSERT_EQ(a.load().fz_N, fa[static_cast<std::size_t>(k - 1)]) << "at " << t;
  }
  // Bad input is a status, not a crash.
  EXPECT_FALSE(a.advance(a.time(), knot(0)).ok);
  EXPECT_FALSE(a.advance(a.time() + 1e-3, HubState{NAN, 0, 0}).ok);
}

}  // namespace
}  // namespace modaltyre::transient
