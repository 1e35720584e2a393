// The 3D transient's slot passes (transient/src/slot_kernels.h) against their stated operations
// to the bit: the AVX2 path on this CPU, the portable one under MODALTYRE_ISA=portable (the
// `portable.` tests); both must give the bits of the plain loops they replaced.
#include "../../transient/src/slot_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace modaltyre::transient::detail {
namespace {

std::vector<double> random_values(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = u(rng) * std::exp(6 * u(rng));
  for (int k = 0; k < n; k += 7) v[k] = 0.0;  // exact zeros: the kink's own side
  return v;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(SlotKernels, SlotPassIsThePenetrationAndTheForcesOfEachSlot) {
  std::mt19937 rng(47);
  const double drop = 3.7e-4, mu = 2.0;
  for (int n : {0, 1, 3, 4, 5, 8, 17, 41, 137}) {
    const std::vector<double> P = random_values(rng, n), h = random_values(rng, n),
                              e = random_values(rng, n), F0 = random_values(rng, n);
    std::vector<double> kc = random_values(rng, n);
    for (double& k : kc) k = std::abs(k) + 1.0;  // springs are positive
    for (bool road : {false, true}) {
      for (bool tread : {false, true}) {
        for (bool with_forces : {false, true}) {
          std::vector<double> g(n), f(n, -1.0), F = F0;
          slot_pass(n, P.data(), drop, road ? h.data() : nullptr, tread ? e.data() : nullptr,
                    kc.data(), mu, g.data(), with_forces ? f.data() : nullptr,
                    with_forces ? F.data() : nullptr);
          for (int k = 0; k < n; ++k) {
            double gk = P[k] - drop;
            if (road) gk = gk + h[k];
            if (tread) gk = gk - e[k];
            ASSERT_TRUE(same_bits(g[k], gk)) << n << " " << k;
            if (!with_forces) {
              ASSERT_EQ(f[k], -1.0);  // untouched
              ASSERT_TRUE(same_bits(F[k], F0[k]));
              continue;
            }
            const double fk = gk > 0 ? kc[k] * gk : 0.0;
            ASSERT_TRUE(same_bits(f[k], fk)) << n << " " << k;
            ASSERT_TRUE(same_bits(F[k], F0[k] + mu * fk)) << n << " " << k;
          }
        }
      }
    }
  }
}

TEST(SlotKernels, ContactFlipsCountsTheCellsThatChangedSide) {
  std::mt19937 rng(5);
  for (int n : {0, 1, 3, 4, 7, 16, 33, 200}) {
    const std::vector<double> g = random_values(rng, n);
    std::vector<char> in(n);
    for (int k = 0; k < n; ++k) in[k] = static_cast<char>(rng() % 2);
    int expected = 0;
    std::vector<char> now(n);
    for (int k = 0; k < n; ++k) {
      now[k] = g[k] > 0 ? 1 : 0;
      expected += now[k] != in[k];
    }
    ASSERT_EQ(contact_flips(n, g.data(), in.data()), expected) << n;
    ASSERT_EQ(in, now) << n;
    ASSERT_EQ(contact_flips(n, g.data(), in.data()), 0) << n;  // nothing changed since
  }
}

TEST(SlotKernels, TreadRatesAreTheUpwindExpression) {
  std::mt19937 rng(11);
  const double a0 = 1.5e3, a1 = -2.0e3, a2 = 0.5e3;
  for (int n : {0, 1, 2, 3, 4, 5, 9, 64, 65}) {
    const std::vector<double> f = random_values(rng, n), ic = random_values(rng, n),
                              kk = random_values(rng, n), e = random_values(rng, n);
    std::vector<double> d(n), rest(n);
    tread_rates(n, f.data(), ic.data(), kk.data(), e.data(), a0, a1, a2, false, d.data());
    tread_rates(n, f.data(), ic.data(), kk.data(), e.data(), 0, 0, 0, true, rest.data());
    for (int k = 0; k < n; ++k) {
      double v = (f[k] * ic[k] - e[k] * kk[k]) + a0 * e[k];
      if (k + 1 < n) v = v + a1 * e[k + 1];
      if (k + 2 < n) v = v + a2 * e[k + 2];
      ASSERT_TRUE(same_bits(d[k], v)) << n << " " << k;
      ASSERT_TRUE(same_bits(rest[k], f[k] * ic[k] - e[k] * kk[k])) << n << " " << k;
    }
  }
}

TEST(SlotKernels, NewtonsSlotPassesAreTheirExpressions) {
  // CellNewton::solve()'s gather onto the sections and scatter back to the tread rows.
  std::mt19937 rng(21);
  for (int n : {0, 1, 3, 4, 6, 13, 64, 111}) {
    const std::vector<double> w = random_values(rng, n), b = random_values(rng, n),
                              d = random_values(rng, n), g = random_values(rng, n),
                              s0 = random_values(rng, n), x0 = random_values(rng, n);
    std::vector<double> s_rest = s0, s_roll = s0, x_rest = x0, x_roll = x0, x_scaled = x0;
    slot_gather(n, w.data(), b.data(), d.data(), s_rest.data());
    slot_gather(n, w.data(), b.data(), nullptr, s_roll.data());
    slot_scatter(n, g.data(), s0.data(), d.data(), x_rest.data());
    slot_scatter(n, g.data(), s0.data(), nullptr, x_roll.data());
    slot_scale(n, d.data(), x_scaled.data());
    for (int k = 0; k < n; ++k) {
      ASSERT_TRUE(same_bits(s_rest[k], s0[k] + w[k] * (b[k] * d[k]))) << n << " " << k;
      ASSERT_TRUE(same_bits(s_roll[k], s0[k] + w[k] * b[k])) << n << " " << k;
      ASSERT_TRUE(same_bits(x_rest[k], (x0[k] + g[k] * s0[k]) * d[k])) << n << " " << k;
      ASSERT_TRUE(same_bits(x_roll[k], x0[k] + g[k] * s0[k])) << n << " " << k;
      ASSERT_TRUE(same_bits(x_scaled[k], x0[k] * d[k])) << n << " " << k;
    }
  }
}

}  // namespace
}  // namespace modaltyre::transient::detail
