// Issue 9, input contract: every reader of a user's CSV file (hammer data, the five rheology
// tests, measured data for discover/validate, footprint measurements) against the same table of
// hostile inputs. Each refusal must be an InputError whose message starts with
// "file:line: column: " (line and column as expected, no raw binary bytes); each reader runs as
// the CLI runs it (read, then identify), so that physical rules (time order, equal loads, zero
// pressure) give their physical message. What a reader legitimately accepts (unsorted or
// repeated rows) is checked for a correct result instead.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "../support/hammer_lines.h"
#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/mode_identification.h"
#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/free_vibration.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"
#include "modaltyre/studies/measurements.h"
#include "modaltyre/studies/sweep.h"
#include "modaltyre/studies/validation.h"
#include "rheology_test_support.h"

namespace modaltyre::rheology {
namespace {

namespace fs = std::filesystem;
using Lines = std::vector<std::string>;

using modaltyre_test::kSrc;
using test::kR0;
constexpr double kTread = 0.13;  // SF-350 (configs/sf350_2d_table3.yaml)

const contact::TyreConfig& sf350() {
  static const contact::TyreConfig c =
      contact::load_tyre_config(kSrc + "/configs/sf350_2d_table3.yaml");
  return c;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> f;
  std::stringstream in(line);
  for (std::string c; std::getline(in, c, ',');) f.push_back(c);
  if (!line.empty() && line.back() == ',') f.emplace_back();
  return f;
}

std::string join(const std::vector<std::string>& f, char sep = ',') {
  std::string s;
  for (std::size_t i = 0; i < f.size(); ++i) s += (i ? std::string(1, sep) : "") + f[i];
  return s;
}

std::string file_text(const Lines& l) { return join(l, '\n') + "\n"; }

/// The data lines of a bundled example, header first, comments dropped.
Lines example(const std::string& name) {
  std::ifstream in(kSrc + "/tests/data/rheology/" + name);
  Lines l;
  for (std::string s; std::getline(in, s);) {
    if (!s.empty() && s[0] != '#') l.push_back(s);
  }
  return l;
}

/// A reader as the CLI uses it, with a valid file (header on line 1, >= 3 data rows).
struct Reader {
  std::string name;
  Lines lines;
  std::string column;  ///< a required number column the generic cases corrupt
  std::function<void(const std::string&)> run;

  std::size_t index(const std::string& col) const {
    const auto h = fields(lines[0]);
    return static_cast<std::size_t>(std::find(h.begin(), h.end(), col) - h.begin());
  }
  /// The valid file with cell `col` of file line `line` set to `value`.
  Lines with_cell(int line, const std::string& col, const std::string& value) const {
    Lines l = lines;
    auto f = fields(l[line - 1]);
    f.at(index(col)) = value;
    l[line - 1] = join(f);
    return l;
  }
};

ThreeElementOptions three_element() { return test::sf350_three_element_options(); }

std::vector<Reader> readers() {
  std::vector<Reader> r;
  r.push_back({"hammer", modaltyre_test::hammer_lines(), "radial",
               [](const std::string& p) { modal::identify_modes(modal::read_hammer_csv(p)); }});
  r.push_back(
      {"load-deflection", example("load_deflection.csv"), "load_N", [](const std::string& p) {
         LoadDeflectionOptions o;
         o.r0_m = kR0;
         identify_load_deflection(read_load_deflection_csv(p), o);
       }});
  r.push_back(
      {"free-vibration", example("free_vibration.csv"), "deflection_mm", [](const std::string& p) {
         identify_free_vibration(read_free_vibration_csv(p), nullptr, three_element());
       }});
  r.push_back(
      {"contact-stress", example("contact_stress.csv"), "stress_kPa", [](const std::string& p) {
         ContactStressOptions o;
         o.r0_m = kR0;
         o.tread_width_m = kTread;
         identify_contact_stress(read_contact_stress_csv(p), o);
       }});
  r.push_back({"soil-rolling", example("soil_rolling.csv"), "speed_m_s", [](const std::string& p) {
                 identify_soil(read_soil_rolling_csv(p), {0.5, 0.3});
               }});
  r.push_back(
      {"static-loop", example("static_loop.csv"), "deflection_mm", [](const std::string& p) {
         identify_static_loop(read_static_loop_csv(p), three_element());
       }});
  r.push_back({"measurements (discover)",
               {"load_N,pressure_kPa,branch,sinking_mm,length_mm,status,message",
                "2131,230,load,8,86,ok,converged", "3261,230,load,12,112,ok,converged",
                "5478,230,unload,20,117,ok,\"converged, 9 iterations\""},
               "load_N",
               [](const std::string& p) { studies::read_measurements(p, sf350()); }});
  r.push_back(
      {"footprint (validate)",
       {"load_N,sinking_mm,length_mm", "2131,8,86", "3261,12,112", "5478,20,117", "6502,23,126"},
       "load_N",
       [](const std::string& p) { studies::read_validation_measurements(p, sf350()); }});
  return r;
}

struct Expect {
  int line;
  std::string key;
  std::string words;  ///< must appear in the message
};

struct Case {
  std::string name;
  std::string content;
  Expect want;
};

class HostileReaders : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("modaltyre_hostile_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& content, const std::string& name = "input.csv") {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p.string();
  }

  /// `run` on `path` must throw an InputError at want.line / want.key whose message starts
  /// with "path:line: key: ", contains want.words and has no raw control or non-UTF-8 bytes.
  static void expect_refused(const std::function<void(const std::string&)>& run,
                             const std::string& path, const Expect& want,
                             const std::string& label) {
    SCOPED_TRACE(label);
    try {
      run(path);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(e.where().file, path) << what;
      EXPECT_EQ(e.where().line, want.line) << what;
      EXPECT_EQ(e.where().key, want.key) << what;
      std::string prefix = path;
      if (want.line > 0) prefix += ":" + std::to_string(want.line);
      if (!want.key.empty()) prefix += ": " + want.key;
      EXPECT_EQ(what.rfind(prefix + ": ", 0), 0u) << "want prefix '" << prefix << "' in: " << what;
      EXPECT_NE(what.find(want.words), std::string::npos)
          << "want '" << want.words << "' in: " << what;
      EXPECT_EQ(printable(what, std::numeric_limits<std::size_t>::max()), what)
          << "raw bytes in the message";
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not an InputError: " << e.what();
    }
  }

  void expect_refused(const Reader& r, const Case& c) {
    expect_refused(r.run, write(c.content), c.want, r.name + " / " + c.name);
  }

  fs::path dir_;
};

// The cases every reader refuses the same way (the CSV layer's rules).
std::vector<Case> generic_cases(const Reader& r) {
  const auto header = fields(r.lines[0]);
  const std::string col = r.column, last = header.back();
  const std::string extra_col = "column " + std::to_string(header.size() + 1);
  std::vector<Case> c;
  c.push_back({"empty file", "", {1, "", "empty"}});
  c.push_back({"comments only", "# nothing yet\n\n", {2, "", "empty"}});
  c.push_back({"header only", r.lines[0] + "\n", {1, "", "no data rows"}});
  {
    Lines l = r.lines;  // the column removed from the header and every row
    for (auto& s : l) {
      auto f = fields(s);
      f.erase(f.begin() + static_cast<long>(r.index(col)));
      s = join(f);
    }
    c.push_back({"missing column", file_text(l), {1, col, "required column is missing"}});
  }
  {
    Lines l = r.lines;
    l[0] += ",bogus_col";
    for (std::size_t i = 1; i < l.size(); ++i) l[i] += ",1";
    c.push_back({"unknown column", file_text(l), {1, "bogus_col", "unknown column"}});
  }
  {
    Lines l = r.lines;
    l[2] += ",7";
    c.push_back({"extra field in a row", file_text(l), {3, extra_col, "has no column"}});
    l = r.lines;
    l[2] = l[2].substr(0, l[2].rfind(','));
    c.push_back({"missing field in a row", file_text(l), {3, last, "no value for this column"}});
  }
  for (const std::string bad :
       {"abc", "12 kN", "1.2.3", "0x", "nan", "NaN", "inf", "-inf", "1e999", "-1e400"}) {
    c.push_back({"cell '" + bad + "'",
                 file_text(r.with_cell(3, col, bad)),
                 {3, col, "is not a finite number"}});
  }
  c.push_back(
      {"empty number cell", file_text(r.with_cell(3, col, "")), {3, col, "not a finite number"}});
  c.push_back({"non-UTF-8 number cell",
               file_text(r.with_cell(3, col, "12\xE9")),
               {3, col, "'12\\xE9' is not a finite number (bytes that are not UTF-8"}});
  {
    Lines l = r.lines;
    auto h = fields(l[0]);
    h[r.index(col)] += "\xFF";
    l[0] = join(h);
    c.push_back({"non-UTF-8 header", file_text(l), {1, col + "\\xFF", "unknown column"}});
  }
  c.push_back({"NUL byte",
               file_text(r.with_cell(3, col, std::string("1\0", 2))),
               {3, col, "control or binary byte \\x00"}});
  c.push_back({"unterminated quote",
               file_text(r.with_cell(3, col, "\"12")),
               {3, col, "unterminated quoted field"}});
  c.push_back({"line break inside quotes",
               file_text(r.with_cell(3, col, "\"1\n2\"")),
               {3, col, "unterminated quoted field"}});
  c.push_back({"text after a closing quote",
               file_text(r.with_cell(3, col, "\"12\"3")),
               {3, col, "after the closing quote"}});
  {
    std::string u16 = "\xFF\xFE";
    for (char ch : file_text(r.lines)) u16 += std::string{ch, '\0'};
    c.push_back({"UTF-16 file", u16, {1, "", "UTF-16"}});
  }
  c.push_back({"CR-only line ends",
               join(r.lines, '\r') + "\r",
               {1, "column " + std::to_string(header.size()), "carriage return"}});
  return c;
}

TEST_F(HostileReaders, EveryReaderRefusesEveryGenericCaseNamingFileLineAndColumn) {
  for (const auto& r : readers()) {
    ASSERT_NO_THROW(r.run(write(file_text(r.lines), "valid.csv"))) << r.name;
    for (const auto& c : generic_cases(r)) expect_refused(r, c);
  }
}

TEST_F(HostileReaders, DirectoryMissingFileAndPipeNameTheFile) {
  const std::string folder = (dir_ / "folder.csv").string();
  fs::create_directories(folder);
  for (const auto& r : readers()) {
    expect_refused(r.run, folder, {0, "", "is a directory"}, r.name + " / directory");
    expect_refused(r.run, (dir_ / "absent.csv").string(), {0, "", "file not found"},
                   r.name + " / missing");
  }
}

// A file far beyond any measurement table is refused before a byte of it is read (a sparse
// file: no disk, no memory), never an out-of-memory.
TEST_F(HostileReaders, HugeFileIsRefusedBeforeReading) {
  const std::string big = (dir_ / "huge.csv").string();
  std::ofstream(big).close();
  fs::resize_file(big, std::uintmax_t{65} << 20);
  for (const auto& r : readers()) {
    expect_refused(r.run, big, {0, "", "is 65 MB; refusing CSV files over 64 MB"},
                   r.name + " / huge");
  }
}

// More rows than the reader's limit: refused at the first row over it.
TEST_F(HostileReaders, TooManyRowsAreRefusedAtTheLineOverTheLimit) {
  std::string s = "load_N,pressure_kPa,deflection_mm\n";
  s.reserve(14'000'000);
  for (int i = 0; i < 1'000'001; ++i) s += "2000,150,15.4\n";
  expect_refused([](const std::string& p) { read_load_deflection_csv(p); }, write(s),
                 {1'000'002, "", "more than 1000000 data rows; refusing"}, "too many rows");
}

// Rules of each test's physics: refused with the physical message at the row's line.
TEST_F(HostileReaders, PhysicalRulesGiveThePhysicalMessage) {
  const auto all = readers();
  auto reader = [&](const std::string& name) {
    return *std::find_if(all.begin(), all.end(), [&](const Reader& r) { return r.name == name; });
  };
  struct Row {
    std::string reader;
    Case c;
  };
  std::vector<Row> rows;
  // Cell `col` of data row 2 (file line 3) set to `value`.
  auto cell = [&](const std::string& name, const std::string& col, const std::string& value,
                  const std::string& words) {
    rows.push_back(
        {name,
         {col + " = " + value, file_text(reader(name).with_cell(3, col, value)), {3, col, words}}});
  };
  // File line `line` repeated just after itself.
  auto dup = [](Lines l, int line) {
    l.insert(l.begin() + line, l[line - 1]);
    return file_text(l);
  };

  const std::string hammer = "hammer";
  cell(hammer, "freq_hz", "0", "frequency must be in (0, 1e5] Hz");
  cell(hammer, "damping_ratio", "3", "not a percentage");
  cell(hammer, "damping_ratio", "-0.01", "[0, 1)");
  cell(hammer, "mode", "0", "positive whole number");
  cell(hammer, "point", "2.5", "positive whole number");
  cell(hammer, "freq_hz", "1e300", "frequency must be in (0, 1e5] Hz");
  cell(hammer, "freq_hz", "150", "different frequency or damping than on line 2");
  // Squares of such shapes overflowed in the harmonic fits: "-nan" in fit-modes' table.
  cell(hammer, "tangential", "-1e300", "within +-1e6 kg^-1/2");
  rows.push_back({hammer,
                  {"duplicated row",
                   dup(reader(hammer).lines, 3),
                   {4, "point", "duplicate point 2 of mode 1 (first at line 3)"}}});

  const std::string ld = "load-deflection";
  for (const std::string v : {"0", "-2000", "1e300"}) cell(ld, "load_N", v, "(0, 1e7] N");
  for (const std::string v : {"0", "-50", "1e300"}) {
    cell(ld, "pressure_kPa", v, "eq. (3) describes an inflated tyre");
  }
  cell(ld, "deflection_mm", "0", "deflection must be > 0 mm");
  cell(ld, "deflection_mm", "400", "deflection exceeds the radius r0");
  {
    const Lines l = reader(ld).lines;  // one measurement, twice: nothing to fit a law to
    rows.push_back({ld,
                    {"one row duplicated",
                     dup({l[0], l[1]}, 2),
                     {3, "load_N", "equal loads at the same pressure (as line 2)"}}});
  }

  const std::string fv = "free-vibration";
  {
    Lines l = reader(fv).lines;
    std::swap(l[2], l[3]);  // file lines 3 and 4
    rows.push_back({fv,
                    {"unsorted time",
                     file_text(l),
                     {4, "t_s", "time must increase strictly (line 3 has t_s = 0.002)"}}});
    rows.push_back(
        {fv,
         {"duplicated row", dup(reader(fv).lines, 3), {4, "t_s", "time must increase strictly"}}});
  }

  const std::string cs = "contact-stress";
  cell(cs, "stress_kPa", "-5", "contact stress must be >= 0 kPa");
  cell(cs, "x_mm", "-400", "abscissa beyond the tyre radius r0");

  const std::string soil = "soil-rolling";
  for (const std::string v : {"0", "-1000", "1e300"}) cell(soil, "load_N", v, "(0, 1e7] N");
  cell(soil, "longitudinal_force_N", "-1e300", "[-1e7, 1e7] N");
  for (const std::string v : {"0", "-0.5"}) cell(soil, "speed_m_s", v, "must be > 0 m/s");
  cell(soil, "alpha1_deg", "0", "must be in (0, 90) deg");
  cell(soil, "alpha2_deg", "13", "elastic recovery");
  cell(soil, "total_sinking_mm", "0", "must be > 0 mm");
  cell(soil, "elastic_sinking_mm", "11", "(0, total_sinking_mm]");
  cell(soil, "layer_mm", "5", "thicker than the total sinking");

  const std::string loop = "static-loop";
  for (const std::string v : {"0", "-600", "1e300"}) cell(loop, "load_N", v, "[1e-6, 1e7] N");
  cell(loop, "deflection_mm", "0", "deflection must be > 0 mm");
  cell(loop, "deflection_mm", "300", "deflection exceeds the radius r0");
  cell(loop, "branch", "loading\xE9",
       "'loading\\xE9' is not one of: load, unload (or loading, unloading)");
  {
    Lines l = reader(loop).lines;  // the optional pressure column, zero on file line 3
    l[0] += ",pressure_kPa";
    for (std::size_t i = 1; i < l.size(); ++i) l[i] += i == 2 ? ",0" : ",230";
    rows.push_back({loop,
                    {"zero pressure",
                     file_text(l),
                     {3, "pressure_kPa", "gauge inflation pressure must be in (0, 2000]"}}});
  }

  const std::string meas = "measurements (discover)";
  // 1e-300 N: the 3D patch printed a mean pressure of inf (issue 16 audit).
  for (const std::string v : {"0", "1e-300", "1e300"}) cell(meas, "load_N", v, "[1e-6, 1e7] N");
  cell(meas, "pressure_kPa", "0", "(0, 2000] kPa");
  cell(meas, "sinking_mm", "-8", "must be > 0 mm");
  cell(meas, "length_mm", "1e300", "must be at most 1e4 mm");
  cell(meas, "branch", "lo\xE9", "'lo\\xE9' is not one of: load, unload");
  cell(meas, "status", "failed", "row is marked 'failed'");

  const std::string fp = "footprint (validate)";
  // 1e-300 N: the 3D patch printed a mean pressure of inf (issue 16 audit).
  for (const std::string v : {"0", "1e-300", "1e300"}) cell(fp, "load_N", v, "[1e-6, 1e7] N");
  cell(fp, "length_mm", "-112", "must be > 0 mm");
  cell(fp, "sinking_mm", "1e300", "must be at most 1e4 mm");
  rows.push_back({fp,
                  {"duplicated row",
                   dup(reader(fp).lines, 3),
                   {4, "load_N", "duplicate load (same as line 3)"}}});

  for (const auto& [name, c] : rows) expect_refused(reader(name), c);
}

// Free vibration: a zero or negative mass (a CLI option, not a file) is refused by name.
TEST_F(HostileReaders, ZeroOrNegativeMassIsRefused) {
  const DecaySignal s = read_free_vibration_csv(kSrc + "/tests/data/rheology/free_vibration.csv");
  for (double m : {0.0, -350.0}) {
    ThreeElementOptions o = three_element();
    o.mass_kg = m;
    try {
      identify_free_vibration(s, nullptr, o);
      ADD_FAILURE() << "mass " << m << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--mass-kg"), std::string::npos) << e.what();
    }
  }
}

// ---- What the readers legitimately accept: the result must be the right one. ----

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// Unsorted rows and repeated rows (a repeated measurement) leave an exact law's fit exact.
TEST_F(HostileReaders, LoadDeflectionAcceptsUnsortedAndRepeatedRows) {
  const double K = 0.13e-3;
  Lines l = {"load_N,pressure_kPa,deflection_mm"};
  for (double p : {230.0, 150.0})
    for (double P : {6000.0, 2000.0, 4000.0, 3000.0})
      l.push_back(num(P) + "," + num(p) + "," + num(law_deflection(K, P, p * 1e3) * 1e3));
  l.push_back(l[2]);
  const LoadDeflectionData d = read_load_deflection_csv(write(file_text(l)));
  ASSERT_EQ(d.rows.size(), 9u);
  EXPECT_EQ(d.rows[8].line, 10);
  EXPECT_EQ(d.rows[8].load_N, 2000.0);
  LoadDeflectionOptions o;
  o.r0_m = kR0;
  EXPECT_NEAR(identify_load_deflection(d, o).K_Z_m / K, 1.0, 1e-9);
}

TEST_F(HostileReaders, ContactStressAcceptsUnsortedAndRepeatedRows) {
  const double K1 = 2.5e7, h = 0.018;
  Lines l = {"x_mm,stress_kPa"};
  for (int i = 0; i <= 60; ++i) {
    const double x = -120.0 + 4.0 * ((i * 37) % 61);  // every abscissa once, shuffled
    l.push_back(num(x) + "," + num(contact_stress_law(K1, x * 1e-3, h, kR0) * 1e-3));
  }
  l.push_back(l[30]);
  const StressData d = read_contact_stress_csv(write(file_text(l)));
  ASSERT_EQ(d.rows.size(), 62u);
  ContactStressOptions o;
  o.r0_m = kR0;
  o.tread_width_m = kTread;
  const auto r = identify_contact_stress(d, o);
  EXPECT_NEAR(r.K1_Pa_per_m / K1, 1.0, 1e-3);
  EXPECT_NEAR(r.deflection_m / h, 1.0, 1e-3);
}

TEST_F(HostileReaders, SoilAcceptsUnsortedAndRepeatedRows) {
  const double E2 = 3.0e6, eta2 = 5.0e4, deg = M_PI / 180, r0 = 0.5;
  const SoilOptions o{r0, 0.3};
  Lines l = {
      "load_N,longitudinal_force_N,alpha1_deg,alpha2_deg,total_sinking_mm,elastic_sinking_mm,"
      "layer_mm,speed_m_s"};
  for (double a1 : {24.0, 12.0, 20.0, 16.0})
    for (double V : {3.0, 0.5, 1.5}) {
      SoilRow s;
      s.alpha1_rad = a1 * deg;
      s.alpha2_rad = 0.55 * a1 * deg;
      s.total_sinking_m = r0 * (1 - std::cos(s.alpha1_rad));
      s.elastic_sinking_m = r0 * (1 - std::cos(s.alpha2_rad));
      s.layer_m = 0.3;
      s.speed_m_s = V;
      s = soil_forces(s, E2, eta2, o);
      l.push_back(
          join({num(s.load_N), num(s.longitudinal_force_N), num(a1), num(0.55 * a1),
                num(s.total_sinking_m * 1e3), num(s.elastic_sinking_m * 1e3), "300", num(V)}));
    }
  l.push_back(l[5]);
  const SoilData d = read_soil_rolling_csv(write(file_text(l)));
  ASSERT_EQ(d.rows.size(), 13u);
  const auto r = identify_soil(d, o);
  EXPECT_NEAR(r.E2_Pa / E2, 1.0, 1e-6);
  EXPECT_NEAR(r.eta2_Pa_s / eta2, 1.0, 1e-6);
}

TEST_F(HostileReaders, StaticLoopAcceptsUnsortedAndRepeatedRows) {
  const double E1 = 1.2e6, chi = 0.02;
  const auto o = three_element();
  Lines l = {"load_N,deflection_mm,branch"};
  for (int i : {3, 1, 4, 2})
    for (bool loading : {false, true}) {
      const double h = 0.004 * i;
      l.push_back(num(static_loop_load(E1, chi, h, loading, o)) + "," + num(h * 1e3) + "," +
                  (loading ? "loading" : "unloading"));
    }
  l.push_back(l[1]);
  const StaticLoop loop = read_static_loop_csv(write(file_text(l)));
  ASSERT_EQ(loop.rows.size(), 9u);
  EXPECT_FALSE(loop.rows[0].loading);
  const auto r = identify_static_loop(loop, o);
  EXPECT_NEAR(r.E1_Pa / E1, 1.0, 1e-9);
  EXPECT_NEAR(r.chi / chi, 1.0, 1e-9);
}

// Hammer rows in any order: each mode's points come back sorted by angle, values with them.
TEST_F(HostileReaders, HammerAcceptsUnsortedPoints) {
  Lines l = modaltyre_test::hammer_lines();
  std::reverse(l.begin() + 1, l.begin() + 13);  // mode 1's twelve points, last first
  const auto d = modal::read_hammer_csv(write(file_text(l)));
  const auto ref =
      modal::read_hammer_csv(write(file_text(modaltyre_test::hammer_lines()), "r.csv"));
  ASSERT_EQ(d.modes.size(), 2u);
  EXPECT_EQ(d.modes[0].angle_rad, ref.modes[0].angle_rad);
  EXPECT_EQ(d.modes[0].radial, ref.modes[0].radial);
  EXPECT_EQ(d.modes[0].tangential, ref.modes[0].tangential);
  EXPECT_EQ(d.modes[0].first_line, 2);
  EXPECT_TRUE(std::is_sorted(d.modes[0].angle_rad.begin(), d.modes[0].angle_rad.end()));
}

// Measured data keep their file order (calibration rows are numbered in it).
TEST_F(HostileReaders, MeasuredRowsKeepTheirFileOrder) {
  const auto v = studies::read_validation_measurements(
      write("load_N,sinking_mm\n5478,20\n2131,8\n3261,12\n"), sf350());
  ASSERT_EQ(v.rows.size(), 3u);
  EXPECT_EQ(v.rows[0].conditions.load_N, 5478);
  EXPECT_EQ(v.rows[1].row, 2);
  EXPECT_EQ(v.rows[1].conditions.load_N, 2131);
  EXPECT_EQ(v.rows[2].line, 4);
  const auto m = studies::read_measurements(
      write("load_N,pressure_kPa,sinking_mm\n5478,230,20\n2131,200,8\n", "m.csv"), sf350());
  ASSERT_EQ(m.rows.size(), 2u);
  EXPECT_EQ(m.rows[0].conditions.load_N, 5478);
  EXPECT_EQ(m.rows[1].conditions.pressure_kPa, 200);
}

// A sweep's CSV quotes messages with commas or quotes (csv_field); read back as measured data
// (discover, validate), every row arrives with its numbers and the message in one piece.
TEST_F(HostileReaders, SweepQuotedMessagesAreReadBack) {
  const std::string msg = "converged, 9 active-set iterations; \"warm\" start";
  const std::string quoted = studies::csv_field(msg);
  ASSERT_EQ(quoted.front(), '"');
  const std::string content =
      "tread.modulus_MPa,load_N,branch,sinking_mm,length_mm,status,message\n"
      "2.33,2131,load,8,86,ok," +
      quoted +
      "\n"
      "2.33,3261,load,12,112,ok," +
      studies::csv_field("plain") +
      "\n"
      "\"2.33\",5478,\"unload\",20,117,ok," +
      quoted + "\n";
  const std::string path = write(content);
  const auto m = studies::read_measurements(path, sf350());
  ASSERT_EQ(m.rows.size(), 3u);
  EXPECT_EQ(m.rows[0].observed.at("length_mm"), 86);
  EXPECT_EQ(m.rows[2].conditions.load_N, 5478);
  EXPECT_EQ(m.rows[2].conditions.branch, contact::Branch::unloading);
  EXPECT_EQ(m.rows[2].line, 4);
  const auto v = studies::read_validation_measurements(path, sf350());
  ASSERT_EQ(v.rows.size(), 3u);
  EXPECT_EQ(v.rows[1].value("sinking_mm"), 12);
  // The message cell, as read_csv returns it, is the text the sweep wrote.
  CsvSchema schema;
  schema.required = {"message"};
  schema.text = {"message"};
  schema.accept_text_column = [](const std::string&) { return true; };
  const CsvTable t = read_csv(path, schema);
  EXPECT_EQ(t.text(0, "message"), msg);
  EXPECT_EQ(t.text(1, "message"), "plain");
  EXPECT_EQ(t.text(2, "branch"), "unload");
}

}  // namespace
}  // namespace modaltyre::rheology
