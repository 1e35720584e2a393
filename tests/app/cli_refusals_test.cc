// Issue 38 items 3 to 5 at the command line: crashes and silent acceptances become exit 2 with a
// message naming file, line and key (OMP_NUM_THREADS, .tir coefficients, sections and FITTYP,
// non-UTF-8 text, hexadecimal numbers, NUL bytes and CR-only line ends); messages point at what
// is wrong (repeated export loads, output paths, a sweep as a sweep's base, FRFs given as hammer
// data); a user's own measurements with missing values and fewer rows are read or told the --set
// that fits them.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

namespace fs = std::filesystem;
using modaltyre_test::CliRun;

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;
using modaltyre_test::kSrc;
const std::string kTir = kSrc + "/tests/data/tir/mfswift62_mm_kN.tir";

class CliRefusals : public modaltyre_test::CliFixture {
 protected:
  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  /// The command with extra environment variables ("NAME=value"), under a 120 s limit.
  CliRun run_env(const std::vector<std::string>& env, const std::vector<std::string>& args) {
    std::string prefix = "env";
    for (const auto& e : env) prefix += " " + modaltyre_test::quote(e);
    return run_with(prefix + " timeout 120", args);
  }

  /// Exit 2 and every needle in the error message (after what the OpenMP runtime may print
  /// about the environment at start-up).
  static void refused(const CliRun& r, const std::vector<std::string>& needles) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_TRUE(r.err.rfind("error: ", 0) == 0 || r.err.find("\nerror: ") != std::string::npos)
        << r.err;
    for (const auto& n : needles) EXPECT_NE(r.err.find(n), std::string::npos) << n << "\n" << r.err;
  }

  /// A copy of the 2D config with `from` replaced by `to` (hammer_csv made absolute).
  std::string config_with(const std::string& from, const std::string& to) {
    std::string text = modaltyre_test::slurp(kConfig2d);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    const std::string rel = "data/sf350_hammer_12pt.csv";
    const auto h = text.find(rel);
    if (h != std::string::npos) text.replace(h, rel.size(), kSrc + "/configs/" + rel);
    return write("c.yaml", text);
  }
};

// OMP_NUM_THREADS=100000 crashed sweep and discover while starting threads: bounded like
// --threads, named, before anything runs.
TEST_F(CliRefusals, OmpNumThreadsOutOfRangeIsRefused) {
  const std::string sweep = kSrc + "/configs/sweeps/modulus_load_grid.yaml";
  const std::string out = (dir_ / "o.csv").string();
  refused(run_env({"OMP_NUM_THREADS=100000"}, {"sweep", sweep, "--output", out}),
          {"OMP_NUM_THREADS: 100000 threads is outside [1, 4096]"});
  EXPECT_FALSE(fs::exists(out));
  refused(run_env({"OMP_NUM_THREADS=100000"},
                  {"discover", kConfig2d, kSrc + "/configs/data/sf350_footprint_table3.csv"}),
          {"OMP_NUM_THREADS"});
  refused(run_env({"OMP_NUM_THREADS=0x10"}, {"footprint", kConfig2d, "--load", "4000"}),
          {"OMP_NUM_THREADS", "not a thread count"});
  const CliRun ok = run_env({"OMP_NUM_THREADS=2"}, {"sweep", sweep, "--output", out});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
}

// Hexadecimal numbers were read everywhere (strtod, CLI11, YAML 1.1): refused on the command
// line, in --set, in a config and in a CSV, each naming where.
TEST_F(CliRefusals, HexadecimalNumbersAreRefusedEverywhere) {
  refused(run({"footprint", kConfig2d, "--load", "0x1000"}), {"--load", "'0x1000'", "hexadecimal"});
  refused(run({"footprint", kConfig2d, "--load", "0x10p4"}), {"--load", "hexadecimal"});
  refused(run({"sweep", kSrc + "/configs/sweeps/modulus_load_grid.yaml", "--threads", "0x2"}),
          {"--threads", "hexadecimal"});
  refused(run({"footprint", kConfig2d, "--load", "4000", "--set", "tread.modulus_MPa=0x2"}),
          {"--set: tread.modulus_MPa", "hexadecimal"});
  const std::string cfg = config_with("modulus_MPa: ", "modulus_MPa: 0x1 #");
  refused(run({"footprint", cfg, "--load", "4000"}),
          {cfg + ":", "tread.modulus_MPa", "hexadecimal"});
  const std::string csv = write("m.csv", "load_N,sinking_mm\n2131,8\n0x853,12\n");
  refused(run({"validate", kConfig2d, csv}), {csv + ":3: load_N", "'0x853'", "hexadecimal"});
}

// A Latin-1 byte in tyre.name ended in "internal error ... invalid UTF-8" (exit 1); a NUL byte
// and CR-only line ends gave unrelated messages. Each is named at its line.
TEST_F(CliRefusals, TextThatIsNotUtf8TextIsRefusedAtItsLineAndKey) {
  const std::string latin1 = config_with("name: ", "name: Pneu caf\xE9 ");
  refused(run({"footprint", latin1, "--json"}), {latin1 + ":", ": tyre.name: ", "not UTF-8"});
  std::string text = modaltyre_test::slurp(kConfig2d);
  const std::string nul =
      write("nul.yaml", text.substr(0, 40) + std::string(1, '\0') + text.substr(40));
  refused(run({"footprint", nul}), {nul + ":", "NUL byte"});
  std::string cr = text;
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  const std::string cr_yaml = write("cr.yaml", cr);
  refused(run({"footprint", cr_yaml}), {cr_yaml + ":1", "carriage return"});
  std::string tir = modaltyre_test::slurp(kTir);
  std::replace(tir.begin(), tir.end(), '\n', '\r');
  const std::string cr_tir = write("cr.tir", tir);
  refused(run({"tir", "compare", kConfig3d, cr_tir}), {cr_tir + ":1", "carriage return"});
}

// .tir: a negative Q_RA1 gave negative contact lengths, FITTYP = 999 passed as Magic Formula,
// a repeated [VERTICAL] with another FNOMIN was silently dropped.
TEST_F(CliRefusals, TirCoefficientsVersionAndRepeatedSectionsAreChecked) {
  const std::string tir = modaltyre_test::slurp(kTir);
  const auto edit = [&](const std::string& name, const std::string& from, const std::string& to) {
    std::string t = tir;
    const auto at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    t.replace(at, from.size(), to);
    return write(name, t);
  };
  const std::string qra1 = edit("qra1.tir", "Q_RA1                    = 0.65", "Q_RA1 = -0.65");
  refused(run({"tir", "compare", kConfig3d, qra1}), {qra1 + ":", "CONTACT_PATCH.Q_RA1", "outside"});
  const std::string fit = edit("fittyp.tir", "FITTYP                   = 62", "FITTYP = 999");
  refused(run({"tir", "compare", kConfig3d, fit}), {fit + ":", "MODEL.FITTYP", "999"});
  const std::string twice = write("twice.tir", tir + "[VERTICAL]\nFNOMIN = 9.9\n");
  refused(run({"tir", "compare", kConfig3d, twice}),
          {twice + ":", "VERTICAL: section [VERTICAL] given again with other contents"});
}

// Messages that pointed the wrong way (issue 38 item 5).
TEST_F(CliRefusals, MessagesNameWhatIsWrong) {
  // Three equal export loads: a degenerate fit (exit 1) before; now the option is named.
  refused(run({"tir", "export", kConfig2d, "--output", (dir_ / "t.tir").string(), "--loads", "4000",
               "4000", "4000"}),
          {"--loads", "3 different loads"});
  // An output in a folder that does not exist blamed modal.hammer_csv.
  const std::string rheo = kSrc + "/tests/data/rheology/";
  refused(run({"identify", "free-vibration", rheo + "free_vibration.csv", "--mass-kg", "350",
               "--section-height-mm", "117", "--static", rheo + "static_loop.csv", "--into-config",
               kConfig2d, "--out-config", "nodir/x.yaml"}),
          {"--out-config", "output folder", "does not exist"});
  // An empty output path failed after the computation without a path (or fell back to the
  // sweep file's output:).
  refused(run({"tir", "export", kConfig2d, "--output", ""}), {"--output", "an empty path"});
  refused(run({"sweep", kSrc + "/configs/sweeps/modulus_load_grid.yaml", "--output", ""}),
          {"--output", "an empty path"});
  refused(run({"footprint", kConfig2d, "--plot", dir_.string()}), {"--plot", "is a directory"});
  // A sweep whose base: is a sweep said "modal.hammer_csv: required".
  const std::string inner =
      write("inner.yaml", "base: " + kConfig2d + "\ngrid:\n  load_N: [3000]\noutput: i.csv\n");
  const std::string outer =
      write("outer.yaml", "base: inner.yaml\ngrid:\n  load_N: [4000]\noutput: o.csv\n");
  refused(run({"sweep", outer}), {outer + ":1: base", "is a sweep file", "not a tyre config"});
  // hammer_csv pointing at FRFs said "unknown column -1".
  const std::string unv = kSrc + "/tests/data/ema/fixed_columns.unv";
  const std::string cfg =
      config_with("hammer_csv: data/sf350_hammer_12pt.csv", "hammer_csv: " + unv);
  refused(run({"footprint", cfg, "--load", "4000"}), {unv + ":1", "a UFF file", "modaltyre ema"});
  // A UFF file saved with a byte-order mark is read (it gave "expected '-1'").
  const std::string bom = write("bom.unv", "\xEF\xBB\xBF" + modaltyre_test::slurp(unv));
  const CliRun b = run({"ema", bom, "--max-order", "4", "--unscaled", "--json"});
  EXPECT_EQ(b.err.find("expected '    -1'"), std::string::npos) << b.err;
}

// A new user's file: missing values (empty, NA) are read per row; fewer rows than the config's
// calibration block name the --set that fits the file.
TEST_F(CliRefusals, OwnMeasurementsWithMissingValuesAndFewRows) {
  const std::string few =
      write("few.csv", "load_N,sinking_mm\n2000,7\n4000,13\n6000,19\n8000,26\n");
  refused(
      run({"validate", kConfig3d, few}),
      {"validation.calibration_rows: row 6 does not exist",
       "--set validation.calibration_rows=[1,4]",
       "--set validation.calibration_observables=[sinking_mm]", "--set validation.calibrate=[]"});
  const CliRun ok = run({"validate", kConfig3d, few, "--set", "validation.calibrate=[]"});
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  const std::string gaps = write("gaps.csv",
                                 "load_N,sinking_mm,length_mm\n2131,8,86\n3261,NA,112\n5478,20,\n"
                                 "6502,23,126\n7322,26,NA\n8321,29,135\n");
  const CliRun g = run({"validate", kConfig2d, gaps});
  ASSERT_EQ(g.exit_code, 0) << g.err;
  // Rows 2-5 are predictions; row 2 lacks the sinking, rows 3 and 5 the length.
  EXPECT_NE(g.out.find("% (2 rows)  sinking_mm"), std::string::npos) << g.out;
  EXPECT_NE(g.out.find("% (3 rows)\n"), std::string::npos) << g.out;
  const std::string none = write("none.csv", "load_N,sinking_mm\n2131,8\n3261,NA\n");
  refused(run({"validate", kConfig2d, none}), {none + ":3: sinking_mm", "no measured value"});
}

// Closed-form values say so instead of "std_error 0"; no "-0" in a table.
TEST_F(CliRefusals, ClosedFormAndNoNegativeZero) {
  const CliRun r = run({"identify", "b-factors"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("closed form"), std::string::npos) << r.out;
  const CliRun j = run({"identify", "b-factors", "--json"});
  EXPECT_NE(j.out.find("\"closed_form\": true"), std::string::npos) << j.out;
  const CliRun v =
      run({"validate", kConfig2d, kSrc + "/configs/data/sf350_footprint_table3.csv", "--json"});
  EXPECT_EQ(v.out.find("-0.0,"), std::string::npos);
  EXPECT_EQ(v.out.find(": -0,"), std::string::npos);
}

}  // namespace
