// The 2D transient on seed 000's Kelvin-Voigt soil with its rate term eta2 (soil_contact.h,
// docs/soil.md sections 1.2 and 8): the viscous unit force, creep under a held load with the
// soil's time constant eta2 / E2, the elastic limit eta2 -> 0, and the rolling losses.
#include <gtest/gtest.h>

#include <cmath>

#include "decay_metrics.h"
#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/ground_patch.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/transient/driver.h"
#include "modaltyre/transient/soil_contact.h"
#include "modaltyre/transient/transient.h"
#include "transient_models.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using test::model_with;

// The soil: E2 2 MPa over a 200 mm layer (ground_settings.h's defaults), elastic share 1.
const std::vector<std::string> kKelvinVoigt = {
    "ground.model=kelvin_voigt", "ground.kelvin_voigt.E2_MPa=2", "ground.kelvin_voigt.layer_mm=200",
    "ground.kelvin_voigt.elastic_share=1"};

// A rigid flat punch at a held pressure: the soil's surface is advanced exactly for a held
// pressure (soil_contact.h), so z(t) = z_inf (1 - exp(-t E2 / eta2)) to the series root's
// tolerance (1e-13 of g), whatever the steps.
constexpr double kPunchTol = 1e-9;
// Creep: the soil volume V = sum A_i z_i obeys E2 V + eta2 dV/dt = H F exactly under a held
// contact force F (every unit, loaded or not, follows E2 z + eta2 dz/dt = H p), so the sinkage
// approaches the static one as exp(-t E2 / eta2) up to the change of the pressure's shape as the
// contact grows (and the hub's bounce on the soil). The deepest point's fitted time constant at
// 5 mm units (the same at relative tolerance 1e-4 and 1e-7, 2163 and 3240 steps: not the
// integration): 0.83 of eta2 / E2 over [0.1, 0.5] s while the contact grows, 0.978 over
// [1, 1.5] s, 0.998 over [1.5, 2.2] s. The fit over [2 tau, 4 tau] is held to 3 % (the brief's
// "a few %").
constexpr double kCreepTimeConstantTol = 0.03;
// ... and ends at the static footprint on the same soil (the elastic law): after 5 time
// constants e^-5 = 0.7 % of the creep remains, and the fit's extrapolation is compared.
constexpr double kCreepLimitTol = 0.005;
// eta2 -> 0 (a time constant of 5 us, far below the ~1 ms steps) against eta2 = 0, sample by
// sample: the brief's 0.5 %.
constexpr double kElasticLimitTol = 0.005;
// The viscous unit force's derivative against a central difference (step 1e-6 of g).
constexpr double kKvDerivativeTol = 1e-5;
constexpr double kKvRootTol = 1e-10;

std::vector<std::string> kv_coarse(std::vector<std::string> extra = {}) {
  std::vector<std::string> o = {"contact.unit_length_mm=5", "contact.window_mm=300",
                                "transient.dynamic_max_order=16", "transient.output_step_ms=5",
                                "transient.relaxation=false"};
  o.insert(o.end(), kKelvinVoigt.begin(), kKelvinVoigt.end());
  o.insert(o.end(), extra.begin(), extra.end());
  return o;
}

TEST(KelvinVoigtSoil, TheViscousUnitForceIsTheSeriesRootOverTheStep) {
  const TransientModel M = model_with(kv_coarse({"ground.kelvin_voigt.eta2_kPa_s=50"}));
  const SoilContact soil(M, M.tyre.config.ground, M.tyre.config.tread.width_m, 0.1);
  EXPECT_NEAR(soil.time_constant_s(), 50e3 / 2e6, 1e-15);
  const int i = M.m / 2;
  const double A = soil.area_m2(i), k = M.k_contact(i);
  for (const double w : {0.0, 0.3, 0.9, 0.999}) {
    for (const double za : {0.0, 2e-3}) {
      for (const double g : {1e-3, 4e-3, 2e-2}) {
        double d = 0, depth = 0;
        const double f = soil.unit_force(i, g, za, &d, &depth, za, w);
        // The soil surface over the step: w z_a + (1 - w) Z_el(p), the tread spring on it.
        const double Zel = soil.law().sinkage_m(f / A, za);
        if (f == 0) {
          EXPECT_LE(g, w * za + (1 - w) * soil.law().rebound_depth_m(za) + 1e-15);
          continue;
        }
        EXPECT_NEAR(depth, w * za + (1 - w) * Zel, kKvRootTol * g);
        EXPECT_NEAR(f / k + depth, g, kKvRootTol * g);
        const double h = 1e-6 * g;
        double d1 = 0, z1 = 0;
        const double fp = soil.unit_force(i, g + h, za, &d1, &z1, za, w);
        const double fm = soil.unit_force(i, g - h, za, &d1, &z1, za, w);
        EXPECT_NEAR(d, (fp - fm) / (2 * h), kKvDerivativeTol * k);
      }
    }
  }
}

TEST(KelvinVoigtSoil, ARigidPunchCreepsWithEta2OverE2) {
  const TransientModel M = model_with(kv_coarse({"ground.kelvin_voigt.eta2_kPa_s=50"}));
  SoilContact soil(M, M.tyre.config.ground, M.tyre.config.tread.width_m, 0.1);
  const double tau = soil.time_constant_s(), p = 50e3, z_inf = p * 0.2 / 2e6;
  const int lo = M.m / 2 - 5, n = 11;
  soil.set_memory(Eigen::VectorXd::Zero(M.m), 0.0);
  std::vector<double> g(n, 0.0), f(n);
  double t = 0;
  for (const double h : {1e-4, 3e-3, 1e-2, 2e-2, 5e-3, 4e-2, 1e-1}) {
    t += h;
    // The punch: the penetration of every unit such that it carries p A_i (Newton on phi).
    for (int it = 0; it < 50; ++it) {
      f = g;
      soil.forces(t, lo, n, f.data());
      double worst = 0;
      for (int k = 0; k < n; ++k) {
        const double target = p * soil.area_m2(lo + k);
        const double d = soil.stiffness(lo + k);
        g[k] = d > 0 ? g[k] + (target - f[k]) / d : g[k] + 1e-3;
        worst = std::max(worst, std::abs(f[k] - target) / target);
      }
      if (worst < 1e-12) break;
    }
    for (int k = 0; k < n; ++k) {
      EXPECT_NEAR(f[k] / (p * soil.area_m2(lo + k)), 1.0, kPunchTol);
      EXPECT_NEAR(soil.depth(lo + k) / (z_inf * (1 - std::exp(-t / tau))), 1.0, kPunchTol) << t;
    }
    soil.accept(t, lo, lo + n - 1);
  }
}

TEST(KelvinVoigtSoil, AHeldLoadCreepsToTheStaticFootprintWithEta2OverE2) {
  // A 4 kN load in 40 ms (a step against tau = 0.5 s), held 2.5 s = 5 tau.
  const double tau = 1000e3 / 2e6;
  const TransientModel M = model_with(
      kv_coarse({"ground.kelvin_voigt.eta2_kPa_s=1000", "transient.load_hold.load_N=4000",
                 "transient.load_hold.ramp_rate_N_s=100000", "transient.load_hold.hold_s=2.5"}));
  const TransientResult r = run_transient(M, Scenario::load_hold);
  ASSERT_TRUE(r.ok()) << r.message;
  GroundPatchInput in;
  const FootprintResult s = solve_ground_patch(M.tyre, static_operator(M.tyre, 0.0),
                                               LoadCase{4000, 0}, M.tyre.config.ground, in);
  ASSERT_TRUE(s.ok()) << s.message;
  const double z_inf = s.soil_sinkage_m;
  // ln(z_inf - z) against t over [2 tau, 4 tau]: least-squares slope -1 / tau.
  double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
  for (const auto& x : r.samples) {
    if (x.t_s < 2 * tau || x.t_s > 4 * tau) continue;
    ASSERT_LT(x.soil_sinkage_m, z_inf);  // approaches from below
    const double y = std::log(z_inf - x.soil_sinkage_m);
    n += 1, st += x.t_s, sy += y, stt += x.t_s * x.t_s, sty += x.t_s * y;
  }
  ASSERT_GT(n, 100);
  const double slope = (n * sty - st * sy) / (n * stt - st * st);
  std::printf("creep: fitted time constant %.4f of eta2 / E2\n", -1.0 / slope / tau);
  EXPECT_NEAR(-1.0 / slope / tau, 1.0, kCreepTimeConstantTol);
  // The sinkage at the end, with the fit's remaining creep added, is the static footprint's.
  const auto& fin = r.samples.back();
  const double left = std::exp((sy + slope * (fin.t_s * n - st)) / n);
  EXPECT_NEAR((fin.soil_sinkage_m + left) / z_inf, 1.0, kCreepLimitTol);
  EXPECT_NEAR(fin.soil_sinkage_m / z_inf, 1.0, 2 * std::exp(-(fin.t_s - 0.04) / tau));
}

TEST(KelvinVoigtSoil, Eta2ToZeroIsTheElasticTransient) {
  const auto base =
      kv_coarse({"transient.load_hold.load_N=4000", "transient.load_hold.ramp_rate_N_s=20000",
                 "transient.load_hold.hold_s=0.3"});
  auto viscous = base;
  viscous.push_back("ground.kelvin_voigt.eta2_kPa_s=0.01");  // tau = 5 us
  const TransientResult a = run_transient(model_with(base), Scenario::load_hold);
  const TransientResult b = run_transient(model_with(viscous), Scenario::load_hold);
  ASSERT_TRUE(a.ok()) << a.message;
  ASSERT_TRUE(b.ok()) << b.message;
  ASSERT_EQ(a.samples.size(), b.samples.size());
  const double sink = a.samples.back().sinking_m, soil = a.samples.back().soil_sinkage_m;
  ASSERT_GT(soil, 1e-3);
  double worst_sink = 0, worst_soil = 0, worst_load = 0;
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    const auto &x = a.samples[k], &y = b.samples[k];
    worst_sink = std::max(worst_sink, std::abs(x.sinking_m - y.sinking_m));
    worst_soil = std::max(worst_soil, std::abs(x.soil_sinkage_m - y.soil_sinkage_m));
    worst_load = std::max(worst_load, std::abs(x.load_N - y.load_N));
  }
  std::printf("eta2 -> 0: worst sinking %.2e, soil sinkage %.2e, load %.2e (relative)\n",
              worst_sink / sink, worst_soil / soil, worst_load / 4000);
  EXPECT_LT(worst_sink / sink, kElasticLimitTol);
  EXPECT_LT(worst_soil / soil, kElasticLimitTol);
  EXPECT_LT(worst_load / 4000, kElasticLimitTol);
}

double rolling_compaction_resistance_N(double eta2_kPa_s, double speed_km_h) {
  const TransientModel M =
      model_with(kv_coarse({"ground.kelvin_voigt.eta2_kPa_s=" + std::to_string(eta2_kPa_s),
                            "transient.rolling.load_N=3000",
                            "transient.rolling.speed_km_h=" + std::to_string(speed_km_h),
                            "transient.rolling.ramp_s=0.5", "transient.rolling.duration_s=1.5"}));
  const TransientResult r = run_transient(M, Scenario::rolling);
  EXPECT_TRUE(r.ok()) << r.message;
  const double T = r.simulated_s;
  return mean_over(r, T - 0.4, T, [](auto& x) { return x.soil_resistance_N; });
}

TEST(KelvinVoigtSoil, RollingOnAViscousSoilDissipatesMoreWithSpeed) {
  // The elastic soil gives back on the rear what it took on the front (no compaction
  // resistance but the tyre's own asymmetry); the viscous one lags: deeper behind the centre.
  const double elastic = rolling_compaction_resistance_N(0, 2);
  const double r1 = rolling_compaction_resistance_N(50, 1);
  const double r2 = rolling_compaction_resistance_N(50, 2);
  const double r4 = rolling_compaction_resistance_N(50, 4);
  std::printf(
      "compaction resistance: elastic %.4f N; eta2 50 kPa s: %.3f, %.3f, %.3f N at 1, 2, 4 km/h\n",
      elastic, r1, r2, r4);
  EXPECT_LT(std::abs(elastic), 1.0);  // ~1e-3 N of 3 kN
  EXPECT_GT(r1, std::abs(elastic) + 10.0);
  EXPECT_GT(r2, r1);
  EXPECT_GT(r4, r2);
  // At low speed the viscous stress eta2 V dz/dx / H, hence the loss, grows about linearly.
  EXPECT_GT(r2 / r1, 1.5);
}

TEST(KelvinVoigtSoil, The3DPatchRefusesEta2NamingTheKey) {
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
  auto o = kKelvinVoigt;
  o.push_back("ground.kelvin_voigt.eta2_kPa_s=50");
  o.push_back("transient.load_hold.hold_s=0.1");
  const TransientModel M = build_transient_model(build_tyre_model(load_tyre_config(config, o)));
  try {
    run_transient_3d(M, Scenario::load_hold);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("eta2_kPa_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace modaltyre::transient
