// `modaltyre discover` end to end against issue 9's input contract: bad measured files, bad
// options and bad configs exit 2 with one message naming file, line and column (or key) and
// leave no output file behind; a small valid data set gives the documented JSON (finite numbers
// only) and an augmented config that `modaltyre footprint` accepts.
//
// The valid runs use 5 rows of the SF-350's Table 3 on a 4 mm mesh with one effect round: a few
// seconds each. Every refusal below happens before any fitting.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;
using modaltyre_test::slurp;

using modaltyre_test::kConfig2d;
using modaltyre_test::kLeteSandYaml;
using modaltyre_test::kTable3;

class DiscoverCli : public modaltyre_test::CliFixture {
 protected:
  std::string write(const std::string& content, const std::string& name = "measured.csv") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  /// Header and the first `rows` data rows of Table 3.
  std::string table3(std::size_t rows) {
    std::istringstream in(slurp(kTable3));
    std::string line, out;
    std::size_t n = 0;
    while (std::getline(in, line) && n <= rows) {
      if (line.empty() || line[0] == '#') continue;
      out += line + "\n";
      ++n;
    }
    EXPECT_EQ(n, rows + 1) << kTable3 << " has fewer rows than the test needs";
    return out;
  }

  /// discover on `measured` with the fast settings, then `extra`.
  CliRun discover(const std::string& measured, const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args{"discover", kConfig2d,       measured, "--unit-length-mm",
                                  "4",        "--max-effects", "1",      "--threads",
                                  "2"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run(args);
  }

  /// Exit 2, one "error:" line naming every needle, nothing on stdout, no internal error.
  static void expect_input_error(const CliRun& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << "\n" << r.err;
  }

  /// Only the runner's own capture files are left in the test folder.
  void expect_nothing_written() {
    for (const auto& e : fs::directory_iterator(dir_)) {
      const std::string name = e.path().filename().string();
      EXPECT_TRUE(name == "stdout.txt" || name == "stderr.txt" || name == "measured.csv")
          << "left behind: " << name;
    }
  }
};

TEST_F(DiscoverCli, BadMeasuredFileNamesFileLineAndColumn) {
  const std::string h = "load_N,sinking_mm,width_mm,length_mm\n";
  const std::string ok = "2131,8,104,86\n3261,12,123,112\n";
  struct Case {
    std::string content;
    std::string line, column;
  };
  const std::vector<Case> cases = {
      {h + ok + "5478,twenty,142,117\n" + ok, "4", "sinking_mm"},
      {h + ok + "5478,20,142,nan\n" + ok, "4", "length_mm"},
      {h + ok + ok + "0,20,142,117\n", "6", "load_N"},
      {h + ok + "5478,20,-142,117\n" + ok, "4", "width_mm"},
      {"load_N,sinkng_mm,width_mm,length_mm\n" + ok + ok, "1", "sinkng_mm"},
      {"sinking_mm,width_mm,length_mm\n8,104,86\n", "1", "load_N"},
      {"load_N,branch,sinking_mm\n2131,load,8\n3261,sideways,12\n5478,load,20\n6502,load,23\n", "3",
       "branch"},
      {"load_N,sinking_mm,status,message\n2131,8,ok,converged\n150,,failed,did not converge\n"
       "5478,20,ok,converged\n6502,23,ok,converged\n",
       "3", "status"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.content);
    const std::string p = write(c.content);
    expect_input_error(discover(p), {p + ":" + c.line + ": " + c.column + ": "});
  }
}

TEST_F(DiscoverCli, FewerThanFourRowsExitsTwo) {
  const std::string p = write(table3(3));
  expect_input_error(discover(p), {p, "at least 4 measured rows", "3 given"});
}

TEST_F(DiscoverCli, TooManyUnitsExitsTwoAndWritesNothing) {
  const std::string p = write(table3(5));
  const std::string cfg = (dir_ / "out.yaml").string();
  const CliRun r =
      run({"discover", kConfig2d, p, "--unit-length-mm", "0.001", "--out-config", cfg});
  expect_input_error(r, {"--unit-length-mm", "at most 20000"});
  expect_nothing_written();
  // Outside the option's range at all, and not a number: usage errors.
  for (const char* bad : {"-1", "51", "nan", "four"}) {
    const CliRun u = run({"discover", kConfig2d, p, "--unit-length-mm", bad});
    EXPECT_EQ(u.exit_code, 2) << bad << ": " << u.err;
    EXPECT_NE(u.err.find("--unit-length-mm"), std::string::npos) << bad << ": " << u.err;
    EXPECT_TRUE(u.out.empty()) << bad;
  }
}

TEST_F(DiscoverCli, OutputInAMissingFolderExitsTwoAndWritesNothing) {
  const std::string p = write(table3(5));
  const std::string missing = (dir_ / "no_such_folder").string();
  const std::string good_cfg = (dir_ / "out.yaml").string();
  const std::string good_plot = (dir_ / "plot.svg").string();
  // A bad plot path must not leave a written config, nor a bad config path a plot.
  const std::string bad_plot = missing + "/plot.svg";
  expect_input_error(discover(p, {"--plot", bad_plot, "--out-config", good_cfg}),
                     {bad_plot, "does not exist"});
  const std::string bad_cfg = missing + "/out.yaml";
  expect_input_error(discover(p, {"--plot", good_plot, "--out-config", bad_cfg}),
                     {bad_cfg, "does not exist"});
  EXPECT_FALSE(fs::exists(missing));
  expect_nothing_written();
}

TEST_F(DiscoverCli, UnusableOutputPathIsRefusedBeforeFitting) {
  const std::string p = write(table3(5));
  const std::string cfg = (dir_ / "out.yaml").string();
  // A plot that is not .svg/.png, and an output path that is a folder.
  const std::string txt = (dir_ / "plot.txt").string();
  expect_input_error(discover(p, {"--plot", txt, "--out-config", cfg}), {txt, ".svg or .png"});
  expect_nothing_written();
  const fs::path folder = dir_ / "out_is_a_folder.yaml";
  fs::create_directories(folder);
  expect_input_error(discover(p, {"--out-config", folder.string()}),
                     {folder.string(), "directory"});
  fs::remove(folder);
  expect_nothing_written();
}

TEST_F(DiscoverCli, BadEffectSettingsExitTwoNamingTheKey) {
  const std::string p = write(table3(5));
  expect_input_error(discover(p, {"--set", "effects.nonsense.enabled=true"}),
                     {"--set", "effects.nonsense"});
  expect_input_error(discover(p, {"--set", "effects.tread_relaxation.enabled=true", "--set",
                                  "effects.tread_relaxation.creep_ratio=50"}),
                     {"effects.tread_relaxation.creep_ratio"});
  expect_input_error(discover(p, {"--set", "effects.tread_relaxation.creep_ratio=abc"}),
                     {"effects.tread_relaxation.creep_ratio"});
  expect_input_error(discover(p, {"--set", "effects.dry_friction.enabled=maybe"}),
                     {"effects.dry_friction.enabled"});
  expect_nothing_written();
}

TEST_F(DiscoverCli, JsonOnASmallDataSetAndTheAugmentedConfigRuns) {
  const std::string p = write(table3(5));
  const std::string cfg = (dir_ / "augmented.yaml").string();
  const CliRun r = discover(p, {"--json", "--out-config", cfg});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Numbers only: a NaN or inf would not parse as JSON (nor be printed as a bare word).
  EXPECT_FALSE(
      std::regex_search(r.out, std::regex(R"(\b-?(nan|inf|infinity)\b)", std::regex::icase)))
      << r.out;
  nlohmann::json j;
  ASSERT_NO_THROW(j = nlohmann::json::parse(r.out)) << r.out;
  EXPECT_EQ(j["rows"], 5);
  for (const char* k : {"gap_before", "gap_after"}) {
    ASSERT_TRUE(j.contains(k) && j[k].is_object()) << k;
    for (const char* o : {"sinking_mm", "width_mm", "length_mm"}) {
      ASSERT_TRUE(j[k].contains(o)) << k << " " << o;
      EXPECT_TRUE(j[k][o].is_number()) << k << " " << o;
      EXPECT_GE(j[k][o].get<double>(), 0) << k << " " << o;
    }
  }
  ASSERT_TRUE(j.contains("regime"));
  EXPECT_TRUE(j["regime"]["variable"].is_string());
  ASSERT_TRUE(j["regime"]["correlation"].is_number());
  EXPECT_LE(std::abs(j["regime"]["correlation"].get<double>()), 1.0);
  ASSERT_TRUE(j["effects"].is_array());
  EXPECT_LE(j["effects"].size(), 1u);  // --max-effects 1
  for (const auto& e : j["effects"]) {
    EXPECT_TRUE(e["name"].is_string());
    // Each fitted value inside its band (profile likelihood, two standard errors).
    for (const auto& [key, value] : e["parameters"].items()) {
      const auto& b = e["bands_two_standard_errors"][key];
      EXPECT_LE(b["lower"].get<double>(), value.get<double>()) << e;
      EXPECT_GE(b["upper"].get<double>(), value.get<double>()) << e;
      // The band with the mesh's share holds the noise band (mesh_bias.h).
      const auto& m = e["bands_with_mesh"][key];
      EXPECT_LE(m["lower"].get<double>(), b["lower"].get<double>()) << e;
      EXPECT_GE(m["upper"].get<double>(), b["upper"].get<double>()) << e;
      EXPECT_TRUE(e["mesh_shift"]["shift"][key].is_number()) << e;
    }
    EXPECT_NEAR(e["mesh_shift"]["fine_unit_length_mm"].get<double>(),
                0.5 * e["mesh_shift"]["unit_length_mm"].get<double>(),
                1e-5 * e["mesh_shift"]["unit_length_mm"].get<double>())
        << e;
    // The predictions' change and the residual it is weighed against, and the verdict's rule.
    const double change = e["mesh_shift"]["prediction_change_rms"].get<double>();
    const double residual = e["mesh_shift"]["residual_rms"].get<double>();
    EXPECT_GE(change, 0) << e;
    EXPECT_GT(residual, 0) << e;
    EXPECT_EQ(e["mesh_shift"]["mesh_is_coarse"].get<bool>(), 2 * change >= 0.5 * residual) << e;
  }
  ASSERT_TRUE(j["candidates"].is_array());
  ASSERT_FALSE(j["candidates"].empty());
  for (const auto& c : j["candidates"]) {
    ASSERT_TRUE(c["name"].is_string());
    if (c["testable"].get<bool>()) {
      EXPECT_TRUE(c["delta_bic"].is_number()) << c;
    } else {
      EXPECT_FALSE(c["reason"].get<std::string>().empty()) << c;
    }
    // One round: every candidate carries its detection limit, or null and the reason.
    ASSERT_TRUE(c.contains("detection_limit")) << c;
    if (c["detection_limit"].is_null()) {
      EXPECT_FALSE(c["detection_limit_reason"].get<std::string>().empty()) << c;
    } else {
      const auto& l = c["detection_limit"];
      // One of the candidate's own fitted keys (effects.NAME.*, or an option's key).
      EXPECT_TRUE(c["parameters"].contains(l["parameter"].get<std::string>())) << c;
      EXPECT_GT(l["value"].get<double>(), 0) << c;
      ASSERT_FALSE(l["observable_rms_rel"].empty()) << c;
      for (const auto& kv : l["observable_rms_rel"].items())
        EXPECT_GE(kv.value().get<double>(), 0) << c;
      EXPECT_GE(c["power_at_default"].get<double>(), 0) << c;
      EXPECT_LE(c["power_at_default"].get<double>(), 1) << c;
      // A two-sided effect's limit below its neutral value lies below the one above it.
      if (l.contains("below_neutral") && l["below_neutral"]["value"].is_number()) {
        EXPECT_LT(l["below_neutral"]["value"].get<double>(), l["value"].get<double>()) << c;
      }
    }
  }
  EXPECT_EQ(j["out_config"], cfg);

  // The augmented config is a config the other commands accept.
  ASSERT_TRUE(fs::is_regular_file(cfg));
  const CliRun f = run({"footprint", cfg, "--load", "4000", "--json"});
  ASSERT_EQ(f.exit_code, 0) << f.err << "\n" << slurp(cfg);
  const auto fj = nlohmann::json::parse(f.out);
  EXPECT_TRUE(fj["cases"][0]["converged"].get<bool>());
}

// ---- traction rows (docs/discover.md, "Traction rows") --------------------------------------

// One load's curve on LETE sand as `traction` gives it on the 2D variant (no flexing loss).
const std::string kCurve =
    "load_N,slip,drawbar_pull_N,soil_sinkage_mm,torque_Nm,speed_kmh\n"
    "3000,0.05,341,16.5,178,0\n3000,0.1,647,17.3,269,0\n3000,0.2,998,19.0,376,0\n"
    "3000,0.3,1161,20.8,429,0\n3000,0.5,1264,24.9,471,0\n";

TEST_F(DiscoverCli, HostileTractionRowsExit2NamingFileLineAndColumn) {
  const std::string ground = "--ground";
  // Traction columns mixed wrongly: a footprint observable in a row with a slip.
  std::string p = write("load_N,sinking_mm,slip,drawbar_pull_N\n3000,,0.1,600\n3000,15,0.2,900\n");
  expect_input_error(discover(p, {ground, kLeteSandYaml}),
                     {p + ":3: sinking_mm: ", "traction row"});
  // Slip in per cent, NaN in a pull.
  p = write("load_N,slip,drawbar_pull_N\n3000,0.1,600\n3000,20,900\n");
  expect_input_error(discover(p, {ground, kLeteSandYaml}), {p + ":3: slip: ", "[-1, 1]"});
  p = write("load_N,slip,drawbar_pull_N\n3000,0.1,600\n3000,0.2,nan\n");
  expect_input_error(discover(p, {ground, kLeteSandYaml}),
                     {p + ":3: drawbar_pull_N: ", "not a finite number"});
  // Traction rows with no soil to roll on (the 2D config has none) name the key.
  p = write(kCurve);
  expect_input_error(discover(p), {"ground.model", "need a soil"});
  expect_nothing_written();
}

TEST_F(DiscoverCli, TractionCurvePlotsPullAndSinkageAgainstSlip) {
  const std::string p = write(kCurve);
  const std::string png = (dir_ / "curve.png").string();
  const CliRun r = discover(p, {"--ground", kLeteSandYaml, "--plot", png, "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["traction_cases"].get<long>(), 0);
  EXPECT_TRUE(j["gap_before"].contains("drawbar_pull_N"));
  EXPECT_TRUE(j["gap_before"].contains("soil_sinkage_mm"));
  ASSERT_TRUE(fs::is_regular_file(png));
  EXPECT_GT(fs::file_size(png), 1000u);
}

}  // namespace
