// The tyre on a soil as a user runs it: the footprint's header names the soil (not "rigid
// road"), `transient --ground` gives the soil's columns, and what the transient on a soil does
// not model is refused with exit 2 naming the key (docs/soil.md section 8).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;
using modaltyre_test::kLeteSandYaml;
const std::vector<std::string> kCoarse = {"--set", "contact.unit_length_mm=5", "--set",
                                          "contact.window_mm=300"};

class SoilCli : public modaltyre_test::CliFixture {
 protected:
  modaltyre_test::CliRun transient(std::vector<std::string> extra) {
    std::vector<std::string> a{"transient", kConfig2d,
                               "--set",     "transient.load_hold.hold_s=0.2",
                               "--set",     "transient.load_hold.ramp_rate_N_s=20000"};
    a.insert(a.end(), kCoarse.begin(), kCoarse.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return run(a);
  }
};

TEST_F(SoilCli, TheFootprintHeaderNamesTheSoil) {
  std::vector<std::string> a{"footprint", kConfig2d,
                             "--load",    "3000",
                             "--set",     "ground.model=bekker",
                             "--set",     "ground.bekker.n=0.79",
                             "--set",     "ground.bekker.k_c=102",
                             "--set",     "ground.bekker.k_phi=5301"};
  a.insert(a.end(), kCoarse.begin(), kCoarse.end());
  const auto r = run(a);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("loading branch, on the soil bekker"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("rigid road"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("soil_sinkage_mm  tyre_deflection_mm  bekker_width_mm"), std::string::npos)
      << r.out;
}

// `footprint --ground SOIL.yaml` is the soil as the config's ground: section would give it (the
// same document), ground.* overrides go to the soil file, tyre.rigid may follow it; a rigid
// tyre on the road is refused naming tyre.rigid.
TEST_F(SoilCli, FootprintTakesTheSoilFileAsItsGround) {
  std::vector<std::string> by_file{"footprint",   kConfig2d, "--load",
                                   "3000",        "--json",  "--ground",
                                   kLeteSandYaml, "--set",   "ground.bekker.n=0.8"};
  std::vector<std::string> by_set{"footprint",
                                  kConfig2d,
                                  "--load",
                                  "3000",
                                  "--json",
                                  "--set",
                                  "ground.model=bekker",
                                  "--set",
                                  "ground.name=LETE sand",
                                  "--set",
                                  "ground.bekker.n=0.8",
                                  "--set",
                                  "ground.bekker.k_c=102",
                                  "--set",
                                  "ground.bekker.k_phi=5301"};
  by_file.insert(by_file.end(), kCoarse.begin(), kCoarse.end());
  by_set.insert(by_set.end(), kCoarse.begin(), kCoarse.end());
  const auto f = run(by_file);
  const auto s = run(by_set);
  ASSERT_EQ(f.exit_code, 0) << f.err;
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto cf = nlohmann::json::parse(f.out)["cases"][0];
  const auto cs = nlohmann::json::parse(s.out)["cases"][0];
  EXPECT_GT(cf["soil_sinkage_mm"].get<double>(), 1.0);  // LETE sand at 3 kN sinks centimetres
  EXPECT_EQ(cf["soil_sinkage_mm"], cs["soil_sinkage_mm"]);
  EXPECT_EQ(cf["sinking_mm"], cs["sinking_mm"]);
  EXPECT_EQ(cf["contact_length_mm"], cs["contact_length_mm"]);

  const auto rigid = run({"footprint", kConfig2d, "--load", "3000", "--ground", kLeteSandYaml,
                          "--set", "tyre.rigid=true", "--json"});
  ASSERT_EQ(rigid.exit_code, 0) << rigid.err;
  EXPECT_EQ(nlohmann::json::parse(rigid.out)["cases"][0]["tyre_deflection_mm"], 0.0);

  const auto road = run({"footprint", kConfig2d, "--load", "3000", "--set", "tyre.rigid=true"});
  EXPECT_EQ(road.exit_code, 2);
  EXPECT_NE(road.err.find("tyre.rigid"), std::string::npos) << road.err;
}

TEST_F(SoilCli, TransientOntoTheSoilGivesItsColumns) {
  const auto r = transient({"--scenario", "load-hold", "--ground", kLeteSandYaml, "--json", "--csv",
                            (dir_ / "lh.csv").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["ground"], "bekker");
  const double soil = j["final"]["soil_sinkage_mm"].get<double>();
  EXPECT_GT(soil, 1.0);  // LETE sand at 4 kN: ~14 mm
  EXPECT_NEAR(j["final"]["tyre_deflection_mm"].get<double>(),
              j["final"]["sinking_mm"].get<double>() - soil, 1e-6 * soil);
  const std::string csv = modaltyre_test::slurp(dir_ / "lh.csv");
  EXPECT_NE(csv.find(",soil_sinkage_mm,compaction_resistance_N\n"), std::string::npos)
      << csv.substr(0, 200);
}

TEST_F(SoilCli, TheDefault3dConfigRunsOntoTheSoil) {
  // The 3D patch's transient on the soil (docs/soil.md section 8.3): the soil's columns beside
  // the 3D ones (coarse mesh: 5 mm sections, 15 mm columns).
  const auto r =
      run({"transient", kConfig3d, "--scenario", "load-hold", "--ground", kLeteSandYaml, "--set",
           "transient.load_hold.hold_s=0.2", "--set", "transient.load_hold.ramp_rate_N_s=20000",
           "--set", "contact.unit_length_mm=5", "--set", "footprint_3d.lateral_cell_mm=15",
           "--json", "--csv", (dir_ / "lh3d.csv").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["patch"], "3d");
  EXPECT_EQ(j["ground"], "bekker");
  const double soil = j["final"]["soil_sinkage_mm"].get<double>();
  EXPECT_GT(soil, 1.0);  // LETE sand at 4 kN: ~13 mm
  EXPECT_NEAR(j["final"]["tyre_deflection_mm"].get<double>(),
              j["final"]["sinking_mm"].get<double>() - soil, 1e-6 * soil);
  const std::string csv = modaltyre_test::slurp(dir_ / "lh3d.csv");
  EXPECT_NE(csv.find(",width_mm,contact_area_mm2,soil_sinkage_mm,compaction_resistance_N\n"),
            std::string::npos)
      << csv.substr(0, 200);
}

TEST_F(SoilCli, WhatTheTransientOnSoilDoesNotModelIsRefused) {
  // A road given as --ground.
  const auto road = dir_ / "road.yaml";
  std::ofstream(road) << "ground:\n  model: rigid\n";
  const auto a = transient({"--scenario", "load-hold", "--ground", road.string()});
  EXPECT_EQ(a.exit_code, 2);
  EXPECT_NE(a.err.find("ground.model"), std::string::npos) << a.err;
  // The cleat (a rigid obstacle on the road).
  const auto b = transient({"--scenario", "cleat", "--ground", kLeteSandYaml});
  EXPECT_EQ(b.exit_code, 2);
  EXPECT_NE(b.err.find("ground.model"), std::string::npos) << b.err;
  // The cleat on the 3D patch (its soil transient runs load-hold, free vibration, rolling).
  const auto c = run({"transient", kConfig3d, "--scenario", "cleat", "--ground", kLeteSandYaml});
  EXPECT_EQ(c.exit_code, 2);
  EXPECT_NE(c.err.find("ground.model"), std::string::npos) << c.err;
  // A soil key the file does not know.
  const auto d = transient({"--scenario", "load-hold", "--ground", kLeteSandYaml, "--set",
                            "ground.bekker.no_such_key=1"});
  EXPECT_EQ(d.exit_code, 2);
  EXPECT_NE(d.err.find("no_such_key"), std::string::npos) << d.err;
}

}  // namespace
