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
  // Underflow is a finite number (rounded to a subnormal or zero), not a refusal.
  EXPECT_EQ(parse_finite_double("1e-400"), 0.0);
  EXPECT_GT(*parse_finite_double("1.2e-316"), 0.0);
  for (const char* bad :
       {"", "nan", "NaN", "inf", "-inf", "Infinity", "1e999", "1.0x", "abc", "1,2", "0x1p3q"}) {
    EXPECT_FALSE(parse_finite_double(bad).has_value()) << bad;
  }
  // Hexadecimal (strtod reads it) is refused, with a hint for the readers' messages (issue 38).
  for (const char* hex : {"0x1000", "0x853", "0x10p4", "-0x2", "0X1A", " 0x1 "}) {
    EXPECT_FALSE(parse_finite_double(hex).has_value()) << hex;
    EXPECT_NE(decimal_hint(hex).find("hexadecimal"), std::string::npos) << hex;
  }
  EXPECT_EQ(decimal_hint("abc"), "");
  EXPECT_EQ(parse_finite_double("+1.5E+03"), 1500.0);
}

// A CSV cell that is a hexadecimal number names its line and column and says why.
TEST_F(CsvTest, HexadecimalCellIsRefusedWithItsColumn) {
  const auto p = write("hex.csv", "x,y\n1,2\n0x853,3\n");
  const auto e = error_of(p);
  EXPECT_EQ(e.where().line, 3);
  EXPECT_EQ(e.where().key, "x");
  EXPECT_NE(std::string(e.what()).find("hexadecimal"), std::string::npos) << e.what();
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

// A semicolon-separated export is named as such (issue 16 item 9), not as an unknown column.
TEST_F(CsvTest, SemicolonSeparatorIsNamed) {
  const auto p = write("semicolon.csv", "x;y\n1,5;2\n");
  const std::string msg = error_of(p).what();
  EXPECT_NE(msg.find("separated by ';'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("separator is ','"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("unknown column"), std::string::npos) << msg;
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

// Issue 44 item 5: a comment is text like the rest of the file: bytes that are not UTF-8 in it
// are refused at their line, as the YAML reader refuses them. UTF-8 comments (a degree sign, a
// mu) stay accepted.
TEST_F(CsvTest, NonUtf8CommentsAreRefusedAtTheirLine) {
  const auto c = error_of(write("c.csv",
                                "# tested at 20 \xB0"
                                "C\nx,y\n1,2\n"));
  EXPECT_EQ(c.where().line, 1);
  EXPECT_EQ(c.where().key, "comment");
  EXPECT_NE(std::string(c.what()).find("\\xB0 is not UTF-8"), std::string::npos) << c.what();
  const auto late = error_of(write("late.csv", "x,y\n1,2\n  # r\xE9sum\xE9\n3,4\n"));
  EXPECT_EQ(late.where().line, 3);
  EXPECT_NO_THROW(read_csv(write("ok.csv",
                                 "# 20 \xC2\xB0"
                                 "C, \xCE\xBC = 0.8\nx,y,label\n1,2,\xC2\xB0\n"),
                           schema()));
}

// The row limit protects against accidentally huge inputs.
TEST_F(CsvTest, RowLimit) {
  auto s = schema();
  s.max_rows = 2;
  const auto p = write("long.csv", "x,y\n1,2\n3,4\n5,6\n");
  EXPECT_EQ(error_of(p, s).where().line, 4);
}

// RFC 4180 quoting: commas and doubled quotes inside quotes, quoted numbers, quoted header names;
// quoted text is kept verbatim, a '"' inside an unquoted field is an ordinary character.
TEST_F(CsvTest, QuotedFields) {
  const auto p = write("quoted.csv",
                       "\"x\",y,label\n"
                       "\"1.5\", \"2\" ,\"a, b\"\n"
                       "3,4,\"say \"\"hi\"\", then go\"\n"
                       "5,6,  \" padded \"  \n"
                       "7,8,5\" rim\n");
  const CsvTable t = read_csv(p, schema());
  ASSERT_EQ(t.rows(), 4u);
  EXPECT_EQ(t.columns(), (std::vector<std::string>{"x", "y", "label"}));
  EXPECT_DOUBLE_EQ(t.number(0, "x"), 1.5);
  EXPECT_DOUBLE_EQ(t.number(0, "y"), 2.0);
  EXPECT_EQ(t.text(0, "label"), "a, b");
  EXPECT_EQ(t.text(1, "label"), "say \"hi\", then go");
  EXPECT_EQ(t.text(2, "label"), " padded ");
  EXPECT_EQ(t.text(3, "label"), "5\" rim");
  EXPECT_EQ(t.line(3), 5);
}

// Broken quoting is named by file, line and column.
TEST_F(CsvTest, BrokenQuotesNameLineAndColumn) {
  struct Bad {
    std::string content, column, words;
  };
  for (const Bad& b : std::vector<Bad>{
           {"x,y,label\n1,2,ok\n3,4,\"no end\n", "label", "unterminated quoted field"},
           {"x,y,label\n1,2,ok\n3,4,\"two\nlines\"\n", "label", "must end on its line"},
           {"x,y,label\n1,2,ok\n3,\"4\"5,z\n", "y", "after the closing quote"},
           {"x,y,label\n1,2,ok\n3,\"\",z\n", "y", "'' is not a finite number"},
           {"x,y,label\n1,2,ok\n3,4,\"\"\n", "label", "empty cell"}}) {
    const auto p = write("q.csv", b.content);
    const auto e = error_of(p);
    EXPECT_EQ(e.where().line, 3) << b.content;
    EXPECT_EQ(e.where().key, b.column) << b.content;
    EXPECT_NE(std::string(e.what()).find(p + ":3: " + b.column + ": "), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(b.words), std::string::npos) << e.what();
  }
  const auto h = write("qh.csv", "x,\"y\n1,2\n");
  EXPECT_EQ(error_of(h).where().line, 1);
  EXPECT_EQ(error_of(h).where().key, "column 2");
}

// An empty file, one of comments only and a header without rows each name a line.
TEST_F(CsvTest, EmptyAndHeaderOnlyNameALine) {
  struct Whole {
    std::string content;
    int line;
    std::string words;
  };
  for (const Whole& w :
       std::vector<Whole>{{"", 1, "the file is empty: no header line"},
                          {"# c\n\n\n", 3, "empty: only blank and comment"},
                          {"\n# c\nx,y\n# none\n", 3, "header only, no data rows"}}) {
    const auto p = write("w.csv", w.content);
    const auto e = error_of(p);
    EXPECT_EQ(e.where().line, w.line) << w.content;
    EXPECT_EQ(std::string(e.what()).rfind(p + ":" + std::to_string(w.line) + ": ", 0), 0u)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(w.words), std::string::npos) << e.what();
  }
}

// A wrong field count names the column without a value, or the first field without a column.
TEST_F(CsvTest, FieldCountNamesTheColumn) {
  const auto shorter = error_of(write("s.csv", "x,y,label\n1,2,a\n3,4\n"));
  EXPECT_EQ(shorter.where().key, "label");
  EXPECT_NE(std::string(shorter.what()).find("has 2 fields, header has 3"), std::string::npos);
  const auto longer = error_of(write("l.csv", "x,y\n1,2\n3,4,5\n"));
  EXPECT_EQ(longer.where().line, 3);
  EXPECT_EQ(longer.where().key, "column 3");
}

// Size limits refuse clearly: bytes before reading (line 0, whole file), cells at their line.
TEST_F(CsvTest, ByteAndCellLimits) {
  auto s = schema();
  s.max_bytes = 10;
  const auto big = write("big.csv", "x,y\n1,2\n3,4\n5,6\n");
  const auto e1 = error_of(big, s);
  EXPECT_EQ(e1.where().line, 0);
  EXPECT_NE(std::string(e1.what()).find("refusing CSV files over"), std::string::npos);
  s = schema();
  s.max_cells = 5;  // two columns: the third row would make six cells
  const auto e2 = error_of(big, s);
  EXPECT_EQ(e2.where().line, 4);
  EXPECT_NE(std::string(e2.what()).find("more than 5 cells"), std::string::npos) << e2.what();
}

// Old Mac line ends (CR only) and UTF-16 files get a message saying what they are.
TEST_F(CsvTest, CarriageReturnsAndUtf16) {
  const auto cr = error_of(write("cr.csv", "x,y\r1,2\r3,4\r"));
  EXPECT_EQ(cr.where().line, 1);
  EXPECT_EQ(cr.where().key, "column 2");
  EXPECT_NE(std::string(cr.what()).find("carriage return"), std::string::npos) << cr.what();
  std::string u16 = "\xFE\xFF";
  for (char c : std::string("x,y\n1,2\n")) u16 += std::string{'\0', c};
  const auto e = error_of(write("u16.csv", u16));
  EXPECT_EQ(e.where().line, 1);
  EXPECT_NE(std::string(e.what()).find("UTF-16"), std::string::npos) << e.what();
}

// Cells and column names quoted in messages never carry raw binary or non-UTF-8 bytes.
TEST_F(CsvTest, MessagesArePrintable) {
  EXPECT_EQ(printable("a\xE9z"), "a\\xE9z");
  EXPECT_EQ(printable(std::string("n\0l", 3)), "n\\x00l");
  EXPECT_EQ(printable("30\xC2\xB0 \xCE\xBC"), "30\xC2\xB0 \xCE\xBC");  // valid UTF-8 stays
  EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");             // a UTF-16 surrogate
  EXPECT_EQ(printable(std::string(100, 'a'), 8), "aaaaaaaa...");
  const auto e = error_of(write("u.csv", "x,y\xFF\n1,2\n"));
  EXPECT_EQ(e.where().key, "y\\xFF");
  const auto e2 = error_of(write("v.csv", "x,y\n1," + std::string(5000, '7') + "x\n"));
  EXPECT_LT(std::string(e2.what()).size(), 300u) << "a huge cell is not echoed whole";
}

// read_csv_header parses the header as read_csv does and never blocks or throws.
TEST_F(CsvTest, ReadCsvHeader) {
  EXPECT_EQ(
      read_csv_header(write("h.csv", "\xEF\xBB\xBF# c\n\n \"load_N\", a.b ,\"c,d\"\n1,2,3\n")),
      (std::vector<std::string>{"load_N", "a.b", "c,d"}));
  EXPECT_TRUE(read_csv_header(write("e.csv", "")).empty());
  EXPECT_TRUE(read_csv_header(write("bad.csv", "x,\"y\n")).empty());
  EXPECT_TRUE(read_csv_header((dir_ / "absent.csv").string()).empty());
  EXPECT_TRUE(read_csv_header(dir_.string()).empty());
  const std::string fifo = (dir_ / "pipe.csv").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(read_csv_header(fifo).empty());  // no writer: a read would block for ever
}

}  // namespace
}  // namespace modaltyre
