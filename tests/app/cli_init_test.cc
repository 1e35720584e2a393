// `modaltyre init` as a user runs it (issue 36's interface): init then footprint on the written
// config; --json says what was decided; bad input exits 2 naming the option; the config never
// replaces the hammer data it names.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;

using modaltyre_test::kHammer12pt;
// Seed 001 Table 2's radial family without orders (init proposes them).
const std::string kFrequencies =
    "133.580,135.528,155.739,156.657,180.092,182.454,207.977,210.787,238.917,241.519,274.594";

class CliInit : public modaltyre_test::CliFixture {};

TEST_F(CliInit, InitThenFootprintRunsWithoutCalibration) {
  const std::string out = (dir_ / "tyre.yaml").string();
  const CliRun init =
      run({"init", "--size", "195/60R14", "--test-pressure-kPa", "230", "--pressure-kPa", "230",
           "--frequencies", kFrequencies, "--output", out});
  ASSERT_EQ(init.exit_code, 0) << init.err;
  EXPECT_NE(slurp(out).find("frequencies_hz"), std::string::npos);
  const CliRun fp = run({"footprint", out, "--load", "4000", "--json"});
  ASSERT_EQ(fp.exit_code, 0) << fp.err;
  const auto j = nlohmann::json::parse(fp.out);
  const double sinking = j["cases"][0]["sinking_mm"];
  EXPECT_GT(sinking, 5);  // a passenger tyre at 4 kN sinks 10-20 mm
  EXPECT_LT(sinking, 40);
}

TEST_F(CliInit, JsonSaysOrdersAlternativesMassAndTension) {
  const CliRun r = run({"init", "--size", "195/60R14", "--test-pressure-kPa", "230",
                        "--frequencies", kFrequencies, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["orders_proposed"].get<bool>());
  EXPECT_EQ(j["orders"].size(), 11u);
  EXPECT_GE(j["alternatives"].size(), 2u);
  EXPECT_EQ(j["mass_source"], "tension");
  EXPECT_GT(j["mass_per_length_kg_m"].get<double>(), 1.0);
  EXPECT_GT(j["implied_tension_N"].get<double>(), 0.0);
  EXPECT_TRUE(j.contains("config"));  // no --output: the config is in the document
}

TEST_F(CliInit, BadInputExitsTwoNamingTheOption) {
  const CliRun size = run(
      {"init", "--size", "195-60R14", "--test-pressure-kPa", "230", "--frequencies", kFrequencies});
  EXPECT_EQ(size.exit_code, 2);
  EXPECT_NE(size.err.find("--size"), std::string::npos) << size.err;
  const CliRun orders = run({"init", "--size", "195/60R14", "--test-pressure-kPa", "230",
                             "--frequencies", "130,150,170", "--orders", "2,x,4"});
  EXPECT_EQ(orders.exit_code, 2);
  EXPECT_NE(orders.err.find("--orders"), std::string::npos) << orders.err;
  const CliRun none = run({"init", "--size", "195/60R14", "--test-pressure-kPa", "230"});
  EXPECT_EQ(none.exit_code, 2);
}

TEST_F(CliInit, ConfigNeverReplacesTheHammerData) {
  const std::string hammer = (dir_ / "h.csv").string();
  fs::copy_file(kHammer12pt, hammer);
  const std::string before = slurp(hammer);
  const CliRun r = run({"init", "--size", "195/60R14", "--test-pressure-kPa", "230", "--hammer",
                        hammer, "--output", hammer});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--hammer"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(hammer), before);
}

}  // namespace
