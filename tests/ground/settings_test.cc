// The ground's readers: soil files (configs/soils/), --set overrides, road profiles; hostile
// input is an InputError naming file, line and key.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/ground/rigid_wheel.h"

namespace modaltyre::ground {
namespace {

const std::string kSoils = std::string(MODALTYRE_SOURCE_DIR) + "/configs/soils/";

std::string temp_file(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "modaltyre_ground_tests";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return (dir / name).string();
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GroundSettings, EveryStandardSoilFileReadsAndNamesItsSource) {
  for (const char* name :
       {"dry_sand", "sandy_loam", "clayey_soil", "heavy_clay", "lete_sand", "snow"}) {
    const GroundSettings g = load_ground_file(kSoils + name + ".yaml");
    EXPECT_EQ(g.model, GroundModel::bekker) << name;
    EXPECT_NE(g.source.find("Wong"), std::string::npos) << name;
    EXPECT_FALSE(g.bekker.unloading.has_value()) << name;
    // Each soil carries the SF-350's outer radius as a rigid wheel at 500 N (fresh snow sinks
    // beyond 80 degrees of contact at 3 kN).
    const RigidWheelResult r = rigid_wheel_static(g, {0.2948, 0.14}, 500);
    EXPECT_TRUE(r.ok()) << name << ": " << r.message;
  }
  const GroundSettings lete = load_ground_file(kSoils + "lete_sand.yaml");
  EXPECT_EQ(lete.bekker.n, 0.79);
  EXPECT_EQ(lete.bekker.k_c, 102);
  EXPECT_EQ(lete.bekker.k_phi, 5301);
  EXPECT_EQ(lete.bekker_shear.cohesion_kPa, 1.3);
  EXPECT_EQ(lete.bekker_shear.friction_angle_deg, 31.1);
  EXPECT_EQ(lete.bekker_shear.shear_modulus_K_mm, 12);
}

TEST(GroundSettings, EveryKeyCanBeSetFromTheCommandLine) {
  const GroundSettings g =
      load_ground_file(kSoils + "lete_sand.yaml",
                       {"ground.bekker.n=0.8", "ground.bekker.k_c=0", "ground.bekker.k_phi=6000",
                        "ground.bekker.cohesion_kPa=0", "ground.bekker.friction_angle_deg=0",
                        "ground.bekker.shear_modulus_K_mm=20", "ground.bekker.unloading.k0=10",
                        "ground.bekker.unloading.Au=2e6"});
  EXPECT_EQ(g.bekker.n, 0.8);
  EXPECT_EQ(g.bekker.k_c, 0);
  EXPECT_EQ(g.bekker.k_phi, 6000);
  EXPECT_EQ(g.bekker_shear.friction_angle_deg, 0);  // a frictionless soil is valid
  ASSERT_TRUE(g.bekker.unloading.has_value());
  EXPECT_EQ(g.bekker.unloading->k0_kN_m3, 10);
  EXPECT_EQ(g.bekker.unloading->Au_kN_m4, 2e6);
  const std::string kv_file = temp_file(
      "kv.yaml", "ground:\n  model: kelvin_voigt\n  kelvin_voigt: {E2_MPa: 2, layer_mm: 200}\n");
  const GroundSettings kv = load_ground_file(kv_file, {"ground.kelvin_voigt.E2_MPa=3"});
  EXPECT_EQ(kv.model, GroundModel::kelvin_voigt);
  EXPECT_EQ(kv.kelvin_voigt.E2_MPa, 3);
}

// The discovery's soil_unloading switch: Wong's unloading on while its block is given, off with
// enabled: false (the rigid-plastic soil, as without the block).
TEST(GroundSettings, WongsUnloadingIsSwitchable) {
  const std::string f =
      temp_file("unl_on.yaml",
                "ground:\n  model: bekker\n  bekker:\n    n: 0.79\n    k_c: 102\n    "
                "k_phi: 5301\n    unloading: {k0: 0, Au: 5e5}\n");
  EXPECT_TRUE(load_ground_file(f).bekker.unloading.has_value());
  const GroundSettings off = load_ground_file(f, {"ground.bekker.unloading.enabled=false"});
  EXPECT_FALSE(off.bekker.unloading.has_value());
  const GroundSettings none = load_ground_file(kSoils + "lete_sand.yaml");
  const RigidWheel wheel{0.2948, 0.14};
  GroundSettings a = off, b = none;
  a.bekker_shear = b.bekker_shear;
  EXPECT_EQ(rigid_wheel_rolling(a, wheel, 3000, 0.2).sinkage_m,
            rigid_wheel_rolling(b, wheel, 3000, 0.2).sinkage_m);
  const std::string m = message_of([&] {
    load_ground_file(kSoils + "lete_sand.yaml", {"ground.bekker.unloading.enabled=true"});
  });
  EXPECT_NE(m.find("ground.bekker.unloading.Au"), std::string::npos) << m;
}

// Issue 44, "soil settings dropped silently": each case exit 2 naming file, line and key.
TEST(GroundSettings, SoilKeysAreNeverDroppedInSilence) {
  // A soil file without model: (the rigid road) and model: rigid with a bekker block.
  const std::string no_model = temp_file(
      "no_model.yaml", "ground:\n  bekker:\n    n: 0.79\n    k_c: 102\n    k_phi: 5301\n");
  std::string m = message_of([&] { load_ground_file(no_model); });
  EXPECT_NE(m.find("no_model.yaml:3: ground.bekker.n"), std::string::npos) << m;
  EXPECT_NE(m.find("without ground.model"), std::string::npos) << m;
  const std::string rigid =
      temp_file("rigid.yaml",
                "ground:\n  model: rigid\n  bekker:\n    n: 0.79\n    k_c: 102\n    k_phi: 5301\n");
  m = message_of([&] { load_ground_file(rigid); });
  EXPECT_NE(m.find("rigid.yaml:4: ground.bekker.n"), std::string::npos) << m;
  EXPECT_NE(m.find("ground.model is rigid"), std::string::npos) << m;
  // --set ground.model=kelvin_voigt over a Bekker file: the Kelvin-Voigt keys are unstated and
  // the Bekker block would be dropped.
  m = message_of(
      [&] { load_ground_file(kSoils + "lete_sand.yaml", {"ground.model=kelvin_voigt"}); });
  EXPECT_NE(m.find("ground.bekker"), std::string::npos) << m;
  EXPECT_NE(m.find("ground.model is kelvin_voigt"), std::string::npos) << m;
  // A soil model whose normal law is not stated.
  const std::string kv = temp_file("kv_bare.yaml", "ground:\n  model: kelvin_voigt\n");
  m = message_of([&] { load_ground_file(kv); });
  EXPECT_NE(m.find("ground.kelvin_voigt.E2_MPa"), std::string::npos) << m;
  EXPECT_NE(m.find("required with model: kelvin_voigt"), std::string::npos) << m;
  const std::string bekker =
      temp_file("bk_bare.yaml", "ground:\n  model: bekker\n  bekker:\n    n: 0.7\n");
  m = message_of([&] { load_ground_file(bekker); });
  EXPECT_NE(m.find("ground.bekker.k_c"), std::string::npos) << m;
}

TEST(GroundSettings, WongReecesStressIsAStatedOptionOffByDefault) {
  const GroundSettings off = load_ground_file(kSoils + "lete_sand.yaml");
  EXPECT_FALSE(off.wong_reece.enabled);
  const GroundSettings on =
      load_ground_file(kSoils + "lete_sand.yaml",
                       {"ground.bekker.wong_reece.enabled=true", "ground.bekker.wong_reece.c1=0.18",
                        "ground.bekker.wong_reece.c2=0.3", "ground.bekker.wong_reece.c3=0.1"});
  EXPECT_TRUE(on.wong_reece.enabled);
  EXPECT_EQ(on.wong_reece.c1, 0.18);
  EXPECT_EQ(on.wong_reece.c2, 0.3);
  EXPECT_EQ(on.wong_reece.c3, 0.1);
  EXPECT_NEAR(on.wong_reece.peak_ratio(0.5), 0.33, 1e-15);
  EXPECT_EQ(on.wong_reece.peak_ratio(5), 1.0);  // clamped: the peak never leaves the contact
  const std::string m = message_of(
      [&] { load_ground_file(kSoils + "lete_sand.yaml", {"ground.bekker.wong_reece.c1=1.5"}); });
  EXPECT_NE(m.find("ground.bekker.wong_reece.c1"), std::string::npos) << m;
  const std::string bad =
      temp_file("wr.yaml",
                "ground:\n  model: bekker\n  bekker:\n    n: 0.79\n    k_c: 102\n    k_phi: 5301\n "
                "   wong_reece: {enabled: true, c4: 1}\n");
  EXPECT_NE(message_of([&] { load_ground_file(bad); }).find("wong_reece.c4"), std::string::npos);
}

TEST(GroundSettings, HostileSoilFilesNameFileLineAndKey) {
  const std::string bad_key = temp_file("bad_key.yaml",
                                        "ground:\n  model: bekker\n  bekker:\n    n: 0.79\n    "
                                        "k_c: 102\n    k_phi: 5301\n    nn: 1\n");
  EXPECT_NE(message_of([&] { load_ground_file(bad_key); }).find("ground.bekker.nn"),
            std::string::npos);
  const std::string bad_n = temp_file(
      "bad_n.yaml", "ground:\n  model: bekker\n  bekker:\n    n: -1\n    k_c: 1\n    k_phi: 1\n");
  const std::string m = message_of([&] { load_ground_file(bad_n); });
  EXPECT_NE(m.find(":4"), std::string::npos) << m;
  EXPECT_NE(m.find("ground.bekker.n"), std::string::npos) << m;
  const std::string bad_model = temp_file("bad_model.yaml", "ground:\n  model: sand\n");
  EXPECT_NE(message_of([&] { load_ground_file(bad_model); }).find("ground.model"),
            std::string::npos);
  const std::string zero =
      temp_file("zero.yaml", "ground:\n  model: bekker\n  bekker: {n: 1, k_c: 0, k_phi: 0}\n");
  EXPECT_FALSE(message_of([&] { load_ground_file(zero); }).empty());
  const std::string no_ground = temp_file("none.yaml", "soil:\n  model: bekker\n");
  EXPECT_FALSE(message_of([&] { load_ground_file(no_ground); }).empty());
  const std::string unloading =
      temp_file("unl.yaml",
                "ground:\n  model: bekker\n  bekker:\n    n: 0.79\n    k_c: 102\n    k_phi: 5301\n "
                "   unloading: {k0: 0, Au: 0}\n");
  EXPECT_NE(message_of([&] { load_ground_file(unloading); }).find("unloading"), std::string::npos);
  EXPECT_FALSE(message_of([&] { load_ground_file(kSoils + "nonexistent.yaml"); }).empty());
}

TEST(RoadProfile, InterpolatesAndRefusesHostileFiles) {
  const std::string ok =
      temp_file("road.csv", "# a cleat\nx_m,height_m\n0,0\n1,0\n1.01,0.01\n1.03,0.01\n1.04,0\n");
  const RoadProfile p = read_road_profile_csv(ok);
  EXPECT_NEAR(p.height_at(1.005), 0.005, 1e-15);
  EXPECT_DOUBLE_EQ(p.height_at(-5), 0);
  EXPECT_DOUBLE_EQ(p.height_at(1.02), 0.01);
  EXPECT_NEAR(p.slope_at(1.005), 1.0, 1e-12);
  const std::string back = temp_file("back.csv", "x_m,height_m\n0,0\n1,0\n0.5,0\n");
  const std::string m = message_of([&] { read_road_profile_csv(back); });
  EXPECT_NE(m.find(":4"), std::string::npos) << m;
  EXPECT_NE(m.find("x_m"), std::string::npos) << m;
  EXPECT_FALSE(message_of([&] {
                 read_road_profile_csv(temp_file("one.csv", "x_m,height_m\n0,0\n"));
               }).empty());
  EXPECT_FALSE(message_of([&] {
                 read_road_profile_csv(temp_file("nan.csv", "x_m,height_m\n0,nan\n1,0\n"));
               }).empty());
  EXPECT_FALSE(message_of([&] {
                 read_road_profile_csv(temp_file("high.csv", "x_m,height_m\n0,1e9\n1,0\n"));
               }).empty());
  const std::string cfg =
      temp_file("profile.yaml", "ground:\n  model: profile\n  profile_csv: road.csv\n");
  const GroundSettings g = load_ground_file(cfg);
  ASSERT_TRUE(g.profile);
  EXPECT_DOUBLE_EQ(g.profile->height_at(1.02), 0.01);
  const std::string missing = temp_file("profile2.yaml", "ground:\n  model: profile\n");
  EXPECT_NE(message_of([&] { load_ground_file(missing); }).find("profile_csv"), std::string::npos);
}

}  // namespace
}  // namespace modaltyre::ground
