// Hammer-file validation: every defect a researcher's file can have is an InputError naming the
// file, and the line and column where they apply; a good file reads back sorted by angle.
#include "modaltyre/modal/hammer_data.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../support/hammer_lines.h"
#include "modal_test_constants.h"
#include "modaltyre/core/errors.h"

// The fixture is named like the reader's HammerData: in a namespace of its own, it hides that
// type here only (not in the modal tests compiled after this file in a unity build).
namespace modaltyre::modal::hammer_file {
namespace {

using modaltyre_test::hammer_lines;
using modaltyre_test::set_field;

namespace fs = std::filesystem;
using test::kPi;

class HammerData : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("modaltyre_hammer_") + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::vector<std::string>& lines, const std::string& name = "h.csv") {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return write_raw(s, name);
  }
  std::string write_raw(const std::string& content, const std::string& name = "h.csv") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }
  /// The InputError of reading `path`; checks it names the file (and line/column if given).
  void expect_error(const std::string& path, int line, const std::string& column,
                    const std::string& words = "") {
    try {
      read_hammer_csv(path);
      ADD_FAILURE() << "no InputError for " << path;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.where().file, path);
      EXPECT_EQ(what.rfind(path, 0), 0u) << what;  // message starts with the file
      if (line > 0) {
        EXPECT_EQ(e.where().line, line) << what;
        EXPECT_NE(what.find(path + ":" + std::to_string(line)), std::string::npos) << what;
      }
      if (!column.empty()) {
        EXPECT_EQ(e.where().key, column) << what;
        EXPECT_NE(what.find(column), std::string::npos) << what;
      }
      if (!words.empty()) {
        EXPECT_NE(what.find(words), std::string::npos) << what;
      }
    }
  }
  fs::path dir_;
};

// A valid file: N, modes, frequencies and angle-sorted shapes come back (rows may be shuffled,
// angles may be given outside [0, 360)).
TEST_F(HammerData, ReadsValidFileSortedByAngle) {
  auto l = hammer_lines(12, 2);
  std::swap(l[3], l[7]);       // points out of order within mode 1
  set_field(l, 25, 4, "-30");  // mode 2, point 12 at 330 deg written as -30
  const auto d = read_hammer_csv(write(l));
  EXPECT_EQ(d.points, 12);
  ASSERT_EQ(d.modes.size(), 2u);
  EXPECT_EQ(d.modes[1].freq_hz, 120.0);
  EXPECT_EQ(d.modes[0].first_line, 2);
  for (const auto& m : d.modes) {
    for (int i = 0; i < 12; ++i) {
      EXPECT_NEAR(m.angle_rad[i], 2 * kPi * i / 12, 1e-12);
      EXPECT_NEAR(m.radial[i], 0.6 * std::cos(2 * m.angle_rad[i]), 1e-5);
    }
  }
}

TEST_F(HammerData, MissingColumn) {
  auto l = hammer_lines();
  for (auto& s : l) s = s.substr(0, s.rfind(','));  // drop "tangential"
  expect_error(write(l), 1, "tangential");
}

TEST_F(HammerData, NaNCell) {
  auto l = hammer_lines();
  set_field(l, 5, 5, "nan");
  expect_error(write(l), 5, "radial");
}

TEST_F(HammerData, InfCell) {
  auto l = hammer_lines();
  set_field(l, 9, 6, "-inf");
  expect_error(write(l), 9, "tangential");
}

TEST_F(HammerData, TextInNumberColumn) {
  auto l = hammer_lines();
  set_field(l, 16, 1, "120Hz");
  expect_error(write(l), 16, "freq_hz");
}

// A point misplaced by 10 degrees of a 30-degree spacing: the fit of eq. 20-21 assumes equal
// spacing, so this is refused at the mode's first line.
TEST_F(HammerData, UnequalAngularSpacing) {
  auto l = hammer_lines();
  set_field(l, 4, 4, "70");  // mode 1 point 3: 60 -> 70 deg
  expect_error(write(l), 2, "angle_deg", "equally spaced");
}

TEST_F(HammerData, DuplicatePoint) {
  auto l = hammer_lines();
  set_field(l, 6, 3, "3");  // mode 1: point 4 renumbered as point 3 (line 4)
  expect_error(write(l), 6, "point", "line 4");
}

TEST_F(HammerData, TwoPointsAtSameAngle) {
  auto l = hammer_lines();
  set_field(l, 6, 4, "60");  // mode 1 point 5 at the angle of point 3
  expect_error(write(l), 2, "angle_deg");
}

// Fewer than 6 points cannot resolve orders 0..2.
TEST_F(HammerData, TooFewPoints) {
  expect_error(write(hammer_lines(4, 2)), 2, "point", "at least 6");
}

// Every mode must be measured at the same points.
TEST_F(HammerData, ModeWithFewerPointsThanOthers) {
  auto l = hammer_lines(12, 3);
  l.erase(l.begin() + 14 + 5);  // mode 2 (lines 14-25) loses one point
  expect_error(write(l), 14, "point", "mode 2 has 11 points");
}

// Issue 16: one row left out names the missing point instead of an unequal spacing. Mode 2
// (lines 14-25, point i at 30 (i - 1) deg) without point 6: the point and the first mode's line
// of it; the first mode without point 11: the angle and the number.
TEST_F(HammerData, OneMissingRowNamesThePoint) {
  auto l = hammer_lines(12, 3);
  l.erase(l.begin() + 13 + 5);  // line 19: mode 2 point 6
  expect_error(write(l), 14, "point",
               "mode 2 has 11 points, mode 1 has 12; every mode needs the same points: point 6 is "
               "missing (mode 1 has it on line 7)");
  l = hammer_lines(12, 3);
  l.erase(l.begin() + 11);  // line 12: mode 1 point 11 at 300 deg
  expect_error(write(l), 2, "angle_deg",
               "mode 1: no point at 300 deg (point 11?) - the others are 30 deg apart: 12 points "
               "expected, 11 given");
}

// Damping written as a percentage is refused (seed 001 Table 2 gives percentages).
TEST_F(HammerData, DampingAsPercentage) {
  auto l = hammer_lines();
  for (int line = 2; line <= 13; ++line) set_field(l, line, 2, "4.5");
  expect_error(write(l), 2, "damping_ratio", "fraction");
}

// One mode with two frequencies is an inconsistent file.
TEST_F(HammerData, InconsistentFrequencyWithinMode) {
  auto l = hammer_lines();
  set_field(l, 7, 1, "101");
  expect_error(write(l), 7, "freq_hz");
}

TEST_F(HammerData, NonPositiveFrequencyAndBadModeNumber) {
  auto l = hammer_lines();
  set_field(l, 2, 1, "0");
  expect_error(write(l), 2, "freq_hz");
  l = hammer_lines();
  set_field(l, 3, 0, "1.5");
  expect_error(write(l, "h2.csv"), 3, "mode");
}

TEST_F(HammerData, EmptyFile) { expect_error(write_raw(""), 0, "", "empty"); }

TEST_F(HammerData, HeaderOnly) { expect_error(write({hammer_lines()[0]}), 0, "", "no data"); }

TEST_F(HammerData, DirectoryGiven) {
  const auto d = (dir_ / "folder.csv").string();
  fs::create_directories(d);
  expect_error(d, 0, "", "directory");
}

TEST_F(HammerData, MissingFile) {
  expect_error((dir_ / "absent.csv").string(), 0, "", "not found");
}

// Binary bytes (e.g. an .xlsx renamed to .csv) are refused as not a text CSV.
TEST_F(HammerData, BinaryBytes) {
  std::mt19937 rng(42);
  std::string s = "PK\x03\x04";
  for (int i = 0; i < 512; ++i) s.push_back(static_cast<char>(rng() & 0xFF));
  expect_error(write_raw(s), 1, "");
}

// Non-UTF-8 text (Latin-1 degree sign and a UTF-16 file) is refused at its line.
TEST_F(HammerData, NonUtf8Bytes) {
  auto l = hammer_lines();
  set_field(l, 3, 4, "30\xB0");  // "30°" in Latin-1
  expect_error(write(l), 3, "angle_deg");

  std::string utf16 = "\xFF\xFE";
  for (char c : hammer_lines()[0] + "\n") utf16 += std::string{c, '\0'};
  expect_error(write_raw(utf16, "u16.csv"), 1, "");
}

}  // namespace
}  // namespace modaltyre::modal::hammer_file
