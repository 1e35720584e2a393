// `modaltyre tir` end to end: export writes a readable MF 6.2 file (and nothing on failure);
// compare prints the documented JSON; an FTire file and malformed files exit 2 naming the file,
// the line and the key.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "../app/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
const std::string kData = std::string(MODALTYRE_SOURCE_DIR) + "/tests/data/tir/";

class TirCli : public modaltyre_test::CliFixture {};

TEST_F(TirCli, ExportThenCompareInAbsoluteUnits) {
  const std::string out = (dir_ / "sf350.tir").string();
  const CliRun e = run({"tir", "export", kConfig, "--output", out});
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_NE(e.out.find("VERTICAL_STIFFNESS"), std::string::npos);
  const std::string text = modaltyre_test::slurp(out);
  EXPECT_NE(text.find("FITTYP                   = 62"), std::string::npos);
  EXPECT_NE(text.find("[DEFLECTION_LOAD_CURVE]"), std::string::npos);
  EXPECT_NE(text.find("[STRUCTURAL] and [INERTIA] left out"), std::string::npos);

  const CliRun c = run({"tir", "compare", kConfig, out, "--json", "--points", "5"});
  ASSERT_EQ(c.exit_code, 0) << c.err;
  const auto j = nlohmann::json::parse(c.out);
  EXPECT_EQ(j["tir"]["fittyp"], 62);
  for (const char* k :
       {"path", "unloaded_radius_mm", "width_mm", "fnomin_N", "vertical_stiffness_N_per_mm"}) {
    EXPECT_TRUE(j["tir"].contains(k)) << k;
  }
  EXPECT_FALSE(j["dimensionless"].get<bool>());
  ASSERT_EQ(j["rows"].size(), 5u);
  for (const char* k : {"rho_mm", "load_N", "tir_load_N", "model_length_mm", "tir_length_mm",
                        "model_width_mm", "tir_width_mm"}) {
    EXPECT_TRUE(j["rows"][0].contains(k)) << k;
  }
  EXPECT_LT(j["rms_rel_diff"]["load"].get<double>(), 0.03);
  EXPECT_LT(j["rms_rel_diff"]["length"].get<double>(), 0.03);
  EXPECT_TRUE(j["rms_rel_diff"]["width"].is_null());
  EXPECT_FALSE(j["reasons"]["width"].get<std::string>().empty());
}

TEST_F(TirCli, OtherTyreSizeIsComparedDimensionless) {
  const CliRun c = run({"tir", "compare", kConfig, kData + "mfswift62_mm_kN.tir", "--points", "4"});
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NE(c.out.find("dimensionless"), std::string::npos) << c.out;
}

struct Refusal {
  const char* name;
  const char* file;
  const char* says;  ///< the expected "file:line: key" or sentence
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const Refusal& c, std::ostream* os) { *os << c.name; }

class TirCliRefuses : public modaltyre_test::CliFixture,
                      public ::testing::WithParamInterface<Refusal> {};

TEST_P(TirCliRefuses, WithExit2AndLocation) {
  const CliRun c = run({"tir", "compare", kConfig, kData + GetParam().file});
  EXPECT_EQ(c.exit_code, 2) << c.err;
  EXPECT_NE(c.err.find(GetParam().says), std::string::npos) << c.err;
  EXPECT_TRUE(c.out.empty()) << c.out;
}

INSTANTIATE_TEST_SUITE_P(
    Files, TirCliRefuses,
    ::testing::Values(
        Refusal{"FTire", "ftire_model.tir", "is an FTire tyre model file"},
        Refusal{"UnterminatedQuote", "bad_unterminated_quote.tir",
                "bad_unterminated_quote.tir:2: MDI_HEADER.FILE_TYPE: unterminated"},
        Refusal{"DuplicateKey", "bad_duplicate_key.tir",
                "bad_duplicate_key.tir:10: VERTICAL.FNOMIN"},
        Refusal{"NotANumber", "bad_stiffness_text.tir",
                "bad_stiffness_text.tir:9: VERTICAL.VERTICAL_STIFFNESS: '2.0.5e5' is not a number"},
        Refusal{"UnknownUnit", "bad_unit.tir", "bad_unit.tir:4: UNITS.LENGTH: unknown unit"},
        Refusal{"RaggedTable", "bad_table_row.tir", "bad_table_row.tir:12: DEFLECTION_LOAD_CURVE"},
        Refusal{"Missing", "no_such_file.tir", "file not found"}),
    [](const ::testing::TestParamInfo<Refusal>& info) { return info.param.name; });

TEST_F(TirCli, BadExportArgumentsWriteNothing) {
  const std::string out = (dir_ / "x.tir").string();
  CliRun c = run({"tir", "export", kConfig, "--output", out, "--loads", "1000", "2000"});
  EXPECT_EQ(c.exit_code, 2);
  EXPECT_NE(c.err.find("--loads"), std::string::npos) << c.err;
  c = run({"tir", "export", kConfig, "--output", out, "--fnomin", "-5"});
  EXPECT_EQ(c.exit_code, 2);
  EXPECT_NE(c.err.find("--fnomin"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
