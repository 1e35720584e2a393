// Long-CSV FRF reader and FRF-type conversion: a written set reads back exactly; every defect
// names file, line and column; receptance, mobility and accelerance convert into each other
// as (j omega)^p and back.
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <string>

#include "ema_test_support.h"
#include "modaltyre/ema/frf_csv.h"
#include "synthetic_frf.h"

namespace modaltyre::ema {
namespace {

using modaltyre_test::expect_input_error;

std::string to_csv(const FrfSet& s) {
  std::string out = "response_point,response_dir,reference_point,reference_dir,freq_hz,re,im\n";
  char buf[256];
  for (const auto& c : s.channels) {
    for (std::size_t i = 0; i < s.freq_hz.size(); ++i) {
      std::snprintf(buf, sizeof buf, "%d,%s,%d,%s,%.17g,%.17g,%.17g\n", c.response.point,
                    to_string(c.response.dir), c.reference.point, to_string(c.reference.dir),
                    s.freq_hz[i], c.values[i].real(), c.values[i].imag());
      out += buf;
    }
  }
  return out;
}

modaltyre_test::PlantedModel one_mode() {
  modaltyre_test::PlantedModel m;
  m.points = 6;
  modaltyre_test::PlantedMode k{120, 0.03, {}, {}};
  for (int i = 0; i < 6; ++i) {
    k.radial.push_back(0.5 * std::cos(2 * 6.283185307179586 * i / 6));
    k.tangential.push_back(0.25 * std::sin(2 * 6.283185307179586 * i / 6));
  }
  m.modes = {k};
  return m;
}

class FrfCsv : public modaltyre_test::ScratchDir {};

TEST_F(FrfCsv, ReadsBackExactly) {
  modaltyre_test::SynthOptions o;
  o.f_lo_hz = 50;
  o.f_hi_hz = 60;
  const FrfSet in = modaltyre_test::synthesise(one_mode(), o);
  const std::string path = write(to_csv(in), "frf.csv");
  const FrfSet out = read_frf_csv(path, FrfType::mobility);
  EXPECT_EQ(out.type, FrfType::mobility);
  EXPECT_FALSE(out.type_from_file);
  EXPECT_EQ(out.freq_hz, in.freq_hz);
  ASSERT_EQ(out.channels.size(), 12u);
  for (std::size_t c = 0; c < 12; ++c) {
    EXPECT_EQ(out.channels[c].response, in.channels[c].response);
    EXPECT_EQ(out.channels[c].reference, in.channels[c].reference);
    EXPECT_EQ(out.channels[c].values, in.channels[c].values);
    EXPECT_EQ(out.channels[c].line, 2 + static_cast<int>(c * in.freq_hz.size()));
  }
}

struct CsvDefect {
  std::string name;
  int line;          // line to corrupt (1 = header)
  std::string text;  // its new content
  int error_line;
  std::string column;
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const CsvDefect& c, std::ostream* os) { *os << c.name; }

class FrfCsvDefect : public modaltyre_test::ScratchDir,
                     public ::testing::WithParamInterface<CsvDefect> {};

// The base file: two FRFs of three lines (rows 2-4 and 5-7).
TEST_P(FrfCsvDefect, NamesFileLineAndColumn) {
  std::vector<std::string> l = {
      "response_point,response_dir,reference_point,reference_dir,freq_hz,re,im",
      "1,radial,1,radial,10,1,0",
      "1,radial,1,radial,11,2,0",
      "1,radial,1,radial,12,3,0",
      "2,radial,1,radial,10,1,1",
      "2,radial,1,radial,11,1,1",
      "2,radial,1,radial,12,1,1"};
  const CsvDefect d = GetParam();
  l[d.line - 1] = d.text;
  std::string s;
  for (const auto& x : l) s += x + "\n";
  const std::string path = write(s, "bad.csv");
  expect_input_error([&] { read_frf_csv(path, FrfType::accelerance); }, path, d.error_line,
                     d.column);
}

INSTANTIATE_TEST_SUITE_P(
    Rows, FrfCsvDefect,
    ::testing::Values(
        CsvDefect{"UnknownDirection", 3, "1,axial,1,radial,11,2,0", 3, "response_dir"},
        CsvDefect{"PointZero", 3, "1,radial,0,radial,11,2,0", 3, "reference_point"},
        CsvDefect{"PointNotWhole", 3, "1.5,radial,1,radial,11,2,0", 3, "response_point"},
        CsvDefect{"NegativeFrequency", 2, "1,radial,1,radial,-10,1,0", 2, "freq_hz"},
        CsvDefect{"FrequencyNotIncreasing", 4, "1,radial,1,radial,10.5,3,0", 4, "freq_hz"},
        CsvDefect{"OtherGrid", 6, "2,radial,1,radial,11.5,1,1", 6, "freq_hz"},
        CsvDefect{"ShorterFrf", 7, "3,radial,1,radial,10,1,1", 5, "freq_hz"},
        CsvDefect{"NotANumber", 5, "2,radial,1,radial,10,x,1", 5, "re"},
        CsvDefect{"MissingColumn", 1, "response_point,response_dir,reference_point,freq_hz,re,im",
                  1, "reference_dir"}),
    [](const auto& info) { return info.param.name; });

TEST_F(FrfCsv, SizesAreBounded) {
  std::string s = "response_point,response_dir,reference_point,reference_dir,freq_hz,re,im\n";
  for (int p = 1; p <= 3; ++p) {
    for (int f = 0; f < 4; ++f)
      s += std::to_string(p) + ",radial,1,radial," + std::to_string(f) + ",1,0\n";
  }
  const std::string path = write(s, "many.csv");
  FrfLimits lim;
  lim.max_channels = 2;
  expect_input_error([&] { read_frf_csv(path, FrfType::accelerance, lim); }, path, 10,
                     "response_point");
  lim = {};
  lim.max_lines = 3;
  expect_input_error([&] { read_frf_csv(path, FrfType::accelerance, lim); }, path, 2, "freq_hz");
}

// Receptance -> mobility -> accelerance multiplies by j omega each step; the way back divides
// and restores the values to rounding; a line at 0 Hz cannot be divided and is refused.
TEST(FrfType, ConversionsAreConsistent) {
  modaltyre_test::SynthOptions o;
  o.f_lo_hz = 10;
  o.f_hi_hz = 300;
  o.df_hz = 1;
  o.type = FrfType::receptance;
  const FrfSet x = modaltyre_test::synthesise(one_mode(), o);
  o.type = FrfType::mobility;
  const FrfSet v = modaltyre_test::synthesise(one_mode(), o);
  o.type = FrfType::accelerance;
  const FrfSet a = modaltyre_test::synthesise(one_mode(), o);
  const FrfSet x2v = convert_frf_type(x, FrfType::mobility);
  const FrfSet x2a = convert_frf_type(x, FrfType::accelerance);
  const FrfSet a2x = convert_frf_type(a, FrfType::receptance);
  const FrfSet v2a = convert_frf_type(v, FrfType::accelerance);
  for (std::size_t c = 0; c < x.channels.size(); ++c) {
    for (std::size_t i = 0; i < x.freq_hz.size(); ++i) {
      const double scale = std::abs(a.channels[c].values[i]) + 1e-300;
      EXPECT_LT(std::abs(x2v.channels[c].values[i] - v.channels[c].values[i]),
                1e-12 * std::abs(v.channels[c].values[i]) + 1e-300);
      EXPECT_LT(std::abs(x2a.channels[c].values[i] - a.channels[c].values[i]), 1e-12 * scale);
      EXPECT_LT(std::abs(v2a.channels[c].values[i] - a.channels[c].values[i]), 1e-12 * scale);
      EXPECT_LT(std::abs(a2x.channels[c].values[i] - x.channels[c].values[i]),
                1e-12 * std::abs(x.channels[c].values[i]) + 1e-300);
    }
  }
  // Physics: at resonance the accelerance of the driving point is -w^2 times the receptance,
  // whose imaginary part is -phi^2 / (2 zeta w_k^2).
  const double w = 6.283185307179586 * 120;
  const auto& drive = x.channels.front().values[110];  // 120 Hz
  EXPECT_NEAR(drive.imag(), -0.25 / (2 * 0.03 * w * w), 1e-12);
  FrfSet dc = a;
  dc.freq_hz.front() = 0;
  EXPECT_THROW(convert_frf_type(dc, FrfType::receptance), InputError);
  EXPECT_NO_THROW(convert_frf_type(dc, FrfType::accelerance));
}

}  // namespace
}  // namespace modaltyre::ema
