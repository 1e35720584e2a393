// Strict CSV reader: every accepted number is finite, every rejection names file, line, column.
#include "modaltyre/core/csv.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

namespace fs = std::filesystem;

class CsvTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("modaltyre_csv_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  static CsvSchema schema() {
    CsvSchema s;
    s.required = {"x", "y"};
    s.optional = {"w"};
    s.text = {"label"};
    s.optional.push_back("label");
    return s;
  }

  /// Runs read_csv and returns the InputError (fails the test if none is thrown).
  InputError error_of(const std::string& path, const CsvSchema& s = schema()) {
    try {
      read_csv(path, s);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "no InputError for " << path;
    return InputError("none");
  }

  fs::path dir_;
};

// Values, comments, blank lines, a UTF-8 BOM and the 1-based line of every data row survive.
TEST_F(CsvTest, ReadsNumbersTextAndLineNumbers) {
  const auto p = write("ok.csv",
                       "\xEF\xBB\xBFx, y ,label\n"
                       "# a comment\n"
                       "1.5,-2e3,first\n"
                       "\n"
                       "  3 , 4.25 , second \r\n");
  const CsvTable t = read_csv(p, schema());
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.path(), p);
  EXPECT_DOUBLE_EQ(t.number(0, "x"), 1.5);
  EXPECT_DOUBLE_EQ(t.number(0, "y"), -2000.0);
  EXPECT_DOUBLE_EQ(t.number(1, "x"), 3.0);
  EXPECT_DOUBLE_EQ(t.number(1, "y"), 4.25);
  EXPECT_EQ(t.text(1, "label"), "second");
  EXPECT_EQ(t.line(0), 3);
  EXPECT_EQ(t.line(1), 5);
  EXPECT_FALSE(t.has("w"));
  EXPECT_DOUBLE_EQ(t.number_or(0, "w", 7.0), 7.0);
}

// parse_finite_double accepts exactly the finite decimal numbers.
TEST_F(CsvTest, ParseFiniteDouble) {
  EXPECT_EQ(parse_finite_double("1e-3"), 1e-3);
  EXPECT_EQ(parse_finite_double(" -4.5 "), -4.5);
  for (const char* bad :
       {"", "nan", "NaN", "inf", "-inf", "Infinity", "1e999", "1.0x", "abc", "1,2", "0x1p3q"}) {
    EXPECT_FALSE(parse_finite_double(bad).has_value()) << bad;
  }
}

// A required column absent from the header is reported at line 1 with the column name.
TEST_F(CsvTest, MissingColumn) {
  const auto p = write("missing.csv", "x\n1\n");
  const auto e = error_of(p);
  EXPECT_EQ(e.where().file, p);
  EXPECT_EQ(e.where().line, 1);
  EXPECT_EQ(e.where().key, "y");
  EXPECT_NE(std::string(e.what()).find(p + ":1: y"), std::string::npos) << e.what();
}

// An unknown (e.g. misspelt) column is refused rather than silently ignored.
TEST_F(CsvTest, UnknownColumn) {
  const auto p = write("unknown.csv", "x,y,z\n1,2,3\n");
  const auto e = error_of(p);
  EXPECT_EQ(e.where().line, 1);
  EXPECT_EQ(e.where().key, "z");
}

// NaN, infinities and text in a numeric column are each named by file, line and column.
TEST_F(CsvTest, NonFiniteAndTextCells) {
  for (const std::string cell : {"nan", "inf", "-inf", "abc", "", "1.2.3"}) {
    const auto p = write("bad.csv", "x,y\n1,2\n3," + cell + "\n");
    const auto e = error_of(p);
    EXPECT_EQ(e.where().file, p) << cell;
    EXPECT_EQ(e.where().line, 3) << cell;
    EXPECT_EQ(e.where().key, "y") << cell;
    EXPECT_NE(std::string(e.what()).find(p + ":3: y"), std::string::npos) << e.what();
  }
}

// A row with the wrong number of fields is reported at its line.
TEST_F(CsvTest, FieldCountMismatch) {
  const auto p = write("short.csv", "x,y\n1,2\n3\n");
  EXPECT_EQ(error_of(p).where().line, 3);
}

// Empty, header-only, missing and directory inputs each give an InputError naming the path.
TEST_F(CsvTest, WholeFileProblems) {
  const auto empty = write("empty.csv", "");
  const auto header = write("header.csv", "x,y\n# nothing\n");
  const auto missing = (dir_ / "nope.csv").string();
  const auto folder = (dir_ / "folder.csv").string();
  fs::create_directories(folder);
  for (const auto& p : {empty, header, missing, folder}) {
    const auto e = error_of(p);
    EXPECT_EQ(e.where().file, p);
    EXPECT_EQ(std::string(e.what()).rfind(p, 0), 0u) << e.what();
  }
}

// A named pipe would block the reader forever: it is refused before any read (no writer is
// ever attached, so a hang would show as a test timeout).
TEST_F(CsvTest, NamedPipeIsRefusedNotWaitedOn) {
  const std::string fifo = (dir_ / "pipe.csv").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto e = error_of(fifo);
  EXPECT_EQ(e.where().file, fifo);
  EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
}

// Binary content (control bytes) is refused as not a text CSV; non-UTF-8 bytes in a number
// cell are a non-number at their line.
TEST_F(CsvTest, BinaryAndNonUtf8Bytes) {
  std::mt19937 rng(1234);
  std::string bytes = "x,y\n";
  for (int i = 0; i < 256; ++i) bytes.push_back(static_cast<char>(rng() & 0xFF));
  bytes[10] = '\0';  // make sure there is at least one control byte
  const auto bin = write("binary.csv", bytes);
  const auto e1 = error_of(bin);
  EXPECT_EQ(e1.where().file, bin);
  EXPECT_GE(e1.where().line, 2);

  const auto latin = write("latin1.csv", "x,y\n1,2\xE9\xFF\n");
  const auto e2 = error_of(latin);
  EXPECT_EQ(e2.where().line, 2);
  EXPECT_EQ(e2.where().key, "y");
}

// The row limit protects against accidentally huge inputs.
TEST_F(CsvTest, RowLimit) {
  auto s = schema();
  s.max_rows = 2;
  const auto p = write("long.csv", "x,y\n1,2\n3,4\n5,6\n");
  EXPECT_EQ(error_of(p, s).where().line, 4);
}

}  // namespace
}  // namespace modaltyre
