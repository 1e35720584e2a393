// The .tir reader: syntax as MF-Tool and MSC Adams write it, [UNITS] to SI, and every refusal
// naming file, line and SECTION.KEY.
#include <gtest/gtest.h>

#include <string>

#include "modaltyre/core/errors.h"
#include "modaltyre/tir/tir_file.h"
#include "modaltyre/tir/tir_units.h"

namespace {

using modaltyre::InputError;
using namespace modaltyre::tir;

TEST(TirReader, ReadsKeysQuotesCommentsAndFortranExponents) {
  const TirFile f = parse_tir(
      "$---- header\n"
      "[MDI_HEADER]\n"
      "FILE_TYPE = 'tir'   $ the type\n"
      "! : TIRE_VERSION : MF-Tyre 6.2\n"
      "[model]\n"
      "fittyp = 62 ! lower-case names are the same keys\n"
      "TYRESIDE = LEFT\n"
      "COMMENT = \"a $ and a ! inside quotes\"\n"
      "[VERTICAL]\n"
      "VERTICAL_STIFFNESS = 2.0965D+05\n"
      "Q_FZ2 = -1.5e-4\n",
      "mem.tir");
  ASSERT_EQ(f.sections.size(), 3u);
  EXPECT_EQ(f.value("MDI_HEADER", "FILE_TYPE")->text, "tir");
  EXPECT_TRUE(f.value("MDI_HEADER", "FILE_TYPE")->quoted);
  EXPECT_DOUBLE_EQ(*f.value("MODEL", "FITTYP")->number, 62);
  EXPECT_EQ(f.value("MODEL", "FITTYP")->line, 6);
  EXPECT_EQ(f.value("MODEL", "TYRESIDE")->text, "LEFT");
  EXPECT_FALSE(f.value("MODEL", "TYRESIDE")->number);
  EXPECT_EQ(f.value("MODEL", "COMMENT")->text, "a $ and a ! inside quotes");
  EXPECT_DOUBLE_EQ(*f.value("VERTICAL", "VERTICAL_STIFFNESS")->number, 2.0965e5);
  EXPECT_DOUBLE_EQ(*f.value("VERTICAL", "Q_FZ2")->number, -1.5e-4);
  EXPECT_EQ(f.comments.size(), 4u);
}

TEST(TirReader, ReadsTablesWithAndWithoutHeader) {
  const TirFile f = parse_tir(
      "[SHAPE]\n 1.0 0.0\n 1.0 0.4\n 0.9 1.0\n"
      "[DEFLECTION_LOAD_CURVE]\n{pen     fz}\n0.000 0.0\n0.005  1.0e3\n",
      "mem.tir");
  const TirTable& shape = f.section("SHAPE")->table;
  EXPECT_TRUE(shape.columns.empty());
  ASSERT_EQ(shape.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(shape.rows[2][0], 0.9);
  const TirTable& curve = f.section("DEFLECTION_LOAD_CURVE")->table;
  EXPECT_EQ(curve.columns, (std::vector<std::string>{"PEN", "FZ"}));
  ASSERT_EQ(curve.rows.size(), 2u);
  EXPECT_DOUBLE_EQ(curve.rows[1][1], 1000);
  EXPECT_EQ(curve.row_lines[1], 8);
}

TEST(TirReader, UnitsConvertToSi) {
  const TirFile f = parse_tir(
      "[UNITS]\nLENGTH = 'millimeter'\nFORCE = 'kilo_newton'\nANGLE = 'deg'\nTIME = 'second'\n",
      "mem.tir");
  const TirUnits u = read_units(f);
  EXPECT_DOUBLE_EQ(u.to_si(Dimension::length), 1e-3);
  EXPECT_DOUBLE_EQ(u.to_si(Dimension::force), 1e3);
  EXPECT_DOUBLE_EQ(u.to_si(Dimension::stiffness), 1e6);  // kN/mm -> N/m
  EXPECT_DOUBLE_EQ(u.to_si(Dimension::pressure), 1e9);   // kN/mm^2 without PRESSURE
  EXPECT_NEAR(u.to_si(Dimension::angle), 0.017453292519943295, 1e-15);
  const TirUnits bar = read_units(parse_tir("[UNITS]\nPRESSURE = 'bar'\n", "mem.tir"));
  EXPECT_DOUBLE_EQ(bar.to_si(Dimension::pressure), 1e5);
  EXPECT_FALSE(read_units(parse_tir("[MODEL]\n", "mem.tir")).stated);
}

// A section given twice with other contents states two values for one parameter (Goodyear's
// files in Project Chrono repeat [DEFLECTION_LOAD_CURVE] with another table): refused naming both
// lines, as a key given twice is (issue 38). A verbatim repeat is read once, with a note.
TEST(TirReader, RepeatedSectionIsRefusedUnlessVerbatim) {
  try {
    parse_tir(
        "[DEFLECTION_LOAD_CURVE]\n{pen fz}\n0 0\n0.01 1000\n[VERTICAL]\nFNOMIN = 900\n"
        "[deflection_load_curve]\n{pen fz}\n0 0\n0.02 1000\n0.03 2000\n",
        "rep.tir");
    ADD_FAILURE() << "a repeated section with other contents was read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 7);
    EXPECT_EQ(e.where().key, "DEFLECTION_LOAD_CURVE");
    EXPECT_NE(std::string(e.what()).find("given again with other contents (first on line 1)"),
              std::string::npos)
        << e.what();
  }
  try {
    parse_tir("[VERTICAL]\nFNOMIN = 900\n[VERTICAL]\nFNOMIN = 1900\n", "v.tir");
    ADD_FAILURE() << "two FNOMIN in two [VERTICAL] sections were read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
  }
  const TirFile f = parse_tir(
      "[VERTICAL]\nFNOMIN = 900\n[DIMENSION]\nWIDTH = 0.2\n"
      "[vertical]\nfnomin = 900\n",
      "same.tir");
  EXPECT_DOUBLE_EQ(*f.value("VERTICAL", "FNOMIN")->number, 900);
  ASSERT_EQ(f.notes.size(), 1u);
  EXPECT_NE(f.notes[0].find("same.tir:5: section [VERTICAL] given again (first on line 1) with "
                            "the same contents"),
            std::string::npos)
      << f.notes[0];
}

// Old Mac line ends (CR only) would make the file one line: refused with what to do. A Latin-1
// byte in a value is refused naming SECTION.KEY; in a comment it is kept (never interpreted).
TEST(TirReader, CrOnlyLineEndsAndLatin1ValuesAreRefused) {
  try {
    parse_tir("[VERTICAL]\rFNOMIN = 900\r", "cr.tir");
    ADD_FAILURE() << "CR-only line ends read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("carriage return"), std::string::npos) << e.what();
  }
  try {
    parse_tir("[MODEL]\nTYRESIDE = 'caf\xE9'\n", "l1.tir");
    ADD_FAILURE() << "Latin-1 value read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_EQ(e.where().key, "MODEL.TYRESIDE");
    EXPECT_NE(std::string(e.what()).find("not UTF-8"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(
      parse_tir("[MODEL]\nFITTYP = 62 $ 25\xB0"
                "C\n",
                "comment.tir"));
}

// `KEY =` with nothing after it: a parameter its writer left unset (MATLAB tyre libraries write
// every MF 6.1 key so), kept and read as absent.
TEST(TirReader, EmptyValueIsAbsent) {
  const TirFile f = parse_tir("[DIMENSION]\nWIDTH =\nUNLOADED_RADIUS = 0.3\nTAG = ''\n", "e.tir");
  EXPECT_EQ(f.section("DIMENSION")->entries.count("WIDTH"), 1u);
  EXPECT_EQ(f.value("DIMENSION", "WIDTH"), nullptr);
  EXPECT_DOUBLE_EQ(*f.value("DIMENSION", "UNLOADED_RADIUS")->number, 0.3);
  ASSERT_NE(f.value("DIMENSION", "TAG"), nullptr);  // an empty quoted string is a value
  EXPECT_EQ(f.value("DIMENSION", "TAG")->text, "");
}

struct BadTir {
  const char* name;
  const char* text;
  int line;
  const char* key;  ///< expected in the message ("" = none)
  const char* says;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const BadTir& c, std::ostream* os) { *os << c.name; }

class TirReaderRefuses : public ::testing::TestWithParam<BadTir> {};

TEST_P(TirReaderRefuses, NamingFileLineAndKey) {
  const BadTir& c = GetParam();
  try {
    const TirFile f = parse_tir(c.text, "bad.tir");
    (void)read_units(f);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "bad.tir");
    EXPECT_EQ(e.where().line, c.line) << e.what();
    EXPECT_EQ(e.where().key, c.key) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, TirReaderRefuses,
    ::testing::Values(
        BadTir{"UnterminatedQuote", "[A]\nK = 'abc\n", 2, "A.K", "unterminated"},
        BadTir{"TextAfterQuote", "[A]\nK = 'abc' def\n", 2, "A.K", "after the closing quote"},
        BadTir{"DuplicateKey", "[A]\nK = 1\nk = 2\n", 3, "A.K", "given twice"},
        BadTir{"KeyBeforeSection", "K = 1\n", 1, "", "before the first [SECTION]"},
        BadTir{"BadKeyInRepeatedSection", "[A]\nK = 1\n[A]\nK = 1\nK = 2\n", 5, "A.K",
               "given twice"},
        BadTir{"Infinite", "[A]\nK = 1e999\n", 2, "A.K", "not a finite number"},
        BadTir{"NotANumberWord", "[A]\nK = two words\n", 2, "A.K", "one word"},
        BadTir{"BadSectionName", "[A B]\n", 1, "", "not a section name"},
        BadTir{"UnclosedSection", "[A\n", 1, "", "lacks ']'"},
        BadTir{"RaggedTable", "[T]\n1 2\n1 2 3\n", 3, "T", "has 2 columns"},
        BadTir{"TableTextCell", "[T]\n{a b}\n1 x\n", 3, "T", "row of numbers"},
        BadTir{"NanCell", "[T]\n1 nan\n", 2, "T", "not a finite number"},
        BadTir{"SecondTableHeader", "[T]\n{a b}\n{c d}\n", 3, "T", "second table header"},
        BadTir{"UnknownUnit", "[UNITS]\nLENGTH = 'furlong'\n", 2, "UNITS.LENGTH", "unknown unit"},
        BadTir{"NoSection", "$ only a comment\n", 0, "", "no [SECTION]"}),
    [](const ::testing::TestParamInfo<BadTir>& info) { return info.param.name; });

TEST(TirReader, RefusesBinary) {
  try {
    parse_tir(std::string("[A]\nK = 1\0\n", 10), "bin.tir");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(std::string(e.what()).find("NUL"), std::string::npos);
  }
}

TEST(TirReader, BoundsSizes) {
  TirLimits limits;
  limits.max_entries = 3;
  EXPECT_THROW(parse_tir("[A]\nK1 = 1\nK2 = 2\nK3 = 3\nK4 = 4\n", "m.tir", limits), InputError);
  limits = {};
  limits.max_table_rows = 2;
  EXPECT_THROW(parse_tir("[T]\n1\n2\n3\n", "m.tir", limits), InputError);
  EXPECT_THROW(parse_tir("[A]\nK = '" + std::string(5000, 'x') + "'\n", "m.tir"), InputError);
  limits = {};
  limits.max_bytes = 8;
  EXPECT_THROW(parse_tir("[A]\nK = 12345\n", "m.tir", limits), InputError);
}

}  // namespace
