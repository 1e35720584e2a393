// Carcass transfer functions (seed 001 eq. 1-5): closed-form modal sums of a ring under a point
// load, reciprocity and symmetry, the rolling limit, truncation convergence and the lag kernels.
#include "modaltyre/modal/carcass_kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include "modal_test_constants.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/modal_basis.h"
#include "modaltyre/modal/mode_identification.h"

namespace modaltyre::modal {
namespace {

using test::kMu;
using test::kPi;
using test::kR;
using test::kTwoPi;
const double kA2 = 1 / (kPi * kMu * kR);  // mass-normalised |c_r|^2 of a ring mode, k >= 1
// Sums of <= 1000 terms of either sign, compared with the same sum in another order.
constexpr double kSumRelTol = 1e-12;

/// omega_k^2 = s0 + s1 k^2 (+ s2 k^4): ring on an elastic foundation under tension (bending).
struct Law {
  double s0 = std::pow(kTwoPi * 85, 2), s1 = std::pow(kTwoPi * 24, 2), s2 = 0;
  double omega2(int k) const { return s0 + s1 * k * k + s2 * double(k) * k * k * k; }
};

/// Ring basis by hand: one term of weight 1 per order 1..K, radial a cos k(theta-psi),
/// tangential (a/k) sin k(theta-psi), i.e. c_r = a, c_t = -i a/k, plus a breathing term.
ModalBasis ring_basis(int K, const Law& law, double zeta = 0.03) {
  ModalBasis b;
  b.max_order = K;
  const double a0sq = 1 / (kTwoPi * kMu * kR);
  ModalTerm t0;
  t0.order = 0;
  t0.omega_rad_s = std::sqrt(law.omega2(0)) * 1.1;
  t0.damping_ratio = zeta;
  t0.P_rr = a0sq;
  b.terms.push_back(t0);
  for (int k = 1; k <= K; ++k) {
    const std::complex<double> cr(std::sqrt(kA2), 0), ct(0, -std::sqrt(kA2) / k);
    ModalTerm t;
    t.order = k;
    t.omega_rad_s = std::sqrt(law.omega2(k));
    t.damping_ratio = zeta;
    t.P_rr = cr * std::conj(cr);
    t.P_rt = cr * std::conj(ct);
    t.P_tt = ct * std::conj(ct);
    b.terms.push_back(t);
  }
  b.measured_terms = static_cast<int>(b.terms.size());
  return b;
}

ModalBasis sf350_basis(int max_order) {
  const auto data =
      read_hammer_csv(std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_hammer_12pt.csv");
  ModalBasisOptions o;
  o.max_order = max_order;
  return build_modal_basis(identify_modes(data), o);
}

// Static transfer functions equal the closed-form ring sums, computed independently:
//   H_rr = a0^2/w0^2 + sum a^2 cos(k D)/w_k^2,    H_tr (r_from_t) = -sum a^2 sin(k D)/(k w_k^2),
//   H_rt (t_from_r) = +sum a^2 sin(k D)/(k w_k^2),  H_tt = sum a^2 cos(k D)/(k^2 w_k^2).
TEST(CarcassKernel, StaticEqualsClosedFormRingSum) {
  const Law law;
  const int K = 200;
  const auto basis = ring_basis(K, law);
  const double w0sq = basis.terms[0].omega_rad_s * basis.terms[0].omega_rad_s;
  for (double D : {0.0, 0.013, 0.2, -0.35, 1.0, kPi, 4.0}) {
    double rr = basis.terms[0].P_rr.real() / w0sq, rt = 0, tr = 0, tt = 0, scale = rr;
    for (int k = 1; k <= K; ++k) {
      const double w2 = law.omega2(k);
      rr += kA2 * std::cos(k * D) / w2;
      tr += -kA2 * std::sin(k * D) / (k * w2);
      rt += kA2 * std::sin(k * D) / (k * w2);
      tt += kA2 * std::cos(k * D) / (double(k) * k * w2);
      scale += kA2 / w2;
    }
    const auto h = transfer(basis, D);
    EXPECT_NEAR(h.r_from_r, rr, kSumRelTol * scale) << "D=" << D;
    EXPECT_NEAR(h.r_from_t, tr, kSumRelTol * scale) << "D=" << D;
    EXPECT_NEAR(h.t_from_r, rt, kSumRelTol * scale) << "D=" << D;
    EXPECT_NEAR(h.t_from_t, tt, kSumRelTol * scale) << "D=" << D;
  }
  // The lag kernels on a grid give the same closed-form sums at every lag.
  const double dth = kTwoPi / 720;
  const int lags = 360;
  const auto LK = build_lag_kernels(basis, dth, lags);
  for (int j = -(lags - 1); j < lags; ++j) {
    const double D = j * dth;
    double rr = basis.terms[0].P_rr.real() / w0sq, tr = 0, scale = rr;
    for (int k = 1; k <= K; ++k) {
      rr += kA2 * std::cos(k * D) / law.omega2(k);
      tr += -kA2 * std::sin(k * D) / (k * law.omega2(k));
      scale += kA2 / law.omega2(k);
    }
    ASSERT_NEAR(LK.at(j).r_from_r, rr, kSumRelTol * scale) << "j=" << j;
    ASSERT_NEAR(LK.at(j).r_from_t, tr, kSumRelTol * scale) << "j=" << j;
  }
  // The static radial point compliance is positive and largest under the load.
  const double h0 = transfer(basis, 0).r_from_r;
  EXPECT_GT(h0, 0);
  for (double D : {0.1, 0.5, 1.0, 3.0}) EXPECT_LT(transfer(basis, D).r_from_r, h0);
}

// Static reciprocity (Maxwell-Betti): the radial response to a tangential force equals the
// tangential response to a radial force with the points swapped; H_rr and H_tt are even.
TEST(CarcassKernel, StaticReciprocityAndSymmetry) {
  for (const auto& basis : {ring_basis(300, Law{}), sf350_basis(300)}) {
    const double scale = std::abs(transfer(basis, 0).r_from_r);
    for (double D : {0.01, 0.07, 0.3, 1.1, 2.5}) {
      const auto p = transfer(basis, D), m = transfer(basis, -D);
      EXPECT_NEAR(p.r_from_t, m.t_from_r, kSumRelTol * scale);
      EXPECT_NEAR(p.r_from_r, m.r_from_r, kSumRelTol * scale);
      EXPECT_NEAR(p.t_from_t, m.t_from_t, kSumRelTol * scale);
    }
  }
}

// Rolling: as V -> 0 the kernel tends to the static one, the difference shrinking in proportion
// to V (the damping term of D_k is first order in k Omega); at speed the damped kernel becomes
// asymmetric in Delta, and without damping it stays symmetric (no rolling resistance).
TEST(CarcassKernel, RollingLimitAndAsymmetry) {
  // Linear regime: dividing V by 10 divides the difference by 10 to within 2 %
  // (the next term is O(V^2)).
  constexpr double kLinearTol = 0.02;
  const auto basis = sf350_basis(400);
  const double dth = kTwoPi / 2000;
  const int lags = 400;
  const auto st = build_lag_kernels(basis, dth, lags);
  const double scale = *std::max_element(st.r_from_r.begin(), st.r_from_r.end());
  auto diff = [&](double V) {
    const auto k = build_lag_kernels(basis, dth, lags, {V, kR});
    double d = 0;
    for (std::size_t i = 0; i < k.r_from_r.size(); ++i)
      d = std::max(d, std::abs(k.r_from_r[i] - st.r_from_r[i]));
    return d / scale;
  };
  EXPECT_EQ(diff(0.0), 0.0);
  const double d3 = diff(1e-3), d4 = diff(1e-4), d5 = diff(1e-5);
  EXPECT_LT(d3, 1e-3);
  EXPECT_NEAR(d3 / d4, 10.0, 10.0 * kLinearTol);
  EXPECT_NEAR(d4 / d5, 10.0, 10.0 * kLinearTol);

  // At 20 m/s (72 km/h, below every mode's critical speed omega_k R / k) the kernel is skewed.
  const RollingState fast{20.0, kR};
  for (const auto& t : basis.terms) {
    if (t.order > 0) {
      ASSERT_LT(t.order * fast.speed_m_s / fast.radius_m, t.omega_rad_s);
    }
  }
  double odd = 0;
  for (double D : {0.02, 0.05, 0.1, 0.2})
    odd = std::max(
        odd, std::abs(transfer(basis, D, fast).r_from_r - transfer(basis, -D, fast).r_from_r));
  // Damping ratios are 2-5 %; the skew is a few % of the peak, far above rounding.
  EXPECT_GT(odd / scale, 1e-3);

  auto undamped = basis;
  for (auto& t : undamped.terms) t.damping_ratio = 0;
  for (double D : {0.02, 0.05, 0.1, 0.2}) {
    EXPECT_NEAR(transfer(undamped, D, fast).r_from_r, transfer(undamped, -D, fast).r_from_r,
                kSumRelTol * scale);
  }
}

// Truncation: the point compliance H_rr(0) converges as max_order grows. For a ring with
// membrane tension (omega_k^2 ~ s1 k^2) the tail is ~ a^2/(s1 K), so each doubling of K adds
// half of the previous increment; the SF-350 basis converges at least as fast.
TEST(CarcassKernel, ConvergenceWithMaxOrder) {
  // Euler-Maclaurin end corrections change the increment ratio by O(1/K) <= 1.5 % at K = 100.
  constexpr double kRatioTol = 0.05;
  const int Ks[] = {100, 200, 400, 800, 1600};
  std::vector<double> ring, tyre;
  for (int K : Ks) {
    ring.push_back(transfer(ring_basis(K, Law{}), 0).r_from_r);
    tyre.push_back(transfer(sf350_basis(K), 0).r_from_r);
  }
  for (std::size_t i = 1; i + 1 < ring.size(); ++i) {
    const double inc = ring[i] - ring[i - 1], next = ring[i + 1] - ring[i];
    EXPECT_GT(inc, 0);  // every added order adds compliance
    EXPECT_NEAR(inc / next, 2.0, 2.0 * kRatioTol) << "K=" << Ks[i];
    // Tail estimate: increment ~ a^2 / (2 s1 K).
    EXPECT_NEAR(inc / (kA2 / (2 * Law{}.s1 * Ks[i - 1])), 1.0, kRatioTol);
    const double tinc = tyre[i] - tyre[i - 1], tnext = tyre[i + 1] - tyre[i];
    EXPECT_GT(tinc, 0);
    EXPECT_GE(tinc / tnext, 2.0 * (1 - kRatioTol)) << "K=" << Ks[i];  // at least 1/K
  }
}

// The O(terms * lags) recurrence of build_lag_kernels equals direct evaluation of transfer() at
// every lag, static and rolling, for all four functions.
TEST(CarcassKernel, LagKernelsMatchTransfer) {
  const auto basis = sf350_basis(800);
  const double dth = kTwoPi / 3000;
  const int lags = 1500;
  for (double V : {0.0, 25.0}) {
    const RollingState rs{V, kR};
    const auto K = build_lag_kernels(basis, dth, lags, rs);
    ASSERT_EQ(K.r_from_r.size(), std::size_t(2 * lags - 1));
    double mx[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < K.r_from_r.size(); ++i) {
      mx[0] = std::max(mx[0], std::abs(K.r_from_r[i]));
      mx[1] = std::max(mx[1], std::abs(K.r_from_t[i]));
      mx[2] = std::max(mx[2], std::abs(K.t_from_r[i]));
      mx[3] = std::max(mx[3], std::abs(K.t_from_t[i]));
    }
    for (int j = -(lags - 1); j <= lags - 1; ++j) {
      const auto h = transfer(basis, j * dth, rs);
      const auto k = K.at(j);
      ASSERT_NEAR(k.r_from_r, h.r_from_r, kSumRelTol * mx[0]) << "V=" << V << " j=" << j;
      ASSERT_NEAR(k.r_from_t, h.r_from_t, kSumRelTol * mx[1]) << "V=" << V << " j=" << j;
      ASSERT_NEAR(k.t_from_r, h.t_from_r, kSumRelTol * mx[2]) << "V=" << V << " j=" << j;
      ASSERT_NEAR(k.t_from_t, h.t_from_t, kSumRelTol * mx[3]) << "V=" << V << " j=" << j;
    }
  }
}

TEST(CarcassKernel, PeriodicFftKernelsEqualDirectSums) {
  // The FFT route (one inverse transform per function on the n-unit grid) must reproduce the
  // direct O(terms * lags) sums, static and rolling, at every lag; rounding only.
  constexpr double kFftRoundoff = 1e-11;
  const int n = fft_friendly_size(1000);
  EXPECT_EQ(n, 1000);                        // 2^3 5^3
  EXPECT_EQ(fft_friendly_size(7409), 7500);  // nearest 2^a 3^b 5^c
  const ModalBasis basis = sf350_basis(n / 2);
  for (double speed : {0.0, 15.0}) {
    const RollingState rolling{speed, 0.2948};
    const int lags = 120;
    const LagKernels direct = build_lag_kernels(basis, 2 * M_PI / n, lags, rolling);
    const LagKernels fft = build_periodic_kernels(basis, n, lags, rolling);
    const double scale = std::abs(direct.r_from_r[lags - 1]);
    for (int j = -(lags - 1); j < lags; ++j) {
      const auto a = direct.at(j), b = fft.at(j);
      EXPECT_NEAR(a.r_from_r, b.r_from_r, kFftRoundoff * scale) << j;
      EXPECT_NEAR(a.r_from_t, b.r_from_t, kFftRoundoff * scale) << j;
      EXPECT_NEAR(a.t_from_r, b.t_from_r, kFftRoundoff * scale) << j;
      EXPECT_NEAR(a.t_from_t, b.t_from_t, kFftRoundoff * scale) << j;
    }
  }
}

}  // namespace
}  // namespace modaltyre::modal
