// UFF dataset 58 reader: files of the test's own writer (every ordinate type, even and uneven
// abscissa, ASCII and binary of either byte order) read back exactly; a hand-made file in the
// specification's fixed columns reads the same; every defect names file, line, record, field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <ostream>
#include <string>
#include <vector>

#include "ema_test_support.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ema/uff58.h"
#include "synthetic_frf.h"
#include "uff_writer.h"

namespace modaltyre::ema {
namespace {

using modaltyre_test::expect_input_error;
using modaltyre_test::UffOptions;

// Two FRFs (radial and tangential response at point 3, radial reference at point 1) with
// values that fill all digits of the formats.
FrfSet small_set() {
  FrfSet s;
  s.path = "x";
  for (int i = 0; i < 9; ++i) s.freq_hz.push_back(10.0 + 0.25 * i);
  FrfChannel a{{3, Direction::radial}, {1, Direction::radial}, {}, 0};
  FrfChannel b{{3, Direction::tangential}, {1, Direction::radial}, {}, 0};
  for (int i = 0; i < 9; ++i) {
    a.values.emplace_back(std::sin(1.3 * i + 0.1) * 1.234567e-3, std::cos(0.7 * i) * -9.87e2);
    b.values.emplace_back(-std::exp(-0.3 * i) / 7.0, 3.3e-7 * i);
  }
  s.channels = {a, b};
  return s;
}

// What a value becomes after the writer's text (E20.12, E13.5) or float (binary single).
double as_written(double v, const UffOptions& o, bool abscissa) {
  if (o.binary) return o.double_precision ? v : static_cast<double>(static_cast<float>(v));
  const bool wide = o.double_precision && !abscissa;
  return std::strtod(modaltyre_test::fmt(wide ? "%20.12e" : "%13.5e", v).c_str(), nullptr);
}

struct RoundTripCase {
  std::string name;
  UffOptions options;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const RoundTripCase& c, std::ostream* os) { *os << c.name; }

class UffRoundTrip : public modaltyre_test::ScratchDir,
                     public ::testing::WithParamInterface<RoundTripCase> {};

TEST_P(UffRoundTrip, ReadsBackWhatWasWritten) {
  const UffOptions o = GetParam().options;
  const FrfSet in = small_set();
  const std::string path = write(modaltyre_test::uff58_file(in, o), "frf.uff");
  const FrfSet out = read_uff58(path);
  ASSERT_EQ(out.channels.size(), 2u);
  EXPECT_TRUE(out.type_from_file);
  EXPECT_EQ(out.type, o.numerator_type == 12   ? FrfType::accelerance
                      : o.numerator_type == 11 ? FrfType::mobility
                                               : FrfType::receptance);
  ASSERT_EQ(out.freq_hz.size(), in.freq_hz.size());
  for (std::size_t i = 0; i < in.freq_hz.size(); ++i) {
    // Even spacing: minimum and increment are E13.5 fields; here both are exact.
    EXPECT_EQ(out.freq_hz[i], o.even ? in.freq_hz[i] : as_written(in.freq_hz[i], o, true));
  }
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(out.channels[c].response, in.channels[c].response);
    EXPECT_EQ(out.channels[c].reference, in.channels[c].reference);
    EXPECT_EQ(out.channels[c].line, c == 0 ? 2 : out.channels[c].line);
    for (std::size_t i = 0; i < in.freq_hz.size(); ++i) {
      const auto v = in.channels[c].values[i];
      // A negative response direction was written with negated values; the reader undoes it.
      EXPECT_EQ(out.channels[c].values[i].real(), as_written(v.real(), o, false));
      EXPECT_EQ(out.channels[c].values[i].imag(), o.complex ? as_written(v.imag(), o, false) : 0.0);
    }
  }
}

UffOptions opts(auto f) {
  UffOptions o;
  f(o);
  return o;
}

INSTANTIATE_TEST_SUITE_P(
    AllLayouts, UffRoundTrip,
    ::testing::Values(
        RoundTripCase{"AsciiComplexDoubleEven", {}},
        RoundTripCase{"AsciiComplexSingleEven", opts([](auto& o) { o.double_precision = false; })},
        RoundTripCase{"AsciiComplexDoubleUneven", opts([](auto& o) { o.even = false; })},
        RoundTripCase{"AsciiComplexSingleUneven", opts([](auto& o) {
                        o.even = false;
                        o.double_precision = false;
                      })},
        RoundTripCase{"AsciiRealDoubleUneven", opts([](auto& o) {
                        o.even = false;
                        o.complex = false;
                      })},
        RoundTripCase{"AsciiRealSingleEven", opts([](auto& o) {
                        o.complex = false;
                        o.double_precision = false;
                      })},
        RoundTripCase{"AsciiMobilityNegativeDirection", opts([](auto& o) {
                        o.numerator_type = 11;
                        o.negative_response = true;
                      })},
        RoundTripCase{"AsciiReceptance", opts([](auto& o) { o.numerator_type = 8; })},
        RoundTripCase{"BinaryLittleDouble", opts([](auto& o) { o.binary = true; })},
        RoundTripCase{"BinaryBigSingleUneven", opts([](auto& o) {
                        o.binary = true;
                        o.big_endian = true;
                        o.double_precision = false;
                        o.even = false;
                      })},
        RoundTripCase{"BinaryNewlineBeforeEnd", opts([](auto& o) {
                        o.binary = true;
                        o.blank_after_binary = true;
                        o.negative_response = true;
                      })}),
    [](const auto& info) { return info.param.name; });

class Uff58 : public modaltyre_test::ScratchDir {};

// tests/data/ema/fixed_columns.unv (tests/data/ema/README.md): a units dataset 164, a
// coherence (function type 6) and two FRFs typed column by column as the specification lays
// them out, one in E13.5 with a jammed 3-digit exponent and a 'D' exponent, CRLF line ends.
TEST_F(Uff58, HandMadeFixedColumnFileReadsTheSameAsTheWriter) {
  const std::string hand = std::string(MODALTYRE_SOURCE_DIR) + "/tests/data/ema/fixed_columns.unv";
  const FrfSet a = read_uff58(hand);
  ASSERT_EQ(a.channels.size(), 2u);
  EXPECT_EQ(a.type, FrfType::accelerance);
  const std::vector<double> f = {100.0, 100.5, 101.0};
  EXPECT_EQ(a.freq_hz, f);
  // The second FRF is point 2, direction -1: tangential, values negated on reading.
  EXPECT_EQ(a.channels[1].response, (Dof{2, Direction::tangential}));
  EXPECT_EQ(a.channels[1].values[0], std::complex<double>(-1.5, 2.5e-100));
  EXPECT_EQ(a.channels[1].values[2], std::complex<double>(-0.25, -1e-3));

  // The same numbers through the writer (direction -1 again for the tangential FRF) read back
  // identically.
  const FrfSet& w = a;
  std::string text;
  for (const auto& c : w.channels) {
    UffOptions o;
    o.double_precision = false;
    o.negative_response = c.response.dir == Direction::tangential;
    text += modaltyre_test::uff58_dataset(c, w.freq_hz, o);
  }
  const FrfSet b = read_uff58(write(text, "writer.uff"));
  ASSERT_EQ(b.channels.size(), 2u);
  EXPECT_EQ(b.freq_hz, a.freq_hz);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(b.channels[c].response, a.channels[c].response);
    for (std::size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(b.channels[c].values[i], a.channels[c].values[i]) << c << " " << i;
    }
  }
}

// One defect per case: where it is planted (line of the file) and the record/field named.
struct Defect {
  std::string name;
  int line;  // 1-based line of the two-FRF file (the first dataset spans lines 1-17)
  int column;
  std::string replacement;  // replaces the text from `column` for its length
  int error_line;
  std::string field;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const Defect& c, std::ostream* os) { *os << c.name; }

class UffDefect : public modaltyre_test::ScratchDir,
                  public ::testing::WithParamInterface<Defect> {};

TEST_P(UffDefect, NamesFileLineRecordAndField) {
  const Defect d = GetParam();
  std::string text = modaltyre_test::uff58_file(small_set());
  std::size_t pos = 0;
  for (int l = 1; l < d.line; ++l) pos = text.find('\n', pos) + 1;
  const std::size_t room = text.find('\n', pos) - pos - d.column;
  text.replace(pos + d.column, std::min(room, d.replacement.size()), d.replacement);
  const std::string path = write(text, "bad.uff");
  expect_input_error([&] { read_uff58(path); }, path, d.error_line, d.field);
}

// Line 2 "    58", 3-7 ID lines, 8 record 6, 9 record 7, 10-13 records 8-11, 14-18 values.
INSTANTIATE_TEST_SUITE_P(
    Records, UffDefect,
    ::testing::Values(
        Defect{"ResponseDirectionY", 8, 51, "   2", 8, "record 6 field 7"},
        Defect{"ReferenceDirectionRotation", 8, 76, "  -5", 8, "record 6 field 10"},
        Defect{"ResponseNodeZero", 8, 41, "         0", 8, "record 6 field 6"},
        Defect{"RecordSixGarbled", 8, 0, "xx", 8, "record 6"},
        Defect{"OrdinateTypeThree", 9, 0, "         3", 9, "record 7 field 1"},
        Defect{"OneValue", 9, 10, "         1", 9, "record 7 field 2"},
        Defect{"SpacingTwo", 9, 20, "         2", 9, "record 7 field 3"},
        Defect{"ZeroIncrement", 9, 43, "  0.00000e+00", 9, "record 7 field 5"},
        Defect{"AbscissaIsTime", 10, 0, "        17", 10, "record 8 field 1"},
        Defect{"NumeratorIsPressure", 11, 0, "        15", 11, "record 9 field 1"},
        Defect{"DenominatorIsAcceleration", 12, 0, "        12", 12, "record 10 field 1"},
        Defect{"ValueNotANumber", 15, 20, "  1.0000000000xe+00 ", 15, "record 12 value 6"},
        Defect{"TooManyValues", 18, 0, "1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20", 18,
               "record 12"},
        Defect{"MissingEnd", 19, 0, "    -2", 19, "record 12"},
        Defect{"SecondFrfOtherGrid", 28, 30, "  1.10000e+01", 28, "record 7"},
        Defect{"SecondFrfMobility", 30, 0, "        11", 30, "record 9 field 1"},
        Defect{"SecondFrfSameDofs", 27, 51, "   3", 21, ""},
        Defect{"NoDatasetStart", 1, 0, "    -7", 1, ""}),
    [](const auto& info) { return info.param.name; });

TEST_F(Uff58, TruncatedAndEmptyFilesAndLimits) {
  const std::string full = modaltyre_test::uff58_file(small_set());
  const std::string cut = write(full.substr(0, full.find("    -1", 10) - 30), "cut.uff");
  expect_input_error([&] { read_uff58(cut); }, cut, 18, "record 12");

  const std::string empty = write("", "empty.uff");
  const auto msg = expect_input_error([&] { read_uff58(empty); }, empty, 0, "");
  EXPECT_NE(msg.find("no frequency response function"), std::string::npos) << msg;

  UffOptions coh;
  coh.function_type = 6;  // coherence only
  const std::string only = write(modaltyre_test::uff58_file(small_set(), coh), "coh.uff");
  const auto m2 = expect_input_error([&] { read_uff58(only); }, only, 0, "");
  EXPECT_NE(m2.find("2 other datasets 58"), std::string::npos) << m2;

  FrfLimits tight;
  tight.max_lines = 5;
  const std::string ok = write(full, "ok.uff");
  expect_input_error([&] { read_uff58(ok, tight); }, ok, 9, "record 7 field 2");
  tight = {};
  tight.max_channels = 1;
  expect_input_error([&] { read_uff58(ok, tight); }, ok, 20, "");
  tight = {};
  tight.max_bytes = 100;
  expect_input_error([&] { read_uff58(ok, tight); }, ok, 0, "");
  expect_input_error([&] { read_uff58(dir_.string()); }, dir_.string(), 0, "");

  UffOptions bin;
  bin.binary = true;
  const std::string b = modaltyre_test::uff58_file(small_set(), bin);
  const std::string bcut = write(b.substr(0, b.find("    -1", 10) - 20), "bcut.uff");
  expect_input_error([&] { read_uff58(bcut); }, bcut, 2, "record 12 (binary)");

  // A 58b file that ends on record 11 without its newline: the data block is empty, not
  // read past the end of the file (a fuzzing finding: the byte count went negative).
  std::size_t at = b.find("58b");
  for (int k = 0; k < 12 && at != std::string::npos; ++k) at = b.find('\n', at + 1);
  ASSERT_NE(at, std::string::npos);
  const std::string bend = write(b.substr(0, at), "bend.uff");
  const auto m3 = expect_input_error([&] { read_uff58(bend); }, bend, 2, "record 12 (binary)");
  EXPECT_NE(m3.find("ends after 0 bytes"), std::string::npos) << m3;
}

TEST_F(Uff58, SkipsOtherDatasetsAndCoherence) {
  UffOptions coh;
  coh.function_type = 6;
  const std::string text = "    -1\n   151\nmodel\n    -1\n\n" +
                           modaltyre_test::uff58_file(small_set(), coh) +
                           modaltyre_test::uff58_file(small_set());
  const FrfSet s = read_uff58(write(text, "mixed.uff"));
  ASSERT_EQ(s.channels.size(), 2u);
  EXPECT_EQ(s.channels[0].line, 4 + 1 + 2 * 19 + 2);  // its "    58" line
}

}  // namespace
}  // namespace modaltyre::ema
