// The 3D patch's soil section law (contact/src/patch3d_soil.h, docs/soil.md section 9 "What the
// soil law keeps"): a cell asked again at the compression its last solve ended on returns that
// solve's root and slope, and never a stale root after another compression; approach() finds the
// section's force in any order of forces (its bracket answered from approaches it already
// solved), as a fresh section law does.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../contact/src/patch3d_soil.h"
#include "modaltyre/ground/bekker_wong.h"

namespace {

using modaltyre::contact::detail::SoilSections;
using modaltyre::ground::BekkerParams;
using modaltyre::ground::BekkerWong;
using modaltyre::ground::WongUnloading;

// LETE sand, Wong, Theory of Ground Vehicles, 4th ed., 2008, Table 2.3 (configs/soils/); b the
// default tread's 150 mm. `unloading`: Wong's line with the docs' A_u 5e5 kN/m^4 (soil.md 9).
BekkerWong lete_sand(bool unloading) {
  BekkerParams p;
  p.n = 0.79, p.k_c = 102, p.k_phi = 5301;
  if (unloading) p.unloading = WongUnloading{0, 5e5};
  return BekkerWong(p, 0.15);
}

// Three sections of 5 x 4 mm cells (8 mm tread of 3 MPa: t = h / (E A) = 1.33e-4 m/N, the two
// outer ones softer), four column classes of two columns on a crown dropping 0-1.8 mm; memory
// 0 (virgin) or a rut of 4 mm under every second cell.
struct Case {
  std::vector<double> t = {1.6e-4, 1.33e-4, 1.5e-4};
  std::vector<double> z = {0.0, 0.2e-3, 0.8e-3, 1.8e-3};
  std::vector<double> w = {2, 2, 2, 2};
  std::vector<double> area = {2e-5, 2e-5, 2e-5};
  std::vector<double> zmax(bool memory) const {
    std::vector<double> m(t.size() * z.size(), 0.0);
    for (std::size_t a = 0; memory && a < m.size(); a += 2) m[a] = 4e-3;
    return m;
  }
};

// The cell's own equation t f + Z(f / A; z_max) = e (cell() above the rut, off the
// rigid-plastic branch), relative to e.
double residual(const BekkerWong& law, const Case& c, const SoilSections& s, int i, int k, double e,
                double f) {
  return (c.t[i] * f + law.sinkage_m(f / c.area[i], s.memory(i, k)) - e) / e;
}

TEST(SoilSections, ACellAskedAgainReturnsItsSolveAndNeverAStaleRoot) {
  const Case c;
  for (const bool unloading : {false, true}) {
    for (const bool memory : {false, true}) {
      const BekkerWong law = lete_sand(unloading);
      const SoilSections s(c.t, c.z, c.w, law, c.area, c.zmax(memory));
      for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 4; ++k) {
          // Compressions well beyond the memory (the virgin curve) and between two of them.
          const double e1 = 0.02, e2 = 0.035;
          double d1 = 0, d1b = 0, d2 = 0;
          const double f1 = s.cell(i, k, e1, &d1);
          const double f2 = s.cell(i, k, e2, &d2);
          const double f1b = s.cell(i, k, e1, &d1b);
          ASSERT_GT(f1, 0);
          EXPECT_LT(std::abs(residual(law, c, s, i, k, e1, f1)), 1e-12);
          EXPECT_LT(std::abs(residual(law, c, s, i, k, e2, f2)), 1e-12);
          // After e2 the cell's memory of e1 is gone: a solve, not f2 (stale).
          EXPECT_LT(std::abs(residual(law, c, s, i, k, e1, f1b)), 1e-12);
          // Asked again at once: the same root and slope bit for bit.
          double d1c = 0;
          EXPECT_EQ(s.cell(i, k, e1, &d1c), f1b);
          EXPECT_EQ(d1c, d1b);
          // The repeated slope is df/de (central difference, the virgin curve is smooth there).
          const double h = 1e-6 * e1;
          const double fd = (s.cell(i, k, e1 + h) - s.cell(i, k, e1 - h)) / (2 * h);
          EXPECT_NEAR(d1c, fd, 1e-5 * fd);
          // Without a derivative asked, the same force.
          EXPECT_EQ(s.cell(i, k, e1), s.cell(i, k, e1));
        }
      }
    }
  }
}

TEST(SoilSections, TheApproachCarriesItsForceInAnyOrderAsAFreshLawFindsIt) {
  const Case c;
  // Rising, falling and repeated forces: each approach() meets known approaches above and below.
  const std::vector<double> forces = {5, 40, 2, 150, 40, 40, 300, 1, 150};  // N
  for (const bool unloading : {false, true}) {
    for (const bool memory : {false, true}) {
      const BekkerWong law = lete_sand(unloading);
      const SoilSections warm(c.t, c.z, c.w, law, c.area, c.zmax(memory));
      for (int i = 0; i < 3; ++i) {
        for (const double F : forces) {
          const double d = warm.approach(i, F);
          EXPECT_NEAR(warm.section(i, d), F, 1e-10 * F) << "section " << i << ", F " << F;
          const SoilSections fresh(c.t, c.z, c.w, law, c.area, c.zmax(memory));
          EXPECT_NEAR(fresh.approach(i, F), d, 1e-9 * d) << "section " << i << ", F " << F;
        }
      }
    }
  }
}

}  // namespace
