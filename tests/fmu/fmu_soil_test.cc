// The FMU on soil (issue 46 item 3) through its fmi2 functions: `modaltyre fmu CONFIG --ground
// SOIL.yaml` packs the tyre on LETE sand (Wong's Table 2.3), configs/sf350_2d_table3.yaml (the
// 2D transient), 1 ms communication steps. The press against `footprint --ground`, free rolling
// against `traction` at its free-rolling slip, braking against the soil's shear strength, the
// soil's keys as parameters, terrain_height as the undisturbed surface; export refusals.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>

#include "fmu_host.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/fmu/package.h"

namespace modaltyre::fmu::test {
namespace {

const std::string kSandTyreConfig =
    std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
const std::string kSandSoil = std::string(MODALTYRE_SOURCE_DIR) + "/configs/soils/lete_sand.yaml";
constexpr double kSandLoad_N = 4000, kSandStep_s = 1e-3;

const FmuFolder& sand_fmu() {
  static const std::string folder = pack_and_unzip(kSandTyreConfig, {}, kSandSoil);
  static const FmuFolder fmu(folder);
  return fmu;
}

/// The same without the tread's relaxation (its glassy spring while loaded fast): traction's
/// steady rolling is quasi-static with the relaxed tread.
const FmuFolder& sand_fmu_relaxed() {
  static const std::string folder =
      pack_and_unzip(kSandTyreConfig, {"transient.relaxation=false"}, kSandSoil);
  static const FmuFolder fmu(folder);
  return fmu;
}

/// The tyre model on the sand, as `footprint --ground` and `traction --ground` build it.
const contact::TyreModel& sand_model() {
  static const contact::TyreModel m = [] {
    contact::TyreConfig c = contact::load_tyre_config(kSandTyreConfig);
    c.ground = ground::load_ground_file(kSandSoil);
    return contact::build_tyre_model(c);
  }();
  return m;
}

double sand_R0() { return sand_model().config.outer_radius_m; }

/// `footprint --ground`'s sinking at the load [m].
double footprint_sinking(double load) {
  const contact::Prediction p =
      contact::predict(sand_model(), sand_model().config.default_conditions(load));
  EXPECT_TRUE(p.ok());
  return p.sinking_mm * 1e-3;
}

// Issue 46: the press within 1 % of footprint --ground at the same axle position. Pressed in
// 2 s (13 mm/s) and held 0.5 s; faster presses leave the rigid-plastic sand pressed deeper by
// the glassy tread (docs/soil.md section 8): 50 ms gives -0.9 % (docs/fmu.md).
constexpr double kSandPressTol = 0.01;

TEST(FmuSoil, APressSettlesToTheFootprintOnTheSandAtTheSameAxlePosition) {
  const double delta = footprint_sinking(kSandLoad_N);
  FmuInstance f(sand_fmu());
  ASSERT_TRUE(f.ok());
  ASSERT_EQ(f.initialize(), fmi2OK);
  const double ramp = 2.0;
  for (int k = 0; k < 2500; ++k) {
    const double t = k * kSandStep_s;
    f.set("wheel_state.pos.z", sand_R0() - delta * std::min(t / ramp, 1.0));
    f.set("wheel_state.lin_vel.z", t < ramp - 1e-12 ? -delta / ramp : 0.0);
    ASSERT_EQ(f.step(kSandStep_s), fmi2OK) << f.messages().back();
  }
  const double fz = f.get("wheel_load.force.z");
  std::cout << "press onto LETE sand to footprint --ground's " << delta * 1e3 << " mm: F_z " << fz
            << " N, soil sinkage " << f.get("soil.sinkage") * 1e3 << " mm, tyre deflection "
            << f.get("tyre.deflection") * 1e3 << " mm\n";
  EXPECT_NEAR(fz / kSandLoad_N, 1.0, kSandPressTol);
  // The sinking is the soil's and the tyre's.
  EXPECT_NEAR(f.get("soil.sinkage") + f.get("tyre.deflection"), delta, 1e-9);
  EXPECT_GT(f.get("soil.sinkage"), 0.5 * delta);
  EXPECT_NEAR(f.get("wheel_load.force.x"), 0, 1e-6 * kSandLoad_N);
}

/// A hub of 20 kg under kSandLoad_N on the sand, spun freely or at a prescribed spin, at `speed`
/// after a smoothstep ramp of 0.5 s; means over the last 0.2 s of each phase. The free wheel's
/// inertia is 50 kg m^2: a wheel of 1 kg m^2 oscillates in spin at 5-10 km/h on the sand
/// (docs/fmu.md section 4: the soil's shear is elastic, nothing slides as on the road), a heavy
/// one settles to the free-rolling state (M_y = 0) in a second.
struct Roll {
  FmuInstance& f;
  double speed, z, w = 0, x = 0, spin = 0, angle = 0;
  std::vector<double> fx{}, fz{}, my{};
  static constexpr double kInertia_kg_m2 = 50;
  void until(double end, const std::function<double(double)>& spin_of = {}) {
    while (f.time() < end - 1e-9) {
      const double s = std::min(f.time() / 0.5, 1.0), v = speed * s * s * (3 - 2 * s);
      if (spin_of) spin = spin_of(v);
      f.set_wheel(x, z, v, w, angle, spin);
      ASSERT_EQ(f.step(kSandStep_s), fmi2OK) << f.messages().back();
      fx.push_back(f.get("wheel_load.force.x"));
      fz.push_back(f.get("wheel_load.force.z"));
      my.push_back(f.get("wheel_load.moment.y"));
      w += kSandStep_s * ((fz.back() - kSandLoad_N) / 20 - 2000 * w / 20);
      z += kSandStep_s * w;
      if (!spin_of) spin += kSandStep_s * my.back() / kInertia_kg_m2;
      angle += kSandStep_s * spin;
      x += kSandStep_s * v;
    }
  }
  static double tail(const std::vector<double>& v) {
    double s = 0;
    for (std::size_t k = v.size() - 200; k < v.size(); ++k) s += v[k];
    return s / 200;
  }
};

/// `traction`'s drawbar pull and motion resistance at its free-rolling slip (zero torque),
/// interpolated between the two slips that bracket it (against the rolling radius since issue
/// 48: zero torque at s = -0.018 on this sand).
struct FreeRolling {
  double slip = 0, drawbar_pull_N = 0, motion_resistance_N = 0;
};
FreeRolling traction_free_rolling() {
  const std::vector<contact::TractionResult> r = contact::steady_traction(
      sand_model(), sand_model().config.ground, {{kSandLoad_N, -0.03}, {kSandLoad_N, -0.01}});
  EXPECT_TRUE(r[0].ok() && r[1].ok());
  EXPECT_LT(r[0].torque_Nm, 0);
  EXPECT_GT(r[1].torque_Nm, 0);
  const double u = r[0].torque_Nm / (r[0].torque_Nm - r[1].torque_Nm);
  auto at = [&](double a, double b) { return a + u * (b - a); };
  return {at(r[0].slip, r[1].slip), at(r[0].drawbar_pull_N, r[1].drawbar_pull_N),
          at(r[0].motion_resistance_N, r[1].motion_resistance_N)};
}

// Issue 46: free rolling's F_x / F_z within 5 % of traction's at its free-rolling slip. The
// towing force of a free-rolling wheel is traction's -DP at zero torque; its compaction part
// R_c is reported as soil.compaction_resistance. Traction is quasi-static with the relaxed
// tread, so the FMU runs without the tread's relaxation (5 km/h; 2 km/h gives the same to
// 1e-3). Measured: -F_x/F_z 0.0995 against -DP/W 0.1005 (-1 %), R_c 388.7 N against 387.6 N.
// With the config's relaxation the glassy tread presses the sand deeper at the front:
// -F_x/F_z 0.1058 (docs/fmu.md section 4).
constexpr double kSandRollingTol = 0.05;

TEST(FmuSoil, FreeRollingResistsAsTractionAtItsFreeRollingSlipAndBrakingSaturatesOnTheShear) {
  const FreeRolling tr = traction_free_rolling();
  FmuInstance f(sand_fmu_relaxed());
  Roll r{f, 5 / 3.6, sand_R0() - footprint_sinking(kSandLoad_N)};
  r.spin = r.speed / sand_R0();  // rolling from the start
  f.set("wheel_state.pos.z", r.z);
  ASSERT_EQ(f.initialize(), fmi2OK);
  r.until(2.0);
  const double Fx = Roll::tail(r.fx), Fz = Roll::tail(r.fz);
  const double Rc = f.get("soil.compaction_resistance");
  std::cout << "free rolling on LETE sand at 5 km/h: -F_x/F_z " << -Fx / Fz << " (traction at its "
            << "free-rolling slip " << tr.slip << ": -DP/W " << -tr.drawbar_pull_N / kSandLoad_N
            << ", R_c/W " << tr.motion_resistance_N / kSandLoad_N << "), R_c " << Rc << " N\n";
  EXPECT_NEAR(Fz, kSandLoad_N, 0.002 * kSandLoad_N);
  EXPECT_NEAR(Roll::tail(r.my), 0, 1e-3 * kSandLoad_N * sand_R0());  // free rolling: M_y = 0
  EXPECT_NEAR(-Fx / Fz, -tr.drawbar_pull_N / kSandLoad_N,
              kSandRollingTol * -tr.drawbar_pull_N / kSandLoad_N);
  EXPECT_NEAR(Rc, tr.motion_resistance_N, kSandRollingTol * tr.motion_resistance_N);

  // Braking at held spins V (1 + kappa) / R_e: |F_x| rises with the slip; its shear part
  // |F_x| - R_c saturates below the soil's strength c A + W tan(phi) (Janosi-Hanamoto).
  const double Re = r.speed / r.spin;
  const auto& shear = sand_model().config.ground.soil_shear();
  const double strength_N =
      shear.cohesion_kPa * 1e3 * f.get("tyre.contact_length") * sand_model().config.tread.width_m +
      kSandLoad_N * std::tan(shear.friction_angle_deg * M_PI / 180);
  double previous = 0, until = 2.0;
  for (double kappa : {-0.02, -0.05, -0.1, -0.2, -0.4, -0.7}) {
    until += 0.6;
    const std::size_t before = r.fx.size();
    r.until(until, [&](double v) { return v * (1 + kappa) / Re; });
    ASSERT_GT(r.fx.size(), before + 200);
    const double brake = -Roll::tail(r.fx), rc = f.get("soil.compaction_resistance");
    std::cout << "kappa " << kappa << ": F_x " << -brake << " N, shear " << -(brake - rc)
              << " N, c A + W tan(phi) " << strength_N << " N\n";
    EXPECT_GT(brake, previous) << kappa;
    EXPECT_LT(brake - rc, strength_N) << kappa;
    previous = brake;
  }
  EXPECT_GT(previous - f.get("soil.compaction_resistance"), 0.95 * strength_N);  // saturated
}

TEST(FmuSoil, TheSoilsKeysAreParametersWithTheirRanges) {
  FmuInstance f(sand_fmu());
  ASSERT_TRUE(f.ok());
  EXPECT_EQ(f.set("ground.bekker.n", 0.0), fmi2Discard);  // n in (0, 3]
  EXPECT_TRUE(f.logged("ground.bekker.n = 0 is outside the variable's range (0, 3]"))
      << f.messages().back();
  EXPECT_EQ(f.set("ground.bekker.friction_angle_deg", 95), fmi2Discard);
  // A stiffer sand carries more at the same press: the parameter reaches the soil.
  const double delta = footprint_sinking(kSandLoad_N);
  auto press = [&](FmuInstance& g) {
    g.set("wheel_state.pos.z", sand_R0() - delta);
    EXPECT_EQ(g.initialize(), fmi2OK) << g.messages().back();
    return g.get("wheel_load.force.z");
  };
  FmuInstance packed_sand(sand_fmu()), stiffer(sand_fmu());
  ASSERT_EQ(stiffer.set("ground.bekker.k_phi", 2 * 5301), fmi2OK);
  const double a = press(packed_sand), b = press(stiffer);
  EXPECT_NEAR(a / kSandLoad_N, 1.0, 1e-3);  // the static start is the footprint itself
  EXPECT_GT(b, 1.2 * a);
  // k_c and k_phi both 0: refused at initialization, naming the keys.
  FmuInstance none(sand_fmu());
  ASSERT_EQ(none.set("ground.bekker.k_c", 0.0), fmi2OK);
  ASSERT_EQ(none.set("ground.bekker.k_phi", 0.0), fmi2OK);
  EXPECT_EQ(none.initialize(), fmi2Error);
  EXPECT_TRUE(none.logged("ground.bekker.k_c and ground.bekker.k_phi cannot both be 0"));
}

TEST(FmuSoil, TerrainHeightMovesTheUndisturbedSurface) {
  const double delta = footprint_sinking(kSandLoad_N);
  FmuInstance low(sand_fmu()), high(sand_fmu());
  low.set("wheel_state.pos.z", sand_R0() - delta);
  high.set("terrain_height", 0.25);
  high.set("wheel_state.pos.z", 0.25 + sand_R0() - delta);
  ASSERT_EQ(low.initialize(), fmi2OK);
  ASSERT_EQ(high.initialize(), fmi2OK);
  for (int k = 0; k < 50; ++k) {
    ASSERT_EQ(low.step(kSandStep_s), fmi2OK);
    ASSERT_EQ(high.step(kSandStep_s), fmi2OK);
  }
  // The same up to the static start's search (to 10 nm of deflection, driven_tyre.cc) and the
  // rounding of the shifted heights.
  EXPECT_NEAR(high.get("wheel_load.force.z"), low.get("wheel_load.force.z"), 1e-4 * kSandLoad_N);
  EXPECT_NEAR(high.get("soil.sinkage"), low.get("soil.sinkage"), 1e-6);
}

TEST(FmuSoil, ASoilTheFmuCannotRunIsRefusedAtExportNamingTheKey) {
  auto refused = [](const std::string& config, const std::vector<std::string>& sets,
                    const std::string& ground, const std::string& key) {
    PackageOptions o;
    o.config_path = config;
    o.overrides = sets;
    o.ground_path = ground;
    o.output_path = "/nonexistent-folder/never-written.fmu";
    o.binary_path = find_fmu_binary().empty() ? std::string(MODALTYRE_CLI) : find_fmu_binary();
    try {
      write_fmu(o);
      ADD_FAILURE() << "packed: " << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().key, key) << e.what();
    }
  };
  const std::string config3d = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
  refused(config3d,
          {"ground.model=kelvin_voigt", "ground.kelvin_voigt.E2_MPa=2",
           "ground.kelvin_voigt.layer_mm=200", "ground.kelvin_voigt.eta2_kPa_s=50"},
          "", "ground.kelvin_voigt.eta2_kPa_s");
  refused(kSandTyreConfig, {"tyre.rigid=true"}, kSandSoil, "tyre.rigid");
  refused(kSandTyreConfig, {"contact.window_mm=60"}, kSandSoil, "ground.model");
}

}  // namespace
}  // namespace modaltyre::fmu::test
