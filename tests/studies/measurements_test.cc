// read_measurements() against the hostile inputs of issue 9: every refusal is an InputError
// whose message names the file, the line and the column; what is legitimate (a sweep's extra
// columns, CRLF line endings, repeated measurements) is read, and read completely.
#include "modaltyre/studies/measurements.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../support/table3_tyre.h"
#include "modaltyre/core/errors.h"

namespace {

namespace fs = std::filesystem;
using namespace modaltyre::contact;
using namespace modaltyre::studies;
using modaltyre::InputError;


using modaltyre_test::table3_tyre;

class Measurements : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("modaltyre_measurements_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& content, const std::string& name = "measured.csv") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  MeasurementSet read(const std::string& content) {
    return read_measurements(write(content), table3_tyre());
  }

  /// `content` must be refused with an InputError at (line, column) whose message names
  /// file:line, the column and contains `reason`.
  void expect_refused(const std::string& content, int line, const std::string& column,
                      const std::string& reason) {
    const std::string path = write(content);
    try {
      const MeasurementSet s = read_measurements(path, table3_tyre());
      ADD_FAILURE() << "accepted (" << s.rows.size() << " rows):\n" << content;
    } catch (const InputError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(e.where().file, path) << msg;
      EXPECT_EQ(e.where().line, line) << msg;
      EXPECT_EQ(e.where().key, column) << msg;
      EXPECT_NE(msg.find(path + ":" + std::to_string(line) + ": " + column + ": "),
                std::string::npos)
          << msg;
      EXPECT_NE(msg.find(reason), std::string::npos) << "want '" << reason << "' in: " << msg;
    }
  }

  fs::path dir_;
};

const std::string kHeader = "load_N,sinking_mm,length_mm,width_mm\n";
const std::string kRow = "4000,15,110,130\n";

// A valid file with one cell of `column` replaced on data row 2 (file line 3).
std::string with_cell(const std::string& header, const std::string& row, const std::string& bad) {
  return header + row + bad + row;
}

TEST_F(Measurements, ValidFileIsReadWithLinesAndDefaults) {
  const auto s = read("# comment\n" + kHeader + "\n" + kRow + "6000,20,120,140\n");
  ASSERT_EQ(s.rows.size(), 2u);
  EXPECT_EQ(s.rows[0].row, 1);
  EXPECT_EQ(s.rows[0].line, 4);  // comment and blank lines still count
  EXPECT_EQ(s.rows[1].line, 5);
  EXPECT_EQ(s.rows[1].conditions.load_N, 6000);
  EXPECT_EQ(s.rows[1].observed.at("length_mm"), 120);
  EXPECT_EQ(s.observables, (std::vector<std::string>{"sinking_mm", "length_mm", "width_mm"}));
  EXPECT_EQ(s.conditions, (std::vector<std::string>{"load_N"}));
  // Absent condition columns take the config's values.
  EXPECT_EQ(s.rows[0].conditions.pressure_kPa, table3_tyre().default_conditions(4000).pressure_kPa);
  EXPECT_EQ(s.rows[0].conditions.branch, Branch::loading);
}

TEST_F(Measurements, EmptyFileAndHeaderOnlyAreRefusedNamingTheFile) {
  // Whole-file problems: no line or column to name beyond the file itself.
  for (const std::string& content : {std::string(), std::string("# only a comment\n\n")}) {
    const std::string path = write(content);
    try {
      read_measurements(path, table3_tyre());
      ADD_FAILURE() << "empty file accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
    }
  }
  const std::string path = write(kHeader);
  try {
    read_measurements(path, table3_tyre());
    ADD_FAILURE() << "header-only file accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no data rows"), std::string::npos) << e.what();
  }
}

TEST_F(Measurements, MissingLoadColumn) {
  expect_refused("sinking_mm,length_mm\n15,110\n", 1, "load_N", "required column");
}

TEST_F(Measurements, NoObservableColumn) {
  expect_refused("load_N,pressure_kPa\n4000,230\n", 1, "sinking_mm", "no observable column");
}

TEST_F(Measurements, UnknownOrMisspeltColumn) {
  expect_refused("load_N,sinkng_mm,length_mm\n4000,15,110\n", 1, "sinkng_mm", "unknown column");
  // Header after a comment: the line is the header's.
  expect_refused("# bench 3\nload_N,length_mm,Pressure_kPa\n4000,110,230\n", 2, "Pressure_kPa",
                 "unknown column");
  expect_refused("load_N,sinking_mm,sinking_mm\n4000,15,15\n", 1, "sinking_mm", "twice");
}

TEST_F(Measurements, SweepOutputColumnsAreAcceptedAndIgnored) {
  const auto s = read(
      "tread.modulus_MPa,effects.tread_relaxation.enabled,load_N,hold_s,sinking_mm,length_mm,"
      "width_mm,rolling_resistance_N,vertical_stiffness_N_mm,peak_pressure_kPa,iterations,"
      "status,message\n"
      "2.329,true,3000,45,12.5,101,128,0,240,310,7,ok,converged in 7 active-set iterations\n"
      "3,true,6000,45,19.25,121,139,0,311.7,402,9,ok,converged in 9 active-set iterations\n");
  ASSERT_EQ(s.rows.size(), 2u);
  EXPECT_EQ(s.observables, (std::vector<std::string>{"sinking_mm", "length_mm", "width_mm",
                                                     "rolling_resistance_N"}));
  EXPECT_EQ(s.conditions, (std::vector<std::string>{"load_N", "hold_s"}));
  EXPECT_EQ(s.rows[1].conditions.load_N, 6000);
  EXPECT_EQ(s.rows[1].conditions.hold_s, 45);
  EXPECT_EQ(s.rows[1].observed.at("sinking_mm"), 19.25);
  EXPECT_EQ(s.rows[0].observed.at("rolling_resistance_N"), 0);  // 0 N is a measurement
  EXPECT_EQ(s.rows[0].observed.size(), 4u) << "by-products must not become observables";
}

TEST_F(Measurements, FailedSweepRowIsRefusedNamingItsLine) {
  const std::string header =
      "load_N,sinking_mm,length_mm,width_mm,rolling_resistance_N,vertical_stiffness_N_mm,"
      "peak_pressure_kPa,iterations,status,message\n";
  const std::string ok = "3000,12.5,101,128,0,240,310,7,ok,converged\n";
  // The row as `modaltyre sweep` writes it for a failed case: empty numbers.
  expect_refused(header + ok + ok + "150,,,,,,,,failed,load 150 N does not exceed the friction\n",
                 4, "status", "remove failed sweep rows");
  // Numbers present but the status says it failed.
  expect_refused(header + ok + "3000,12.5,101,128,0,240,310,7,failed,did not converge\n" + ok, 3,
                 "status", "failed");
}

TEST_F(Measurements, TextInANumberColumn) {
  expect_refused(with_cell(kHeader, kRow, "4000,fifteen,110,130\n"), 3, "sinking_mm",
                 "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "4000,15,110,13O\n"), 3, "width_mm",
                 "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "4 kN,15,110,130\n"), 3, "load_N", "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "4000,NA-ish,110,130\n"), 3, "sinking_mm",
                 "not a finite number");
}

// A value not measured in a row (empty cell, NA or N/A: R's and spreadsheets' marks) leaves that
// observable out of the row; the row keeps the others (issue 38). A row with none is refused.
TEST_F(Measurements, MissingValuesArePerRow) {
  const MeasurementSet s =
      read(kHeader + std::string("4000,,110,130\n4000,15,NA,130\n") + "4000,15,110,N/A\n");
  ASSERT_EQ(s.rows.size(), 3u);
  EXPECT_FALSE(s.rows[0].value("sinking_mm").has_value());
  EXPECT_EQ(*s.rows[0].value("length_mm"), 110);
  EXPECT_FALSE(s.rows[1].value("length_mm").has_value());
  EXPECT_FALSE(s.rows[2].value("width_mm").has_value());
  EXPECT_EQ(s.observables.size(), 3u);
  expect_refused(kHeader + std::string("4000,15,110,130\n4000,NA,,N/A\n"), 3, "sinking_mm",
                 "no measured value in this row");
  expect_refused(with_cell(kHeader, kRow, "NA,15,110,130\n"), 3, "load_N",
                 "not a finite number");  // a condition is never missing
}

TEST_F(Measurements, NaNAndInfinity) {
  expect_refused(with_cell(kHeader, kRow, "nan,15,110,130\n"), 3, "load_N", "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "4000,NaN,110,130\n"), 3, "sinking_mm",
                 "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "4000,15,inf,130\n"), 3, "length_mm",
                 "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "4000,15,110,-Infinity\n"), 3, "width_mm",
                 "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "1e999,15,110,130\n"), 3, "load_N",
                 "not a finite number");
}

TEST_F(Measurements, ZeroOrNegativeLoad) {
  expect_refused(with_cell(kHeader, kRow, "0,15,110,130\n"), 3, "load_N", "[1e-6, 1e7] N");
  expect_refused(with_cell(kHeader, kRow, "-4000,15,110,130\n"), 3, "load_N", "[1e-6, 1e7] N");
  expect_refused(with_cell(kHeader, kRow, "1e-300,15,110,130\n"), 3, "load_N", "[1e-6, 1e7] N");
}

TEST_F(Measurements, ZeroOrNegativeSinkingLengthWidth) {
  expect_refused(with_cell(kHeader, kRow, "4000,0,110,130\n"), 3, "sinking_mm", "> 0");
  expect_refused(with_cell(kHeader, kRow, "4000,-15,110,130\n"), 3, "sinking_mm", "> 0");
  expect_refused(with_cell(kHeader, kRow, "4000,15,0,130\n"), 3, "length_mm", "> 0");
  expect_refused(with_cell(kHeader, kRow, "4000,15,-110,130\n"), 3, "length_mm", "> 0");
  expect_refused(with_cell(kHeader, kRow, "4000,15,110,0\n"), 3, "width_mm", "> 0");
  expect_refused(with_cell(kHeader, kRow, "4000,15,110,-0.5\n"), 3, "width_mm", "> 0");
}

TEST_F(Measurements, ConditionRanges) {
  const std::string h = "load_N,pressure_kPa,hold_s,speed_kmh,sinking_mm\n";
  const std::string r = "4000,230,0,0,15\n";
  expect_refused(with_cell(h, r, "4000,230,-1,0,15\n"), 3, "hold_s", "[0, 1e7] s");
  expect_refused(with_cell(h, r, "4000,230,1e308,0,15\n"), 3, "hold_s", "[0, 1e7] s");
  expect_refused(with_cell(h, r, "4000,0,0,0,15\n"), 3, "pressure_kPa", "(0, 2000]");
  expect_refused(with_cell(h, r, "4000,-230,0,0,15\n"), 3, "pressure_kPa", "(0, 2000]");
  expect_refused(with_cell(h, r, "4000,2000.5,0,0,15\n"), 3, "pressure_kPa", "(0, 2000]");
  expect_refused(with_cell(h, r, "4000,230,0,400.5,15\n"), 3, "speed_kmh", "[0, 400]");
  expect_refused(with_cell(h, r, "4000,230,0,-10,15\n"), 3, "speed_kmh", "[0, 400]");
  // The limits themselves are accepted.
  const auto s = read(h + "4000,2000,0,400,15\n");
  EXPECT_EQ(s.rows.at(0).conditions.pressure_kPa, 2000);
  EXPECT_EQ(s.rows.at(0).conditions.speed_kmh, 400);
}

TEST_F(Measurements, UnknownBranchAndSurfaceWords) {
  const std::string h = "load_N,branch,surface,sinking_mm\n";
  const std::string r = "4000,load,rigid,15\n";
  expect_refused(with_cell(h, r, "4000,sideways,rigid,15\n"), 3, "branch", "load, unload");
  expect_refused(with_cell(h, r, "4000,Load,rigid,15\n"), 3, "branch", "load, unload");
  expect_refused(with_cell(h, r, "4000,unload,gravel,15\n"), 3, "surface", "rigid, soil");
  expect_refused(with_cell(h, r, "4000,load,,15\n"), 3, "surface", "empty cell");
  const auto s = read(h + "4000,unloading,soil,15\n4000,load,rigid,15\n");
  EXPECT_EQ(s.rows.at(0).conditions.branch, Branch::unloading);
  EXPECT_EQ(s.rows.at(0).conditions.surface, Surface::soil);
  EXPECT_EQ(s.rows.at(1).conditions.branch, Branch::loading);
}

TEST_F(Measurements, NonUtf8BytesInACell) {
  expect_refused(with_cell(kHeader, kRow, "4000,\xff\xfe,110,130\n"), 3, "sinking_mm",
                 "not a finite number");
  expect_refused(with_cell(kHeader, kRow, "4000,15\xe9,110,130\n"), 3, "sinking_mm",
                 "not a finite number");
  const std::string h = "load_N,branch,sinking_mm\n";
  expect_refused(with_cell(h, "4000,load,15\n", "4000,lo\xe9\x61\x64,15\n"), 3, "branch",
                 "load, unload");
  // Control bytes: the line is named (not a text CSV).
  const std::string path = write(kHeader + kRow + std::string("4000,15\0,110,130\n", 17));
  try {
    read_measurements(path, table3_tyre());
    ADD_FAILURE() << "NUL byte accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":3"), std::string::npos) << e.what();
  }
}

TEST_F(Measurements, DirectoryOrMissingFileIsRefusedNamingIt) {
  const std::string d = (dir_ / "folder.csv").string();
  fs::create_directories(d);
  try {
    read_measurements(d, table3_tyre());
    ADD_FAILURE() << "a directory was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(d), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("directory"), std::string::npos) << e.what();
  }
  const std::string missing = (dir_ / "absent.csv").string();
  try {
    read_measurements(missing, table3_tyre());
    ADD_FAILURE() << "a missing file was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not found"), std::string::npos) << e.what();
  }
}

TEST_F(Measurements, PipeIsRefusedNotWaitedOn) {
  // Nothing ever writes to the FIFO: reading it would block for ever.
  const std::string fifo = (dir_ / "pipe.csv").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    read_measurements(fifo, table3_tyre());
    ADD_FAILURE() << "a pipe was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fifo), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

TEST_F(Measurements, WrongFieldCountNamesTheLine) {
  const std::string path = write(kHeader + kRow + "4000,15,110\n");
  try {
    read_measurements(path, table3_tyre());
    ADD_FAILURE() << "short row accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(std::string(e.what()).find(path + ":3"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("3 fields"), std::string::npos) << e.what();
  }
}

TEST_F(Measurements, CrlfLineEndingsAreAccepted) {
  const auto s = read(
      "\xEF\xBB\xBFtread.modulus_MPa,load_N,branch,sinking_mm,status\r\n"
      "2.329,4000,unload,15,ok\r\n"
      "\r\n"
      "2.329,6000,load,20,ok\r\n");
  ASSERT_EQ(s.rows.size(), 2u);
  EXPECT_EQ(s.rows[0].conditions.branch, Branch::unloading);
  EXPECT_EQ(s.rows[1].conditions.branch, Branch::loading);
  EXPECT_EQ(s.rows[1].line, 4);
  EXPECT_EQ(s.rows[1].observed.at("sinking_mm"), 20);
  // And a refusal in a CRLF file still names the line and column.
  expect_refused("load_N,sinking_mm\r\n4000,15\r\n4000,-1\r\n", 3, "sinking_mm", "> 0");
}

TEST_F(Measurements, HeaderWithSpacesAndLeadingBlankLineKeepsSweepColumns) {
  // A spreadsheet's ", " separators and a whitespace-only first line: the dotted config-key
  // column is the same column read_csv sees, so it is accepted like any other sweep column.
  const auto s = read(
      "   \n"
      "load_N, tread.modulus_MPa, sinking_mm\n"
      "4000, 2.329, 15\n");
  ASSERT_EQ(s.rows.size(), 1u);
  EXPECT_EQ(s.rows[0].line, 3);
  EXPECT_EQ(s.rows[0].observed.at("sinking_mm"), 15);
}

TEST_F(Measurements, DuplicatedRowsAreKept) {
  // Repeated measurements at the same conditions are legitimate data, not a mistake.
  const auto s = read(kHeader + kRow + kRow + kRow + "6000,20,120,140\n");
  ASSERT_EQ(s.rows.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(s.rows[i].row, i + 1);
    EXPECT_EQ(s.rows[i].line, i + 2);
    EXPECT_EQ(s.rows[i].conditions.load_N, 4000);
    EXPECT_EQ(s.rows[i].observed.at("sinking_mm"), 15);
  }
}

// ---- traction rows (studies/traction_rows.h) ----------------------------------------------

const std::string kTraction = "load_N,slip,drawbar_pull_N,soil_sinkage_mm,torque_Nm\n";
const std::string kTractionRow = "3000,0.2,830,15.7,362\n";

TEST_F(Measurements, TractionRowsAreReadBesideFootprintRows) {
  const auto s = read(
      "load_N,sinking_mm,slip,pass,drawbar_pull_N,soil_sinkage_mm,torque_Nm\n"
      "4000,15,,,,,\n"
      "3000,,0.2,,830,15.7,362\n"
      "3000,,-0.1,2,NA,16.1,\n");
  ASSERT_EQ(s.rows.size(), 3u);
  EXPECT_EQ(s.observables, (std::vector<std::string>{"sinking_mm", "drawbar_pull_N",
                                                     "soil_sinkage_mm", "torque_Nm"}));
  EXPECT_FALSE(s.rows[0].traction);
  ASSERT_TRUE(s.rows[1].traction);
  EXPECT_EQ(s.rows[1].traction->slip, 0.2);
  EXPECT_EQ(s.rows[1].traction->pass, 1);
  EXPECT_EQ(s.rows[1].observed.at("torque_Nm"), 362);
  EXPECT_EQ(s.rows[2].traction->pass, 2);
  EXPECT_EQ(s.rows[2].observed.size(), 1u);  // the empty pull and torque are not measured
  EXPECT_EQ(s.traction_rows(), 2);
  EXPECT_EQ(s.footprint_rows(), 1);
  // No speed_kmh column: the flexing loss's speed is the config's rolling speed, as `traction`.
  EXPECT_DOUBLE_EQ(s.rows[1].conditions.speed_kmh, table3_tyre().transient.rolling.speed_m_s * 3.6);
}

TEST_F(Measurements, TractionColumnsMixedWronglyAreRefusedAtLineAndColumn) {
  // A footprint observable in a traction row, a traction observable in a footprint row.
  expect_refused("load_N,sinking_mm,slip,drawbar_pull_N\n4000,15,,\n3000,15,0.2,830\n", 3,
                 "sinking_mm", "a footprint observable in a traction row");
  expect_refused("load_N,sinking_mm,slip,drawbar_pull_N\n3000,,0.2,830\n4000,15,,830\n", 3,
                 "drawbar_pull_N", "a traction observable in a row without a slip");
  expect_refused("load_N,sinking_mm,slip,pass,drawbar_pull_N\n4000,15,,2,\n", 2, "pass",
                 "a pass without a slip");
  // Traction observables without a slip column; a slip without a traction observable.
  expect_refused("load_N,drawbar_pull_N\n3000,830\n", 1, "drawbar_pull_N", "needs a slip column");
  expect_refused("load_N,sinking_mm,slip\n3000,15,0.2\n", 1, "slip",
                 "without a traction observable");
  // A traction row with nothing measured.
  expect_refused(kTraction + kTractionRow + "3000,0.3,,NA,\n", 3, "slip", "no measured value");
}

TEST_F(Measurements, TractionValuesOutOfRangeOrNotNumbersAreRefused) {
  expect_refused(with_cell(kTraction, kTractionRow, "3000,20,830,15.7,362\n"), 3, "slip",
                 "[-1, 1]");
  expect_refused(with_cell(kTraction, kTractionRow, "3000,-1,830,15.7,362\n"), 3, "slip",
                 "outside [-0.99, 1]");
  expect_refused(with_cell(kTraction, kTractionRow, "3000,nan,830,15.7,362\n"), 3, "slip",
                 "not a finite number");
  expect_refused(with_cell(kTraction, kTractionRow, "3000,0.2,NaN,15.7,362\n"), 3, "drawbar_pull_N",
                 "not a finite number");
  expect_refused(with_cell(kTraction, kTractionRow, "3000,0.2,830,-2,362\n"), 3, "soil_sinkage_mm",
                 "(0, 1e4]");
  expect_refused(with_cell(kTraction, kTractionRow, "3000,0.2,830,15.7,1e9\n"), 3, "torque_Nm",
                 "[-1e7, 1e7]");
  const std::string with_pass = "load_N,slip,pass,drawbar_pull_N\n3000,0.2,1,830\n";
  expect_refused(with_pass + "3000,0.2,1.5,830\n", 3, "pass", "whole number 1-20");
  expect_refused(with_pass + "3000,0.2,21,830\n", 3, "pass", "whole number 1-20");
  expect_refused("load_N,speed_kmh,slip,drawbar_pull_N\n3000,150,0.2,830\n", 2, "speed_kmh",
                 "at most 100 km/h");
}

}  // namespace
