// `modaltyre fmu` as a user runs it: an archive (zip) on success; exit 2 naming file and key for
// a bad config value, an output over the config or its hammer data, an output in a missing
// folder; nothing written then.
#include <filesystem>
#include <string>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;

using modaltyre_test::kSrc;

class CliFmu : public modaltyre_test::CliFixture {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    fs::create_directories(dir_ / "data");
    fs::copy_file(kSrc + "/configs/data/sf350_hammer_12pt.csv",
                  dir_ / "data/sf350_hammer_12pt.csv");
    fs::copy_file(kSrc + "/configs/sf350_2d_table3.yaml", dir_ / "tyre.yaml");
  }
  std::string config() const { return (dir_ / "tyre.yaml").string(); }
};

TEST_F(CliFmu, WritesAZipArchiveAndNamesItsMembers) {
  const std::string out = (dir_ / "tyre.fmu").string();
  const CliRun r = run({"fmu", config(), "--output", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(out).substr(0, 4), std::string("PK\x03\x04", 4));  // a zip's local header
  for (const char* member : {"modelDescription.xml", "binaries/linux64/ModalTyre.so",
                             "resources/tyre.yaml", "resources/data/sf350_hammer_12pt.csv"})
    EXPECT_NE(r.out.find(member), std::string::npos) << member;
}

TEST_F(CliFmu, RefusesABadValueWithItsKeyAndWritesNothing) {
  const std::string out = (dir_ / "tyre.fmu").string();
  const CliRun r = run({"fmu", config(), "--output", out, "--set", "tread.modulus_MPa=-1"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("tread.modulus_MPa"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(CliFmu, RefusesAnOutputOverItsInputsOrInAMissingFolder) {
  const std::string before = slurp(config());
  CliRun r = run({"fmu", config(), "--output", config()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("CONFIG"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(config()), before);
  const std::string hammer = (dir_ / "data/sf350_hammer_12pt.csv").string();
  const std::string data = slurp(hammer);
  r = run({"fmu", config(), "--output", hammer});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("hammer_csv"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(hammer), data);
  r = run({"fmu", config(), "--output", (dir_ / "no/such/folder/tyre.fmu").string()});
  EXPECT_EQ(r.exit_code, 2) << r.err;
}

}  // namespace
