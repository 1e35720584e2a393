// `modaltyre identify ... --into-config TYRE.yaml --out-config OUT.yaml`: identified parameters
// written into the tyre config as effects (docs/rheology.md, "Feeding the footprint model").
// Planted synthetic data as in three_element_test.cc, soil_test.cc and load_deflection_test.cc;
// the CLI runs in a fresh temporary folder per test (tests/app/cli_runner.h).
//
// The checks that need the footprint model go through the CLI (`footprint`, `sweep`), which
// loads OUT with contact::load_tyre_config and predicts with contact::predict: this
// test executable links modaltyre::rheology only.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "../app/cli_runner.h"
#include "../support/data_paths.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/rheology/contact_geometry.h"
#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"
#include "rheology_test_support.h"

namespace modaltyre::rheology {
namespace {

using modaltyre_test::CliFixture;
using modaltyre_test::slurp;

using modaltyre_test::kConfig2d;
using modaltyre_test::kSrc;

ThreeElementOptions tyre_options() { return test::sf350_three_element_options(); }

constexpr double kE1_Pa = 1.2e6, kChi = 0.02, kH0_m = 0.020;

std::string static_loop_csv(double noise_rel, unsigned seed) {
  test::Noise noise;
  noise.rng.seed(seed);
  std::ostringstream s;
  s.precision(10);
  s << "load_N,deflection_mm,branch\n";
  for (bool loading : {true, false})
    for (int i = 1; i <= 8; ++i) {
      const double h = 0.004 * i;
      const double P =
          static_loop_load(kE1_Pa, kChi, h, loading, tyre_options()) * (1 + noise_rel * noise());
      s << P << "," << h * 1e3 << "," << (loading ? "loading" : "unloading") << "\n";
    }
  return s.str();
}

// Free decay about h0 = 20 mm, 8 Hz, zeta = 0.05 (closed form, as three_element_test.cc).
std::string decay_csv() {
  const double f = 8.0, zeta = 0.05, a0 = 0.005;
  const double wd = 2 * M_PI * f, wn = wd / std::sqrt(1 - zeta * zeta);
  std::ostringstream s;
  s.precision(10);
  s << "t_s,deflection_mm\n";
  for (int i = 0; i <= 1500; ++i) {
    const double t = 1e-3 * i;
    s << t << "," << (kH0_m + a0 * std::exp(-zeta * wn * t) * std::cos(wd * t)) * 1e3 << "\n";
  }
  return s.str();
}

// The planted Saint-Venant force at the decay's contact length (docs/rheology.md):
// F_f = 2 B_tr chi E1 r0 phi1 cos phi1 with phi1 at h_Z0.
double planted_friction_N() {
  const auto o = tyre_options();
  const double phi1 = half_contact_angle(kH0_m, o.r0_m);
  return 2 * o.tread_width_m * kChi * kE1_Pa * o.r0_m * phi1 * std::cos(phi1);
}

std::string soil_csv() {
  std::ostringstream s;
  s.precision(10);
  s << "load_N,longitudinal_force_N,alpha1_deg,alpha2_deg,total_sinking_mm,elastic_sinking_mm,"
       "layer_mm,speed_m_s\n";
  for (const SoilRow& r : test::planted_soil_rows().rows)
    s << r.load_N << "," << r.longitudinal_force_N << "," << r.alpha1_rad * 180 / M_PI << ","
      << r.alpha2_rad * 180 / M_PI << "," << r.total_sinking_m * 1e3 << ","
      << r.elastic_sinking_m * 1e3 << "," << r.layer_m * 1e3 << "," << r.speed_m_s << "\n";
  return s.str();
}

std::string load_deflection_csv(const std::vector<double>& pressures_kPa) {
  std::ostringstream s;
  s.precision(10);
  s << "load_N,pressure_kPa,deflection_mm\n";
  for (double p : pressures_kPa)
    for (double P : {2000.0, 3000.0, 4000.0, 5000.0, 6000.0})
      s << P << "," << p << "," << law_deflection(0.13e-3, P, p * 1e3) * 1e3 << "\n";
  return s.str();
}

// CSV of a sweep: column name -> values.
std::map<std::string, std::vector<std::string>> read_csv_columns(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream h(line); std::getline(h, line, ',');) names.push_back(line);
  std::map<std::string, std::vector<std::string>> cols;
  while (std::getline(in, line)) {
    std::stringstream r(line);
    std::string cell;
    for (const auto& n : names) {
      std::getline(r, cell, ',');
      cols[n].push_back(cell);
    }
  }
  return cols;
}

class rheology_IdentifyIntoConfig : public CliFixture {
 protected:
  std::string file(const std::string& name, const std::string& text) {
    const auto p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }
  // OUT in its own folder, so that modal.hammer_csv must be re-anchored.
  std::string out() {
    std::filesystem::create_directories(dir_ / "out");
    return (dir_ / "out" / "sf350_identified.yaml").string();
  }
  // Writes OUT from the three-element test (static loop + free decay) and returns the CLI run.
  modaltyre_test::CliRun identify_three_element(double noise_rel = 0, unsigned seed = 11) {
    return run({"identify", "free-vibration", file("decay.csv", decay_csv()), "--mass-kg", "350",
                "--section-height-mm", "117", "--static",
                file("loop.csv", static_loop_csv(noise_rel, seed)), "--into-config", kConfig2d,
                "--out-config", out(), "--json"});
  }
  ConfigSection effect(const ConfigTree& t, const std::string& name) const {
    return t.root().section("effects").section(name);
  }
};

TEST_F(rheology_IdentifyIntoConfig, ThreeElementWritesDryFrictionForce) {
  const auto r = identify_three_element();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ConfigTree t = ConfigTree::load(out());
  const ConfigSection df = effect(t, "dry_friction");
  EXPECT_TRUE(df.boolean("enabled", false));
  // Noise-free planted loop: chi and E1 exact to 1e-9, h_Z0 of the decay to 1e-6.
  EXPECT_NEAR(df.number("friction_force_N", 0, 0, 1e9) / planted_friction_N(), 1.0, 1e-4);
  // Only the effect the method determines is switched on; the rest of the config is kept.
  EXPECT_FALSE(t.root().section("effects").has("soil_compliance"));
  EXPECT_DOUBLE_EQ(
      t.root().section("tread").number("modulus_MPa", 0, 0, 1e9),
      ConfigTree::load(kConfig2d).root().section("tread").number("modulus_MPa", 0, 0, 1e9));
  // modal.hammer_csv re-anchored to OUT's folder.
  EXPECT_TRUE(
      std::filesystem::exists(t.resolve_path(t.root().section("modal").text("hammer_csv", ""))));
  EXPECT_NE(r.out.find("\"into_config\""), std::string::npos);
  EXPECT_NE(r.out.find("effects.dry_friction.friction_force_N"), std::string::npos);
}

TEST_F(rheology_IdentifyIntoConfig, ThreeElementWithNoiseWithinStatedChiAccuracy) {
  // docs/rheology.md: chi within 25 % with 2 % load noise; E1 within 2 %; F_f ~ chi E1.
  for (unsigned seed : {11u, 12u, 13u}) {
    const auto r = identify_three_element(0.02, seed);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const ConfigTree t = ConfigTree::load(out());
    EXPECT_NEAR(
        effect(t, "dry_friction").number("friction_force_N", 0, 0, 1e9) / planted_friction_N(), 1.0,
        0.27)
        << seed;
  }
}

TEST_F(rheology_IdentifyIntoConfig, OutConfigRunsFootprintAndDryFrictionShiftsElasticLoadBy2Ff) {
  ASSERT_EQ(identify_three_element().exit_code, 0);
  const auto fp = run({"footprint", out(), "--load", "4000", "--json"});
  ASSERT_EQ(fp.exit_code, 0) << fp.err;
  EXPECT_NE(fp.out.find("dry_friction"), std::string::npos) << "listed among the effects on";

  // Three-element model: at the same applied load F the elastic tyre carries F - F_f on the
  // loading branch and F + F_f on the unloading one, a difference of 2 F_f. The sweep predicts
  // both branches with contact::predict; they must equal the friction-free tyre at F -+ F_f.
  const double ff =
      effect(ConfigTree::load(out()), "dry_friction").number("friction_force_N", 0, 0, 1e9);
  const double F = 4000;
  const std::string coarse = "  contact.unit_length_mm: 2\n";
  const auto with = file("with.yaml", "base: " + out() + "\nset:\n" + coarse +
                                          "grid:\n  branch: [load, unload]\n  load_N: [4000]\n"
                                          "output: with.csv\n");
  const auto without =
      file("without.yaml", "base: " + out() + "\nset:\n" + coarse +
                               "  effects.dry_friction.enabled: false\ngrid:\n  load_N: [" +
                               std::to_string(F - ff) + ", " + std::to_string(F + ff) +
                               "]\noutput: without.csv\n");
  ASSERT_EQ(run({"sweep", with, "--threads", "1"}).exit_code, 0);
  ASSERT_EQ(run({"sweep", without, "--threads", "1"}).exit_code, 0);
  const auto w = read_csv_columns((dir_ / "with.csv").string());
  const auto wo = read_csv_columns((dir_ / "without.csv").string());
  ASSERT_EQ(w.at("sinking_mm").size(), 2u);
  ASSERT_EQ(wo.at("sinking_mm").size(), 2u);
  const double load_branch = std::stod(w.at("sinking_mm")[0]);
  const double unload_branch = std::stod(w.at("sinking_mm")[1]);
  EXPECT_EQ(w.at("branch")[0], "load");
  EXPECT_GT(unload_branch, load_branch) << "unloading: the elastic tyre carries more";
  EXPECT_NEAR(load_branch / std::stod(wo.at("sinking_mm")[0]), 1.0, 1e-5);
  EXPECT_NEAR(unload_branch / std::stod(wo.at("sinking_mm")[1]), 1.0, 1e-5);
}

TEST_F(rheology_IdentifyIntoConfig, SoilWritesModulusAndLayer) {
  const auto r =
      run({"identify", "soil-rolling", file("soil.csv", soil_csv()), "--r0-mm", "500",
           "--tread-width-mm", "300", "--into-config", kConfig2d, "--out-config", out()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ConfigSection s = effect(ConfigTree::load(out()), "soil_compliance");
  EXPECT_TRUE(s.boolean("enabled", false));
  EXPECT_NEAR(s.number("modulus_MPa", 0, 0, 1e9) / 3.0, 1.0, 1e-5);  // noise-free: 1e-6
  EXPECT_NEAR(s.number("layer_mm", 0, 0, 1e9), 300.0, 1e-9);
  EXPECT_NE(r.out.find("augmented tyre config"), std::string::npos);
  const auto fp =
      run({"footprint", out(), "--load", "4000", "--json", "--set", "contact.unit_length_mm=2"});
  EXPECT_EQ(fp.exit_code, 0) << fp.err;
}

TEST_F(rheology_IdentifyIntoConfig, LoadDeflectionOverLoadsAndPressuresWritesBothLaws) {
  const auto r =
      run({"identify", "load-deflection", file("ld.csv", load_deflection_csv({150, 230, 300})),
           "--into-config", kConfig2d, "--out-config", out()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ConfigTree t = ConfigTree::load(out());
  const ConfigSection ls = effect(t, "load_stiffening"), ip = effect(t, "inflation_pressure");
  EXPECT_TRUE(ls.boolean("enabled", false));
  EXPECT_DOUBLE_EQ(ls.number("exponent", 0, -1, 1), 0.25);
  EXPECT_NEAR(ls.number("reference_load_N", 0, 0, 1e9), 4000.0, 1e-6);  // mean test load
  EXPECT_TRUE(ip.boolean("enabled", false));
  EXPECT_DOUBLE_EQ(ip.number("exponent", 0, 0, 9), 1.0);
  EXPECT_DOUBLE_EQ(ip.number("modal_test_pressure_kPa", 0, 0, 1e9), 230.0);  // tyre config's
  const auto fp =
      run({"footprint", out(), "--load", "4000", "--json", "--set", "contact.unit_length_mm=2"});
  EXPECT_EQ(fp.exit_code, 0) << fp.err;
}

TEST_F(rheology_IdentifyIntoConfig, LoadDeflectionAtOnePressureLeavesThePressureLawAlone) {
  const auto r = run({"identify", "load-deflection", file("ld1.csv", load_deflection_csv({230})),
                      "--into-config", kConfig2d, "--out-config", out()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const ConfigTree t = ConfigTree::load(out());
  EXPECT_TRUE(effect(t, "load_stiffening").boolean("enabled", false));
  EXPECT_FALSE(effect(t, "inflation_pressure").boolean("enabled", false));
  EXPECT_NE(r.out.find("the seed's, not identified"), std::string::npos);
}

// First number after "key": in a JSON text (the CLI's output).
double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return std::nan("");
  return std::stod(json.substr(at + key.size() + 3));
}

// K_Z feeds the carcass level (docs/rheology.md 6.5): OUT's footprint sinks eq. (3)'s h_Z at
// the mean test load and the tyre's pressure, and a stiffer tested tyre gives a stiffer carcass.
TEST_F(rheology_IdentifyIntoConfig, LoadDeflectionSetsTheCarcassLevelSoTheFootprintSinksEq3) {
  auto csv_for = [](double K_Z_mm) {
    std::ostringstream s;
    s.precision(10);
    s << "load_N,pressure_kPa,deflection_mm\n";
    for (double P : {2000.0, 3000.0, 4000.0, 5000.0, 6000.0})
      s << P << ",230," << law_deflection(K_Z_mm * 1e-3, P, 230e3) * 1e3 << "\n";
    return s.str();
  };
  std::vector<double> scales;
  for (double K_Z_mm : {0.13, 0.10}) {
    const auto r = run({"identify", "load-deflection", file("ld.csv", csv_for(K_Z_mm)),
                        "--into-config", kConfig2d, "--out-config", out()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("calibrated on all 5 rows"), std::string::npos) << r.out;
    const double scale =
        ConfigTree::load(out()).root().section("modal").number("compliance_scale", 0, 0, 1e9);
    scales.push_back(scale);
    const auto fp = run({"footprint", out(), "--load", "4000", "--json"});
    ASSERT_EQ(fp.exit_code, 0) << fp.err;
    const double expected_mm = law_deflection(K_Z_mm * 1e-3, 4000, 230e3) * 1e3;
    EXPECT_NEAR(json_number(fp.out, "sinking_mm") / expected_mm, 1.0, 1e-5) << fp.out;
  }
  EXPECT_LT(scales[1], scales[0]) << "a stiffer tested tyre must give a stiffer carcass";
}

// A contact-stress profile is one operating point (docs/rheology.md 6.6): OUT's footprint sinks
// the profile's h_Z under the load eq. (8) integrates from it, and a stiffer foundation K1 at the
// same deflection (more load) gives a stiffer carcass.
TEST_F(rheology_IdentifyIntoConfig,
       ContactStressSetsTheCarcassLevelSoTheFootprintSinksItsDeflection) {
  const double r0_m = 0.2948, h_m = 0.018;
  auto profile_csv = [&](double K1_Pa_per_m) {
    std::ostringstream s;
    s.precision(10);
    s << "x_mm,stress_kPa\n";
    const double a = std::sqrt(r0_m * r0_m - (r0_m - h_m) * (r0_m - h_m));
    for (int i = -40; i <= 40; ++i) {
      const double x = 1.25 * a * i / 40;
      s << x * 1e3 << "," << contact_stress_law(K1_Pa_per_m, x, h_m, r0_m) * 1e-3 << "\n";
    }
    return s.str();
  };
  std::vector<double> scales;
  for (double K1 : {2.5e7, 3.5e7}) {
    const auto r = run({"identify", "contact-stress", file("cs.csv", profile_csv(K1)), "--config",
                        kConfig2d, "--into-config", kConfig2d, "--out-config", out(), "--json"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("through K1 and h_Z"), std::string::npos) << r.out;
    const double load_N = json_number(r.out.substr(r.out.find("\"load_eq8\"")), "value");
    const double scale =
        ConfigTree::load(out()).root().section("modal").number("compliance_scale", 0, 0, 1e9);
    scales.push_back(scale);
    const auto fp = run({"footprint", out(), "--load", std::to_string(load_N), "--json"});
    ASSERT_EQ(fp.exit_code, 0) << fp.err;
    EXPECT_NEAR(json_number(fp.out, "sinking_mm") / (h_m * 1e3), 1.0, 1e-4) << fp.out;
  }
  EXPECT_LT(scales[1], scales[0]) << "more load at the same deflection needs a stiffer carcass";
}

TEST_F(rheology_IdentifyIntoConfig, LoadDeflectionStifferThanTheTreadAloneExits2) {
  std::ostringstream s;
  s << "load_N,pressure_kPa,deflection_mm\n";
  for (double P : {2000.0, 4000.0})
    s << P << ",230," << law_deflection(1e-6, P, 230e3) * 1e3 << "\n";
  const auto r = run({"identify", "load-deflection", file("stiff.csv", s.str()), "--into-config",
                      kConfig2d, "--out-config", out()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("modal.compliance_scale"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("stiffer"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(rheology_IdentifyIntoConfig, MethodsThatDetermineNoEffectRefuseWithExit2) {
  const auto b = run({"identify", "b-factors", "--into-config", kConfig2d, "--out-config", out()});
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("uses nothing"), std::string::npos) << b.err;
  const auto fv = run({"identify", "free-vibration", file("decay.csv", decay_csv()), "--mass-kg",
                       "350", "--into-config", kConfig2d, "--out-config", out()});
  EXPECT_EQ(fv.exit_code, 2);
  EXPECT_NE(fv.err.find("--static"), std::string::npos) << fv.err;
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(rheology_IdentifyIntoConfig, BadUseExits2NamingTheFileOrOption) {
  const std::string soil = file("soil.csv", soil_csv());
  const std::vector<std::string> geo = {"--r0-mm", "500", "--tread-width-mm", "300"};
  auto args = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = {"identify", "soil-rolling", soil};
    a.insert(a.end(), geo.begin(), geo.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const auto no_out = run(args({"--into-config", kConfig2d}));
  EXPECT_EQ(no_out.exit_code, 2);
  EXPECT_NE(no_out.err.find("--out-config"), std::string::npos) << no_out.err;
  const auto no_into = run(args({"--out-config", out()}));
  EXPECT_EQ(no_into.exit_code, 2);
  EXPECT_NE(no_into.err.find("--into-config"), std::string::npos) << no_into.err;
  const std::string missing = (dir_ / "no_such_tyre.yaml").string();
  const auto unreadable = run(args({"--into-config", missing, "--out-config", out()}));
  EXPECT_EQ(unreadable.exit_code, 2);
  EXPECT_NE(unreadable.err.find(missing), std::string::npos) << unreadable.err;
  // A tyre config with a bad key is named by file and key.
  const std::string bad = file("bad.yaml", slurp(kConfig2d) +
                                               "effects:\n  dry_friction:\n    "
                                               "friction_force_N: -5\n");
  const auto bad_key = run(args({"--into-config", bad, "--out-config", out()}));
  EXPECT_EQ(bad_key.exit_code, 2);
  EXPECT_NE(bad_key.err.find("effects.dry_friction.friction_force_N"), std::string::npos)
      << bad_key.err;
  // OUT must not be the tyre config itself (a copy: never risk configs/sf350_2d_table3.yaml).
  const std::string copy = file("copy.yaml", slurp(kConfig2d));
  const auto self = run(args({"--into-config", copy, "--out-config", copy}));
  EXPECT_EQ(self.exit_code, 2);
  EXPECT_EQ(slurp(copy), slurp(kConfig2d));
  EXPECT_FALSE(std::filesystem::exists(out()));
}

// Issue 16 item 8: `--config X --write-config F` is `--into-config X --out-config F`, byte for
// byte in F and in the output; contact-stress takes r0 and B_tr from the tyre config in both.
TEST_F(rheology_IdentifyIntoConfig, WriteConfigAndIntoConfigWriteTheSameFile) {
  const std::string data = kSrc + "/tests/data/rheology/";
  for (const auto& [method, file] : std::vector<std::pair<std::string, std::string>>{
           {"contact-stress", "contact_stress.csv"}, {"load-deflection", "load_deflection.csv"}}) {
    const auto w = run({"identify", method, data + file, "--config", kConfig2d, "--write-config",
                        out(), "--json"});
    ASSERT_EQ(w.exit_code, 0) << method << ": " << w.err;
    const std::string written = slurp(out());
    std::filesystem::remove(out());
    const auto o = run({"identify", method, data + file, "--into-config", kConfig2d, "--out-config",
                        out(), "--json"});
    ASSERT_EQ(o.exit_code, 0) << method << ": " << o.err;
    EXPECT_EQ(slurp(out()), written) << method;
    EXPECT_EQ(o.out, w.out) << method;
  }
}

// The written config keeps TYRE's comments, and `validate` on it no longer recalibrates the
// identified carcass level: validation.calibrate loses modal.compliance_scale, and says so.
TEST_F(rheology_IdentifyIntoConfig, WrittenConfigKeepsCommentsAndValidateKeepsTheIdentifiedLevel) {
  const auto r =
      run({"identify", "load-deflection", kSrc + "/tests/data/rheology/load_deflection.csv",
           "--into-config", kConfig2d, "--out-config", out()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = slurp(out());
  std::istringstream tyre(slurp(kConfig2d));
  int comments = 0;
  for (std::string line; std::getline(tyre, line);) {
    if (line.find_first_not_of(' ') == std::string::npos ||
        line[line.find_first_not_of(' ')] != '#')
      continue;
    ++comments;
    EXPECT_NE(text.find(line + "\n"), std::string::npos) << "comment lost: " << line;
  }
  EXPECT_GT(comments, 10);
  const std::string said = "validation.calibrate: modal.compliance_scale removed";
  EXPECT_NE(text.find("# " + said), std::string::npos) << text;
  EXPECT_NE(r.out.find(said), std::string::npos) << r.out;
  const auto v =
      run({"validate", out(), kSrc + "/configs/data/sf350_footprint_table3.csv", "--json"});
  ASSERT_EQ(v.exit_code, 0) << v.err;
  const std::string calibrated = v.out.substr(0, v.out.find('}'));
  EXPECT_EQ(calibrated.find("modal.compliance_scale"), std::string::npos) << calibrated;
  EXPECT_NE(calibrated.find("tread.modulus_MPa"), std::string::npos) << calibrated;
}

// free-vibration identifies only eta1 without its static loop: `--config X --write-config F`,
// which means a tyre config, says that the static loop is missing instead of writing a record
// that `footprint F` would refuse; without --config the record is written as before.
TEST_F(rheology_IdentifyIntoConfig, FreeVibrationWriteConfigWithoutStaticSaysTheLoopIsMissing) {
  const std::string decay = file("decay.csv", decay_csv());
  const auto r = run({"identify", "free-vibration", decay, "--mass-kg", "350", "--config",
                      kConfig2d, "--write-config", out()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--write-config"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("without a static loop"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("give --static LOOP.csv"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out()));
  const auto rec = run({"identify", "free-vibration", decay, "--mass-kg", "350", "--r0-mm", "294.8",
                        "--write-config", out()});
  ASSERT_EQ(rec.exit_code, 0) << rec.err;
  EXPECT_NE(slurp(out()).find("rheology:"), std::string::npos);
}

// The soil test's wheel is not the tyre: a tyre config does not give its r0 and B_tr.
TEST_F(rheology_IdentifyIntoConfig, SoilRollingTakesTheWheelGeometryFromItsOptionsOnly) {
  const auto r =
      run({"identify", "soil-rolling", file("soil.csv", soil_csv()), "--config", kConfig2d});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--r0-mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not the test wheel's"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace modaltyre::rheology
