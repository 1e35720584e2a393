// The ground's normal and shear laws against their definitions (docs/soil.md sections 1-2).
#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/ground/bekker_wong.h"
#include "modaltyre/ground/kelvin_voigt_soil.h"
#include "modaltyre/ground/shear.h"
#include "modaltyre/ground/soil_state.h"

namespace modaltyre::ground {
namespace {

// Round-off of pow/inverse pairs in double precision.
constexpr double kRoundOff = 1e-12;

BekkerParams lete_sand() {  // Wong, Theory of Ground Vehicles, 4th ed., Table 2.3
  BekkerParams p;
  p.n = 0.79, p.k_c = 102, p.k_phi = 5301;
  return p;
}

TEST(BekkerWong, LoadingIsBekkersLawInWongsUnits) {
  const BekkerWong law(lete_sand(), 0.15);
  const double z = 0.03;
  // p [kPa] = (k_c / b + k_phi) z^n with z in m.
  const double expected_kPa = (102 / 0.15 + 5301) * std::pow(z, 0.79);
  EXPECT_NEAR(law.loading_Pa(z), expected_kPa * 1e3, kRoundOff * expected_kPa * 1e3);
  EXPECT_NEAR(law.loading_sinkage_m(law.loading_Pa(z)), z, kRoundOff * z);
  EXPECT_EQ(law.loading_Pa(0), 0);
}

TEST(BekkerWong, WithoutUnloadingTheSoilDoesNotRebound) {
  const BekkerWong law(lete_sand(), 0.15);
  EXPECT_TRUE(law.rigid_plastic());
  EXPECT_EQ(law.rebound_depth_m(0.04), 0.04);
  EXPECT_EQ(law.unloading_Pa(0.039, 0.04), 0.0);
  // Reloading: no sinkage until the pressure exceeds the previous maximum.
  const double pmax = law.loading_Pa(0.04);
  EXPECT_EQ(law.sinkage_m(0.5 * pmax, 0.04), 0.04);
  EXPECT_GT(law.sinkage_m(1.1 * pmax, 0.04), 0.04);
}

TEST(BekkerWong, WongsUnloadingLineMeetsTheVirginCurveAndRebounds) {
  BekkerParams p = lete_sand();
  p.unloading = WongUnloading{1000, 5e6};
  const BekkerWong law(p, 0.15);
  const double zmax = 0.04, pmax = law.loading_Pa(zmax);
  const double ku = (1000 + 5e6 * zmax) * 1e3;  // k_u = k0 + Au z_max, kN/m^3 -> Pa/m
  ASSERT_GT(ku, pmax / zmax);                   // above the secant: Wong's line as it is
  EXPECT_NEAR(law.unloading_stiffness_Pa_m(zmax), ku, kRoundOff * ku);
  EXPECT_NEAR(law.rebound_depth_m(zmax), zmax - pmax / ku, kRoundOff);
  EXPECT_NEAR(law.pressure_Pa(zmax - 1e-3, zmax), pmax - ku * 1e-3, kRoundOff * pmax);
  // The inverse is continuous and non-decreasing across the branch point.
  double last = law.sinkage_m(0, zmax);
  for (double f = 0; f <= 1.5; f += 0.01) {
    const double z = law.sinkage_m(f * pmax, zmax);
    EXPECT_GE(z, last - kRoundOff);
    EXPECT_LE(std::abs(z - last), 0.02 * zmax) << "jump at p = " << f << " p_max";
    last = z;
  }
}

TEST(BekkerWong, ASoftUnloadingLineIsFlooredAtTheSecantSoTheSurfaceNeverRisesAboveItsStart) {
  BekkerParams p = lete_sand();
  p.unloading = WongUnloading{0, 1e3};  // k_u far below p_max / z_max
  const BekkerWong law(p, 0.15);
  const double zmax = 0.02, pmax = law.loading_Pa(zmax);
  EXPECT_NEAR(law.unloading_stiffness_Pa_m(zmax), pmax / zmax, kRoundOff * pmax / zmax);
  EXPECT_NEAR(law.rebound_depth_m(zmax), 0.0, kRoundOff);
  // Below the virgin curve everywhere (n < 1: the curve is concave, the secant under it).
  for (double z = 0.001; z < zmax; z += 0.001)
    EXPECT_LT(law.unloading_Pa(z, zmax), law.loading_Pa(z));
}

TEST(KelvinVoigtSoil, FullyElasticShareIsTheWinklerLayerOfSoilCompliance) {
  KelvinVoigtParams p;
  p.E2_MPa = 3, p.layer_mm = 250, p.elastic_share = 1;
  const KelvinVoigtSoil law(p);
  const double pressure = 200e3;
  EXPECT_NEAR(law.loading_sinkage_m(pressure), pressure * 0.25 / 3e6, kRoundOff);
  EXPECT_EQ(law.rebound_depth_m(0.02), 0.0);
}

TEST(KelvinVoigtSoil, PlasticShareStaysAsARutAndTheBranchesMeet) {
  KelvinVoigtParams p;
  p.E2_MPa = 2, p.layer_mm = 200, p.elastic_share = 0.4;
  const KelvinVoigtSoil law(p);
  const double zmax = 0.03;
  EXPECT_NEAR(law.rebound_depth_m(zmax), 0.6 * zmax, kRoundOff);  // seed 000 eq. 24: h_E = k_E h_G
  EXPECT_NEAR(law.unloading_Pa(zmax * (1 - 1e-12), zmax), law.loading_Pa(zmax),
              1e-9 * law.loading_Pa(zmax));
}

TEST(JanosiHanamoto, ShearStressFollowsTheExponentialLaw) {
  const JanosiHanamoto law({1.3, 31.1, 12});
  const double sigma = 50e3;
  const double strength = 1.3e3 + sigma * std::tan(31.1 * M_PI / 180);
  EXPECT_NEAR(law.strength_Pa(sigma), strength, kRoundOff * strength);
  EXPECT_NEAR(law.stress_Pa(sigma, 0.012), strength * (1 - std::exp(-1.0)), 1e-9 * strength);
  EXPECT_NEAR(law.stress_Pa(sigma, 1.0), strength, 1e-9 * strength);
  EXPECT_NEAR(law.stress_Pa(sigma, -0.012), -strength * (1 - std::exp(-1.0)), 1e-9 * strength);
  // Advancing in steps gives the law at the total displacement (no history).
  ShearPoint p;
  double tau = 0;
  for (int i = 0; i < 10; ++i) tau = law.advance(p, sigma, 0.002);
  EXPECT_NEAR(tau, law.stress_Pa(sigma, 0.02), 1e-9 * strength);
}

TEST(CoulombFriction, SticksOnTheTreadSpringThenSlidesAtMuSigma) {
  const double k = 2.5e8, mu = 0.8, sigma = 200e3;  // tread G / h, a dry road
  const CoulombFriction law(mu, k);
  ShearPoint p;
  EXPECT_NEAR(law.advance(p, sigma, 1e-4), k * 1e-4, 1e-6);
  EXPECT_FALSE(p.sliding);
  const double tau = law.advance(p, sigma, 1e-2);  // far beyond mu sigma / k = 0.64 mm
  EXPECT_TRUE(p.sliding);
  EXPECT_NEAR(tau, mu * sigma, 1e-9 * mu * sigma);
  // A falling normal stress lets the spring slide back to the new limit.
  EXPECT_NEAR(law.advance(p, 0.5 * sigma, 0), 0.5 * mu * sigma, 1e-9 * mu * sigma);
  // Reversal: the spring unloads elastically first (stick).
  EXPECT_NEAR(law.advance(p, 0.5 * sigma, -1e-4), 0.5 * mu * sigma - k * 1e-4, 1e-6);
  EXPECT_FALSE(p.sliding);
}

TEST(SoilState, RemembersTheDeepestSinkage) {
  SoilState s(3);
  s.record(1, 0.02);
  s.record(1, 0.01);
  EXPECT_EQ(s.z_max_m(1), 0.02);
  EXPECT_EQ(s.deepest_m(), 0.02);
  const BekkerWong law(lete_sand(), 0.15);
  EXPECT_EQ(s.deepest_rut_m(law), 0.02);  // rigid-plastic: the rut is z_max
}

}  // namespace
}  // namespace modaltyre::ground

namespace modaltyre::ground {
namespace {

// The closed-form works of the laws against the numerical integral of their sinkage (the base
// class's Gauss-Legendre rule): virgin, elastic branch (clamped and not), rigid-plastic branch.
class NumericWork final : public PressureSinkage {
 public:
  explicit NumericWork(const PressureSinkage& law) : law_(law) {}
  double loading_Pa(double z) const override { return law_.loading_Pa(z); }
  double loading_sinkage_m(double p) const override { return law_.loading_sinkage_m(p); }
  double unloading_Pa(double z, double zm) const override { return law_.unloading_Pa(z, zm); }
  double unloading_sinkage_m(double p, double zm) const override {
    return law_.unloading_sinkage_m(p, zm);
  }
  double rebound_depth_m(double zm) const override { return law_.rebound_depth_m(zm); }
  bool rigid_plastic() const override { return law_.rigid_plastic(); }

 private:
  const PressureSinkage& law_;
};

TEST(SoilWork, ClosedFormsEqualTheIntegralOfTheSinkage) {
  constexpr double kQuadrature = 1e-8;
  BekkerParams rigid_plastic = lete_sand(), elastic = lete_sand(), soft = lete_sand();
  elastic.unloading = WongUnloading{1000, 5e6};
  soft.unloading = WongUnloading{0, 1e3};  // the secant: clamped at the surface
  const BekkerWong a(rigid_plastic, 0.15), b(elastic, 0.15), c(soft, 0.15);
  KelvinVoigtParams kvp;
  kvp.elastic_share = 0.4;
  const KelvinVoigtSoil kv(kvp);
  for (const PressureSinkage* law :
       std::initializer_list<const PressureSinkage*>{&a, &b, &c, &kv}) {
    const NumericWork numeric(*law);
    for (double zmax : {0.0, 0.01, 0.03}) {
      const double pmax = law->loading_Pa(std::max(zmax, 0.02));
      for (double f : {0.1, 0.5, 0.99, 1.5}) {
        const double w = law->work_J_m2(f * pmax, zmax), ref = numeric.work_J_m2(f * pmax, zmax);
        EXPECT_NEAR(w, ref, kQuadrature * std::abs(ref) + 1e-12) << zmax << " " << f;
      }
    }
  }
}

}  // namespace
}  // namespace modaltyre::ground

namespace modaltyre::ground {
namespace {

TEST(SoilCompliance, ClosedFormEqualsTheNumericalDerivative) {
  BekkerParams rigid_plastic = lete_sand(), elastic = lete_sand();
  elastic.unloading = WongUnloading{1000, 5e6};
  for (const BekkerParams& bp : {rigid_plastic, elastic}) {
    const BekkerWong law(bp, 0.15);
    const NumericWork numeric(law);  // the base class's numerical derivative
    for (double zmax : {0.0, 0.02}) {
      const double pmax = law.loading_Pa(0.03);
      for (double f : {0.05, 0.3, 0.9, 1.2}) {
        const double a = law.compliance_m_per_Pa(f * pmax, zmax);
        const double b = numeric.compliance_m_per_Pa(f * pmax, zmax);
        EXPECT_NEAR(a, b, 1e-5 * b + 1e-300) << zmax << " " << f;
      }
    }
  }
}

// The virgin curve's sinkage and slope in one evaluation (the 3D patch's cell roots): Bekker-Wong's
// closed form and the base class's default (NumericWork: its numerical derivative) against z(p)
// and the virgin compliance.
TEST(SoilCompliance, TheVirginSinkageAndSlopeAreTheLawsOwn) {
  const BekkerWong law(lete_sand(), 0.15);
  const NumericWork numeric(law);
  for (double z : {1e-4, 0.01, 0.05}) {
    const double p = law.loading_Pa(z);
    double a = 0, b = 0;
    EXPECT_NEAR(law.virgin_sinkage_m(p, a), z, kRoundOff * z);
    EXPECT_NEAR(a, law.compliance_m_per_Pa(p, 0.0), kRoundOff * a);
    EXPECT_NEAR(numeric.virgin_sinkage_m(p, b), z, kRoundOff * z);
    EXPECT_NEAR(b, a, 1e-5 * a);
  }
}

}  // namespace
}  // namespace modaltyre::ground
