// Operating conditions stated with --set (`--set hold_s=60`, `--set surface=soil`) in
// `footprint`, `validate` and `transient`: the catalogue's names and ranges as in a sweep, the
// conditions in the output header, exit 2 naming the condition where it does not apply.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig2d;
using modaltyre_test::kTable3;

class ConditionsCli : public modaltyre_test::CliFixture {
 protected:
  // A coarse mesh with tread relaxation (seed 001 eq. (10)) on: the hold time acts.
  modaltyre_test::CliRun footprint(std::vector<std::string> extra, bool json = true) {
    std::vector<std::string> args{"footprint", kConfig2d,
                                  "--load",    "4000",
                                  "--set",     "contact.unit_length_mm=2",
                                  "--set",     "effects.tread_relaxation.enabled=true"};
    if (json) args.push_back("--json");
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args);
  }
};

TEST_F(ConditionsCli, HoldTimeRelaxesTheTreadSoTheTyreSinksDeeper) {
  const auto base = footprint({});
  const auto held = footprint({"--set", "hold_s=60"});
  ASSERT_EQ(base.exit_code, 0) << base.err;
  ASSERT_EQ(held.exit_code, 0) << held.err;
  const auto b = nlohmann::json::parse(base.out), h = nlohmann::json::parse(held.out);
  EXPECT_EQ(b["conditions"]["hold_s"], 0.0);
  EXPECT_EQ(h["conditions"]["hold_s"], 60.0);
  // The relaxed tread is softer: at the same load the held tyre sinks deeper.
  EXPECT_GT(h["cases"][0]["sinking_mm"].get<double>(),
            b["cases"][0]["sinking_mm"].get<double>() * 1.01);
}

TEST_F(ConditionsCli, FootprintHeaderStatesTheConditionsAndSoilIsAccepted) {
  const auto r = footprint({"--set", "hold_s=60", "--set", "surface=soil"}, false);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("conditions: 230 kPa, held 60 s, standing, loading branch, soil"),
            std::string::npos)
      << r.out;
  const auto j = nlohmann::json::parse(footprint({"--set", "surface=soil"}).out);
  EXPECT_EQ(j["conditions"]["surface"], "soil");
}

TEST_F(ConditionsCli, ValueOutsideTheCatalogueExitsTwoStatingTheRange) {
  const auto r = footprint({"--set", "hold_s=-1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("hold_s"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[0, 1e7] s"), std::string::npos) << r.err;
  const auto w = footprint({"--set", "surface=mud"});
  EXPECT_EQ(w.exit_code, 2);
  EXPECT_NE(w.err.find("rigid"), std::string::npos) << w.err;
}

TEST_F(ConditionsCli, LoadAndHorizontalForceComeFromTheirOptions) {
  const auto r = footprint({"--set", "load_N=3000"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--load"), std::string::npos) << r.err;
  const auto f = footprint({"--set", "horizontal_force_N=100"});
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find("--fx"), std::string::npos) << f.err;
}

TEST_F(ConditionsCli, ValidateAppliesAConditionTheFileDoesNotGive) {
  const auto r = run({"validate", kConfig2d, kTable3, "--set", "contact.unit_length_mm=2", "--set",
                      "effects.tread_relaxation.enabled=true", "--set", "hold_s=60"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("conditions: hold_s=60"), std::string::npos) << r.out;
  const auto j = run({"validate", kConfig2d, kTable3, "--json", "--set", "contact.unit_length_mm=2",
                      "--set", "effects.tread_relaxation.enabled=true", "--set", "hold_s=60"});
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto doc = nlohmann::json::parse(j.out);
  EXPECT_EQ(doc["conditions"]["hold_s"], 60.0);
  for (const auto& row : doc["rows"]) EXPECT_EQ(row["conditions"]["hold_s"], 60.0) << row;
}

TEST_F(ConditionsCli, ValidateRefusesAConditionTheFileGivesAsAColumn) {
  const auto csv = (dir_ / "held.csv").string();
  std::ofstream(csv) << "load_N,hold_s,sinking_mm\n2131,0,8\n3261,0,12\n";
  const auto r = run({"validate", kConfig2d, csv, "--set", "hold_s=60"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("hold_s column"), std::string::npos) << r.err;
}

TEST_F(ConditionsCli, TransientRefusesAConditionItsScenarioHasNot) {
  const auto r = run({"transient", kConfig2d, "--scenario", "rolling", "--set", "hold_s=60"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("scenario rolling takes load_N, speed_kmh"), std::string::npos) << r.err;
  const auto s = run({"transient", kConfig2d, "--scenario", "load-hold", "--set", "surface=soil"});
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("surface"), std::string::npos) << s.err;
  // load-hold's hold_s is its scenario key, checked by the config reader (at most 1e6 s there).
  const auto h = run({"transient", kConfig2d, "--scenario", "load-hold", "--set", "hold_s=5e6"});
  EXPECT_EQ(h.exit_code, 2);
  EXPECT_NE(h.err.find("transient.load_hold.hold_s"), std::string::npos) << h.err;
}

// Issue 16: a key given twice on one command line is refused naming both values (the first
// one used to be taken silently for a config key, the last for a condition), in every command
// that takes --set.
struct Repeated {
  std::string name;
  std::vector<std::string> args;  // up to the --set options
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const Repeated& r, std::ostream* os) { *os << r.name; }

class RepeatedSetCli : public modaltyre_test::CliFixture,
                       public ::testing::WithParamInterface<Repeated> {};

TEST_P(RepeatedSetCli, KeyTwiceIsRefusedNamingBothValues) {
  for (const auto& [key, a, b] :
       {std::tuple<std::string, std::string, std::string>{"tread.modulus_MPa", "3", "4"},
        {"hold_s", "10", "60"}}) {
    auto args = GetParam().args;
    for (const auto& v : {a, b}) args.insert(args.end(), {"--set", key + "=" + v});
    const auto r = run(args);
    EXPECT_EQ(r.exit_code, 2) << key << ": " << r.err;
    EXPECT_NE(r.err.find("--set: " + key + ": given twice ('" + a + "' and '" + b + "')"),
              std::string::npos)
        << r.err;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Commands, RepeatedSetCli,
    ::testing::Values(Repeated{"Footprint", {"footprint", kConfig2d}},
                      Repeated{"Validate", {"validate", kConfig2d, kTable3}},
                      Repeated{"Transient", {"transient", kConfig2d, "--scenario", "load-hold"}},
                      Repeated{"Sweep", {"sweep", "no_such_sweep.yaml"}},
                      Repeated{"TirExport", {"tir", "export", kConfig2d, "--output", "x.tir"}},
                      Repeated{"TirCompare",
                               {"tir", "compare", kConfig2d,
                                std::string(MODALTYRE_SOURCE_DIR) +
                                    "/tests/data/tir/chrono_generic_mf61.tir"}},
                      Repeated{"Discover", {"discover", kConfig2d, kTable3}}),
    [](const ::testing::TestParamInfo<Repeated>& info) { return info.param.name; });

// transient maps hold_s onto its scenario's key: both given is the same key twice.
TEST_F(ConditionsCli, TransientConditionAndItsScenarioKeyTogetherAreRefused) {
  const auto r = run({"transient", kConfig2d, "--scenario", "load-hold", "--set", "hold_s=60",
                      "--set", "transient.load_hold.hold_s=10"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("transient.load_hold.hold_s: given twice ('10' and '60')"),
            std::string::npos)
      << r.err;
}

}  // namespace
