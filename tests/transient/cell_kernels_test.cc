// The 3D transient's vector kernels (transient/src/cell_kernels.h, slot_kernels.h) against their
// stated operations to the bit (the AVX2 paths on this CPU, the portable ones under
// MODALTYRE_ISA=portable, the `portable.` tests: the same bits) and the scans against plain loops.
#include "../../transient/src/cell_kernels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "../../transient/src/slot_kernels.h"
#include "modaltyre/transient/column_product.h"

namespace modaltyre::transient::detail {
namespace {

std::vector<double> random_values(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = u(rng) * std::exp(6 * u(rng));
  return v;
}

TEST(CellKernels, SmallGemmHasTheBitsOfAColumnProductPerColumn) {
  // The capacitance matrix H K was a column_product() per column of K: the register-blocked
  // product must give the same bits (a flat crown's arithmetic depends on them).
  std::mt19937 rng(33);
  for (int m : {1, 2, 3, 5, 12, 13, 41, 42}) {
    for (int n : {1, 3, 4, 42}) {
      for (int k : {1, 7, 42, 47, 114}) {
        const int lda = m + 3, ldb = k + 2, ldc = m + 1;
        const std::vector<double> A = random_values(rng, lda * k), B = random_values(rng, ldb * n);
        const std::vector<double> base = random_values(rng, ldc * n);
        std::vector<double> got(ldc * n, 0.0), added = base;
        small_gemm(m, n, k, A.data(), lda, B.data(), ldb, got.data(), ldc);
        small_gemm(m, n, k, A.data(), lda, B.data(), ldb, added.data(), ldc, /*accumulate=*/true);
        for (int j = 0; j < n; ++j) {
          std::vector<double> col(m), acc(base.begin() + j * ldc, base.begin() + j * ldc + m);
          column_product(m, k, A.data(), lda, B.data() + j * ldb, col.data());
          column_product(m, k, A.data(), lda, B.data() + j * ldb, acc.data(), true);
          for (int i = 0; i < m; ++i) {
            ASSERT_EQ(col[i], got[j * ldc + i]) << m << " x " << n << " x " << k;
            ASSERT_EQ(acc[i], added[j * ldc + i]) << m << " x " << n << " x " << k;
          }
        }
        // Entries outside the m rows of each column are left alone.
        for (int j = 0; j < n; ++j)
          for (int i = m; i < ldc; ++i) ASSERT_EQ(base[j * ldc + i], added[j * ldc + i]);
      }
    }
  }
}

TEST(CellKernels, BandRowIsTheScalarExpression) {
  // factor()'s back substitution row: ((a t - s1 y1) - s2 y2) d, and r += w (t - gamma y), the
  // same operations as the loops it replaced (no fused multiply-add).
  std::mt19937 rng(7);
  for (int n : {1, 4, 5, 42}) {
    for (bool with_t : {true, false}) {
      const std::vector<double> t = random_values(rng, n), y1 = random_values(rng, n),
                                y2 = random_values(rng, n), r0 = random_values(rng, n);
      const double a = 0.37, s1 = -0.8, s2 = 0.2, d = 0.93, w = 4.5e5, gamma = 1.3e-4;
      std::vector<double> y(n), r = r0;
      band_row(n, with_t, a, t.data(), y1.data(), y2.data(), s1, s2, d, y.data(), r.data(), w,
               gamma);
      for (int j = 0; j < n; ++j) {
        const double want = with_t ? ((a * t[j] - s1 * y1[j]) - s2 * y2[j]) * d
                                   : ((0.0 - s1 * y1[j]) - s2 * y2[j]) * d;
        ASSERT_EQ(want, y[j]);
        ASSERT_EQ(r0[j] + w * (t[j] - gamma * want), r[j]);
      }
    }
  }
}

TEST(CellKernels, PairDotsSumInTheirStatedOrder) {
  // Eight partial sums per output (rows k mod 8), lane-wise (k mod 4) + (k mod 4 + 4), then
  // (s0 + s1) + (s2 + s3), then the last n % 8 rows in order; and the dot products to rounding.
  std::mt19937 rng(11);
  for (int n : {0, 3, 8, 13, 114, 223}) {
    for (bool second : {true, false}) {
      const std::vector<double> a = random_values(rng, n), b = random_values(rng, n),
                                x = random_values(rng, n), c = random_values(rng, n),
                                dd = random_values(rng, n), y = random_values(rng, n);
      double out[2];
      pair_dots(n, a.data(), b.data(), x.data(), second ? c.data() : nullptr,
                second ? dd.data() : nullptr, second ? y.data() : nullptr, out);
      auto stated = [&](const std::vector<double>& p, const std::vector<double>& q) {
        double s[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        const int n8 = n / 8 * 8;
        for (int k = 0; k < n8; ++k) {
          s[k % 8] = std::fma(p[k], x[k], s[k % 8]);
          if (second) s[k % 8] = std::fma(q[k], y[k], s[k % 8]);
        }
        double r = ((s[0] + s[4]) + (s[1] + s[5])) + ((s[2] + s[6]) + (s[3] + s[7]));
        for (int k = n8; k < n; ++k) {
          r = std::fma(p[k], x[k], r);
          if (second) r = std::fma(q[k], y[k], r);
        }
        return r;
      };
      ASSERT_EQ(stated(a, c), out[0]) << n;
      ASSERT_EQ(stated(b, dd), out[1]) << n;
      double plain = 0, scale = 0;
      for (int k = 0; k < n; ++k) {
        plain += a[k] * x[k] + (second ? c[k] * y[k] : 0.0);
        scale += std::abs(a[k] * x[k]) + (second ? std::abs(c[k] * y[k]) : 0.0);
      }
      EXPECT_NEAR(plain, out[0], 1e-13 * scale);
    }
  }
}

TEST(CellKernels, ScansEqualPlainLoops) {
  // Signs, zeros of either sign and NaN (never a force, but never "in contact" either).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> pick(0, 4);
  const double values[] = {1.5, -2.0, 0.0, -0.0, nan};
  for (int n : {0, 1, 3, 4, 7, 8, 9, 31, 240}) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> a(n), b(n);
      for (int k = 0; k < n; ++k) a[k] = values[pick(rng)], b[k] = values[pick(rng)];
      std::vector<int> got, want;
      sign_mismatches(n, a.data(), b.data(), got);
      int first = n, last = -1, count = 0;
      for (int k = 0; k < n; ++k) {
        if ((a[k] > 0) != (b[k] > 0)) want.push_back(k);
        if (a[k] > 0) first = std::min(first, k), last = k, ++count;
      }
      ASSERT_EQ(want, got);
      ASSERT_EQ(first, first_positive(a.data(), n));
      ASSERT_EQ(last, last_positive(a.data(), n));
      ASSERT_EQ(count, count_positive(a.data(), n));
    }
    std::vector<int> lo(n), hi(n);
    for (int k = 0; k < n; ++k) lo[k] = k % 5, hi[k] = 10 - k % 7;
    std::vector<int> lo0 = lo, hi0 = hi;
    min_max_fill(lo.data(), hi.data(), n, 2, 6);
    for (int k = 0; k < n; ++k) {
      ASSERT_EQ(std::min(lo0[k], 2), lo[k]);
      ASSERT_EQ(std::max(hi0[k], 6), hi[k]);
    }
  }
}

/// lu_factor() of the row-major n x n a0 against its stated steps as a plain loop on the
/// row-major copy, to the bit (pivots too), and L U = P A. False if a pivot vanished.
bool lu_matches_the_stated_steps(int n, const std::vector<double>& a0) {
  std::vector<double> col(n * n), a(n * n, 0.0), want = a0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) col[j * n + i] = a0[i * n + j];
  std::vector<int> rows(n), want_rows(n);
  const bool ok = lu_factor(n, col.data(), a.data(), rows.data());
  for (int i = 0; i < n; ++i) want_rows[i] = i;
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(want[i * n + k]) > std::abs(want[p * n + k])) p = i;
    for (int j = 0; j < n; ++j) std::swap(want[k * n + j], want[p * n + j]);
    std::swap(want_rows[k], want_rows[p]);
    if (want[k * n + k] == 0) {
      EXPECT_FALSE(ok) << "n " << n << ": the stated steps meet a zero pivot at " << k;
      return false;
    }
    for (int i = k + 1; i < n; ++i) {
      const double l = want[i * n + k] / want[k * n + k];
      want[i * n + k] = l;
      for (int j = k + 1; j < n; ++j)
        want[i * n + j] = std::fma(-l, want[k * n + j], want[i * n + j]);
    }
  }
  EXPECT_TRUE(ok) << n;
  EXPECT_EQ(want_rows, rows) << n;
  for (int e = 0; e < n * n; ++e) EXPECT_EQ(want[e], a[e]) << "n " << n << " entry " << e;
  // L U = P A.
  double worst = 0, scale = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double s = 0;
      for (int k = 0; k <= std::min(i, j); ++k) s += (k == i ? 1.0 : a[i * n + k]) * a[k * n + j];
      worst = std::max(worst, std::abs(s - a0[rows[i] * n + j]));
      scale = std::max(scale, std::abs(a0[i * n + j]));
    }
  EXPECT_LT(worst, 1e-12 * n * scale) << n;
  return true;
}

TEST(CellKernels, LuFactorIsPartialPivotingWithOneFusedMultiplyAddPerEntry) {
  std::mt19937 rng(3);
  // Sizes around the AVX2 path's blocks of 4 and 16 rows (Crout's order there).
  for (int n : {1, 2, 3, 4, 5, 6, 7, 16, 17, 20, 21, 36, 37, 41, 42, 70})
    EXPECT_TRUE(lu_matches_the_stated_steps(n, random_values(rng, n * n))) << n;
  std::vector<double> singular = {1, 2, 2, 4}, lu(4);
  std::vector<int> rows(2);
  EXPECT_FALSE(lu_factor(2, singular.data(), lu.data(), rows.data()));
}

TEST(CellKernels, CholeskyFactorIsTheStatedColumnSweepsToTheBit) {
  std::mt19937 rng(47);
  // Sizes around the AVX2 path's blocks of 4 and 16 rows.
  for (int n : {1, 2, 3, 4, 5, 7, 16, 17, 20, 36, 37, 41, 70}) {
    // A = B B^T + I: symmetric positive definite, entries of mixed magnitude.
    const std::vector<double> B = random_values(rng, n * n);
    std::vector<double> a(n * n, 0.0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        double s = i == j ? 1.0 : 0.0;
        for (int k = 0; k < n; ++k) s += B[i * n + k] * B[j * n + k];
        a[j * n + i] = s;
      }
    std::vector<double> l(n * n, 0.0), want(n * n, 0.0);
    ASSERT_TRUE(cholesky_factor(n, a.data(), l.data())) << n;
    for (int j = 0; j < n; ++j) {
      for (int i = j; i < n; ++i) {
        double c = a[j * n + i];
        for (int p = 0; p < j; ++p) c = std::fma(-want[p * n + i], want[p * n + j], c);
        want[j * n + i] = c;
      }
      const double d = std::sqrt(want[j * n + j]);
      want[j * n + j] = d;
      for (int i = j + 1; i < n; ++i) want[j * n + i] /= d;
    }
    for (int j = 0; j < n; ++j)
      for (int i = j; i < n; ++i) ASSERT_EQ(want[j * n + i], l[j * n + i]) << n << " " << i << j;
    // L L^T = A.
    double worst = 0, scale = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j <= i; ++j) {
        double s = 0;
        for (int p = 0; p <= j; ++p) s += l[p * n + i] * l[p * n + j];
        worst = std::max(worst, std::abs(s - a[j * n + i]));
        scale = std::max(scale, std::abs(a[j * n + i]));
      }
    EXPECT_LT(worst, 1e-13 * n * scale) << n;
  }
  const std::vector<double> indefinite = {1, 2, 2, 1};
  std::vector<double> l(4);
  EXPECT_FALSE(cholesky_factor(2, indefinite.data(), l.data()));
}

TEST(CellKernels, LowerTriangularSolvesAreTheirStatedOperationsToTheBit) {
  std::mt19937 rng(48);
  for (int n : {1, 2, 3, 4, 5, 8, 16, 17, 21, 37, 42}) {
    std::vector<double> l = random_values(rng, n * n);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < j; ++i) l[j * n + i] = 0;  // lower triangle only
      l[j * n + j] = 1.0 + std::abs(l[j * n + j]);
    }
    const std::vector<double> b = random_values(rng, n);
    // x <- L^-1 x by columns.
    std::vector<double> want = b, got = b;
    for (int p = 0; p < n; ++p) {
      want[p] /= l[p * n + p];
      for (int i = p + 1; i < n; ++i) want[i] = std::fma(-l[p * n + i], want[p], want[i]);
    }
    lower_solve(n, l.data(), got.data());
    for (int i = 0; i < n; ++i) ASSERT_EQ(want[i], got[i]) << "L^-1, n " << n << " row " << i;
    // x <- L^-T x by rows from the last, the dot products in four lanes.
    want = b, got = b;
    for (int i = n - 1; i >= 0; --i) {
      const int m = n - i - 1, m4 = m / 4 * 4;
      double s[4] = {0, 0, 0, 0};
      for (int k = 0; k < m4; ++k)
        s[k % 4] = std::fma(l[i * n + i + 1 + k], want[i + 1 + k], s[k % 4]);
      double d = (s[0] + s[1]) + (s[2] + s[3]);
      for (int k = m4; k < m; ++k) d = std::fma(l[i * n + i + 1 + k], want[i + 1 + k], d);
      want[i] = (want[i] - d) / l[i * n + i];
    }
    lower_transpose_solve(n, l.data(), got.data());
    for (int i = 0; i < n; ++i) ASSERT_EQ(want[i], got[i]) << "L^-T, n " << n << " row " << i;
    // y = L x.
    std::vector<double> y(n);
    square_product(n, l.data(), b.data(), y.data());
    for (int i = 0; i < n; ++i) {
      double s = 0;
      for (int p = 0; p < n; ++p) s = std::fma(-l[p * n + i], -b[p], s);
      ASSERT_EQ(s, y[i]) << "L x, n " << n << " row " << i;
    }
  }
}

TEST(CellKernels, BandLockstep8IsTheScalarRecurrenceToTheBit) {
  std::mt19937 rng(50);
  for (int len : {2, 3, 4, 9, 40}) {
    std::vector<std::vector<double>> y0, d;
    for (int l = 0; l < 8; ++l)
      y0.push_back(random_values(rng, len)), d.push_back(random_values(rng, len));
    const double s1 = -0.37, s2 = 0.093;
    auto want = y0, got = y0;
    double* ye[8];
    const double* de[8];
    for (int l = 0; l < 8; ++l) {
      double* e = want[l].data() + len - 1;
      for (int t = 2; t < len; ++t)
        e[-t] = (e[-t] - s1 * e[1 - t] - s2 * e[2 - t]) * d[l][len - 1 - t];
      ye[l] = got[l].data() + len - 1, de[l] = d[l].data() + len - 1;
    }
    band_lockstep8(2, len, ye, de, s1, s2);
    for (int l = 0; l < 8; ++l)
      for (int k = 0; k < len; ++k) ASSERT_EQ(want[l][k], got[l][k]) << len << " " << l << " " << k;
  }
}

TEST(CellKernels, LuFactorTakesTheFirstOfTiedPivots) {
  // Small integers: columns with several entries of the same largest magnitude (either sign),
  // where the pivot must be the first of them, as the stated search takes it (the AVX2 path
  // searches by a vector maximum, then its first occurrence).
  std::mt19937 rng(17);
  std::uniform_int_distribution<int> v(-3, 3);
  int factored = 0;
  for (int trial = 0; trial < 40; ++trial) {
    for (int n : {5, 8, 9, 13, 37}) {
      std::vector<double> a0(n * n);
      for (double& x : a0) x = v(rng);
      factored += lu_matches_the_stated_steps(n, a0) ? 1 : 0;
    }
  }
  EXPECT_GT(factored, 100);  // most are regular
}

/// random_values() with exact zeros at every seventh entry (the contact kink's own side).
std::vector<double> random_with_zeros(std::mt19937& rng, int n) {
  std::vector<double> v = random_values(rng, n);
  for (int k = 0; k < n; k += 7) v[k] = 0.0;
  return v;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The slot passes (transient/src/slot_kernels.h): the bits of the plain loops they replaced.

TEST(SlotKernels, SlotPassIsThePenetrationAndTheForcesOfEachSlot) {
  std::mt19937 rng(47);
  const double drop = 3.7e-4, mu = 2.0;
  for (int n : {0, 1, 3, 4, 5, 8, 17, 41, 137}) {
    const std::vector<double> P = random_with_zeros(rng, n), h = random_with_zeros(rng, n),
                              e = random_with_zeros(rng, n), F0 = random_with_zeros(rng, n);
    std::vector<double> kc = random_with_zeros(rng, n);
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
    const std::vector<double> g = random_with_zeros(rng, n);
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
    const std::vector<double> f = random_with_zeros(rng, n), ic = random_with_zeros(rng, n),
                              kk = random_with_zeros(rng, n), e = random_with_zeros(rng, n);
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
    const std::vector<double> w = random_with_zeros(rng, n), b = random_with_zeros(rng, n),
                              d = random_with_zeros(rng, n), g = random_with_zeros(rng, n),
                              s0 = random_with_zeros(rng, n), x0 = random_with_zeros(rng, n);
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
