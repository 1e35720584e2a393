// The Kelvin-Voigt soil's rate term under the rolling flexible tyre (contact/soil_rate_term.h,
// docs/soil.md section 9.1): the unit law is the exact relaxation over a ground point's passage,
// off it is the elastic rolling bit for bit (2D and 3D patch), a very stiff tyre rolls as the
// rigid wheel of section 3.2, the rate term converges with the unit length, and the soil stiffens
// and resists more with speed and viscosity.
#include "modaltyre/contact/soil_rate_term.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/ground/kelvin_voigt_soil.h"

namespace modaltyre::contact {
namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;

// Section 3.2's soil: E2 2 MPa over H 200 mm, k_E as given; frictionless unless `shear`.
std::vector<std::string> rate_soil(double k_E, double eta2_kPa_s, bool shear = false) {
  return {"ground.model=kelvin_voigt",
          "ground.kelvin_voigt.E2_MPa=2",
          "ground.kelvin_voigt.layer_mm=200",
          "ground.kelvin_voigt.elastic_share=" + std::to_string(k_E),
          "ground.kelvin_voigt.eta2_kPa_s=" + std::to_string(eta2_kPa_s),
          std::string("ground.kelvin_voigt.cohesion_kPa=") + (shear ? "1" : "0"),
          std::string("ground.kelvin_voigt.friction_angle_deg=") + (shear ? "30" : "0"),
          "ground.kelvin_voigt.shear_modulus_K_mm=25"};
}

std::vector<std::string> rate_plus(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<TractionResult> rate_roll(const std::string& config,
                                      const std::vector<std::string>& sets, double V_km_h,
                                      std::vector<double> slips = {0.0}, bool rigid = false) {
  const TyreConfig c = load_tyre_config(config, sets);
  const TyreModel m = build_tyre_model(c);
  TractionOptions o;
  o.rigid = rigid;
  o.speed_m_per_s = V_km_h / 3.6;
  std::vector<TractionCase> cases;
  for (double s : slips) cases.push_back({3000, s});
  std::vector<TractionResult> r = steady_traction(m, c.ground, cases, o);
  for (const TractionResult& x : r) EXPECT_TRUE(x.ok()) << x.message;
  return r;
}

void rate_expect_identical(const TractionResult& a, const TractionResult& b) {
  EXPECT_EQ(a.soil_sinkage_m, b.soil_sinkage_m);
  EXPECT_EQ(a.sinking_m, b.sinking_m);
  EXPECT_EQ(a.drawbar_pull_N, b.drawbar_pull_N);
  EXPECT_EQ(a.motion_resistance_N, b.motion_resistance_N);
  EXPECT_EQ(a.torque_Nm, b.torque_Nm);
  EXPECT_EQ(a.contact_length_m, b.contact_length_m);
  EXPECT_EQ(a.exit_angle_rad, b.exit_angle_rad);
  EXPECT_EQ(a.iterations, b.iterations);
}

// Z_i(p) = w z_a + (1 - w) Z_el(p) is tau dz/dt + z = Z_el(p) integrated over the passage h from
// z_a (both branches of the law: docs/soil.md 1.2): against RK4 on 10^4 steps, from a shallower
// (loading) and a deeper (recovering) arrival.
TEST(SoilRateTerm, TheUnitLawIsTheRelaxationOverAGroundPointsPassage) {
  ground::KelvinVoigtParams kv;
  kv.eta2_kPa_s = 50, kv.elastic_share = 0.7;
  const ground::KelvinVoigtSoil law(kv);
  const double tau = 50e3 / 2e6, V = 5 / 3.6, R0 = 0.3;
  const std::vector<double> theta = {-0.002, 0.0, 0.002};  // x = R0 sin(theta)
  SoilRate rate;
  rate.weight.resize(3), rate.start_m.resize(3);
  const std::vector<double> surface = {0.012, 0.010, 0.011};
  soil_rate_column(rate, theta, R0, tau, V, 0.004, 0, 1, surface);
  EXPECT_EQ(rate.start_m[2], 0.004);  // the front point: the surface ahead of the patch
  EXPECT_EQ(rate.start_m[1], surface[2]);
  EXPECT_EQ(rate.start_m[0], surface[1]);
  const double z_max = 0.015;
  for (double p : {0.0, 20e3, 60e3}) {
    const double h = R0 * (std::sin(theta[1]) - std::sin(theta[0])) / V;
    const double u = law.sinkage_m(p, z_max);
    double z = rate.start_m[0];
    const int n = 10000;
    auto dz = [&](double zz) { return (u - zz) / tau; };
    for (int k = 0; k < n; ++k) {
      const double dt = h / n, k1 = dz(z), k2 = dz(z + dt * k1 / 2), k3 = dz(z + dt * k2 / 2);
      z += dt / 6 * (k1 + 2 * k2 + 2 * k3 + dz(z + dt * k3));
    }
    EXPECT_NEAR(rate.sinkage_m(0, u), z, 1e-12) << p;
  }
  // Off: no rate term, the elastic law untouched.
  const SoilRate off;
  EXPECT_EQ(off.sinkage_m(0, 0.0123), 0.0123);
  EXPECT_EQ(off.scale(0), 1.0);
  EXPECT_EQ(off.work_J_m2(0, 5e4, 7.5), 7.5);
  ground::GroundSettings g;
  g.model = ground::GroundModel::kelvin_voigt;
  g.kelvin_voigt = kv;
  EXPECT_DOUBLE_EQ(soil_rate_time_s(g, V), tau);
  EXPECT_EQ(soil_rate_time_s(g, 0), 0.0);
  g.kelvin_voigt.eta2_kPa_s = 0;
  EXPECT_EQ(soil_rate_time_s(g, V), 0.0);
}

// Off (eta2 = 0 at 5 km/h, or eta2 50 kPa s standing) the rolling takes the elastic law's code
// path: the same result bit for bit, on the 2D patch and the 3D patch (the JSON of `traction`
// was also compared byte for byte with the code before the rate term).
TEST(RollingOnAViscousSoil, OffIsTheElasticRollingBitForBit) {
  for (const std::string& config : {kConfig2d, kConfig3d}) {
    const std::vector<std::string> mesh = {"contact.unit_length_mm=2",
                                           "footprint_3d.lateral_cell_mm=10"};
    const std::vector<std::string> m =
        config == kConfig2d ? std::vector<std::string>{mesh[0]} : mesh;
    const auto elastic = rate_roll(config, rate_plus(m, rate_soil(0.7, 0, true)), 5, {0.0, 0.2});
    const auto standing = rate_roll(config, rate_plus(m, rate_soil(0.7, 50, true)), 0, {0.0, 0.2});
    const auto still = rate_roll(config, rate_plus(m, rate_soil(0.7, 0, true)), 0, {0.0, 0.2});
    ASSERT_EQ(elastic.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      rate_expect_identical(elastic[k], standing[k]);
      rate_expect_identical(elastic[k], still[k]);
    }
  }
}

// A tyre a thousand times stiffer than the SF-350 (its contour the undeformed circle) rolls as
// the rigid wheel of its radius and width (section 3.2's integrals: V tan(theta) is -V dz/dx of
// the circle): the sinkage within 1e-3 (the stiff tyre still deflects ~0.1 % of the sinkage;
// measured 2e-4 to 6e-4), the compaction resistance with a first-order error of the one-sided
// rate (one unit's lag at the entry's jump): -2.0 / -1.1 % (k_E 1) and -1.7 / -0.8 % (k_E 0.7)
// on 1 / 0.5 mm units, halving with the unit, Richardson's extrapolation within 0.3 %.
TEST(RollingOnAViscousSoil, AVeryStiffTyreRollsAsTheRigidWheel) {
  const std::vector<std::string> stiff = {"modal.compliance_scale=0.001",
                                          "tread.modulus_MPa=10000"};
  for (double k_E : {1.0, 0.7}) {
    const auto soil = rate_soil(k_E, 50);
    const TractionResult wheel =
        rate_roll(kConfig2d, rate_plus({"contact.unit_length_mm=1"}, soil), 5, {0.0}, true)[0];
    std::vector<double> Rc;
    for (const char* u : {"contact.unit_length_mm=1", "contact.unit_length_mm=0.5"}) {
      const TractionResult t = rate_roll(kConfig2d, rate_plus(rate_plus(stiff, {u}), soil), 5)[0];
      EXPECT_NEAR(t.soil_sinkage_m, wheel.soil_sinkage_m, 1e-3 * wheel.soil_sinkage_m) << u;
      EXPECT_NEAR(t.exit_angle_rad, wheel.exit_angle_rad, 0.2 * M_PI / 180) << u;
      Rc.push_back(t.compaction_resistance_N);
    }
    const double R = wheel.compaction_resistance_N;
    EXPECT_GT(R, 0.1 * 3000 * 0.5);  // far above the elastic wheel's 0 (k_E 1) or 74 N (0.7)
    EXPECT_LT(std::abs(Rc[1] - R), 0.015 * R) << k_E;
    const double ratio = (Rc[0] - R) / (Rc[1] - R);
    EXPECT_GT(ratio, 1.6) << k_E;
    EXPECT_LT(ratio, 2.5) << k_E;
    EXPECT_NEAR(2 * Rc[1] - Rc[0], R, 0.003 * R) << k_E;
  }
}

// The flexible SF-350 (2D config, frictionless, k_E 0.7, eta2 50 kPa s, 5 km/h): the rate term's
// compaction resistance converges at first order in the unit length (2, 1, 0.5 mm).
TEST(RollingOnAViscousSoil, TheRateTermConvergesWithTheUnitLength) {
  std::vector<double> Rc, z;
  for (const char* u :
       {"contact.unit_length_mm=2", "contact.unit_length_mm=1", "contact.unit_length_mm=0.5"}) {
    const TractionResult t = rate_roll(kConfig2d, rate_plus({u}, rate_soil(0.7, 50)), 5)[0];
    Rc.push_back(t.compaction_resistance_N);
    z.push_back(t.soil_sinkage_m);
  }
  const double d1 = Rc[0] - Rc[1], d2 = Rc[1] - Rc[2];
  EXPECT_GT(d1 / d2, 1.5);
  EXPECT_LT(d1 / d2, 2.7);
  EXPECT_LT(std::abs(d2), 0.02 * Rc[2]);
  EXPECT_LT(std::abs(z[1] - z[2]), 0.005 * z[2]);
}

// Trends on the flexible tyre (2D config, 1 mm units, with friction, s = 0.1): sinkage falls and
// motion resistance rises with V (1, 5, 20 km/h) and with eta2 (10, 50, 200 kPa s at 5 km/h); the
// rate term depends on eta2 and V only through lambda = eta2 V / E2; at small lambda (2-8 mm,
// against a contact of ~190 mm, on 0.5 mm units: lambda well above the unit) the resistance it
// adds is linear in eta2 V within 10 % (measured: 15.6, 32.5, 64.6 N; 122.0 N at 16 mm, the
// growth slowing as the soil stiffens).
TEST(RollingOnAViscousSoil, TheSoilStiffensAndResistsMoreWithSpeedAndViscosity) {
  auto at = [&](double eta2, double V, const char* unit = "contact.unit_length_mm=1") {
    return rate_roll(kConfig2d, rate_plus({unit}, rate_soil(0.7, eta2, true)), V, {0.1})[0];
  };
  const TractionResult v1 = at(50, 1), v5 = at(50, 5), v20 = at(50, 20);
  EXPECT_GT(v1.soil_sinkage_m, v5.soil_sinkage_m);
  EXPECT_GT(v5.soil_sinkage_m, v20.soil_sinkage_m);
  EXPECT_LT(v1.compaction_resistance_N, v5.compaction_resistance_N);
  EXPECT_LT(v5.compaction_resistance_N, v20.compaction_resistance_N);
  const TractionResult e10 = at(10, 5), e200 = at(200, 5);
  EXPECT_GT(e10.soil_sinkage_m, v5.soil_sinkage_m);
  EXPECT_GT(v5.soil_sinkage_m, e200.soil_sinkage_m);
  EXPECT_LT(e10.compaction_resistance_N, v5.compaction_resistance_N);
  EXPECT_LT(v5.compaction_resistance_N, e200.compaction_resistance_N);
  EXPECT_NEAR(at(250, 1).compaction_resistance_N, v5.compaction_resistance_N,
              1e-6 * v5.compaction_resistance_N);
  // lambda = 2, 4, 8 mm: eta2 50 kPa s at 0.288, 0.576, 1.152 km/h.
  const char* fine = "contact.unit_length_mm=0.5";
  const double R0 = at(0, 0, fine).compaction_resistance_N;
  std::vector<double> added;
  for (double V : {0.288, 0.576, 1.152})
    added.push_back(at(50, V, fine).compaction_resistance_N - R0);
  EXPECT_GT(added[0], 0);
  EXPECT_NEAR(added[1] / added[0], 2, 0.2);
  EXPECT_NEAR(added[2] / added[1], 2, 0.2);
}

}  // namespace
}  // namespace modaltyre::contact
