// The plate's shape and data that cannot determine Bekker's law (rheology/bevameter.h, docs/soil.md
// section 6, issues 44 and 48): b the radius of a circular plate, the width of a rectangular one;
// an ambiguous header refused; one sinkage per plate refused; impossible fits warned with the
// data's reason.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/rheology/bevameter.h"
#include "rheology_test_support.h"

namespace modaltyre::rheology {
namespace {

std::string input_error(const std::string& name, const std::string& text) {
  try {
    identify_bevameter(read_plate_sinkage_csv(test::temp_file(name, text)));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// LETE sand on circular plates of 50 and 100 mm radius: b is the radius, so k_c comes back as
// planted from the radius column (given as the diameter it would come back doubled).
TEST(BevameterPlates, ACircularPlatesBIsItsRadius) {
  std::ostringstream csv;
  csv.precision(17);
  csv << "plate_radius_mm,sinkage_mm,pressure_kPa\n";
  for (double r : {0.05, 0.1})
    for (double z = 0.005; z <= 0.0501; z += 0.005)
      csv << r * 1e3 << "," << z * 1e3 << "," << (102 / r + 5301) * std::pow(z, 0.79) << "\n";
  const PlateData d = read_plate_sinkage_csv(test::temp_file("round.csv", csv.str()));
  EXPECT_EQ(d.shape, PlateShape::circular);
  const BevameterResult r = identify_bevameter(d);
  EXPECT_NEAR(r.k_c, 102, 1e-3);
  EXPECT_NEAR(r.k_phi, 5301, 1e-2);
  EXPECT_NE(r.report.notes[0].find("Bekker's b = the plate's radius"), std::string::npos);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(BevameterPlates, AnAmbiguousPlateSizeIsRefused) {
  const std::string diameter =
      input_error("diam.csv", "plate_diameter_mm,sinkage_mm,pressure_kPa\n100,5,10\n");
  EXPECT_NE(diameter.find("plate_diameter_mm"), std::string::npos) << diameter;
  EXPECT_NE(diameter.find("plate_radius_mm"), std::string::npos) << diameter;
  const std::string both = input_error(
      "both.csv", "plate_width_mm,plate_radius_mm,sinkage_mm,pressure_kPa\n100,50,5,10\n");
  EXPECT_NE(both.find("both plate_width_mm and plate_radius_mm"), std::string::npos) << both;
  const std::string none = input_error("none.csv", "sinkage_mm,pressure_kPa\n5,10\n");
  EXPECT_NE(none.find("plate_width_mm"), std::string::npos) << none;
}

// Issue 44, "false precision": one sinkage per plate (n = 0.774 +- 0.002 before) and every row at
// one point (n = 0.215 +- 1.4e-17 before) cannot determine the law.
TEST(BevameterPlates, DataThatCannotDetermineTheLawAreRefused) {
  const std::string one =
      input_error("one.csv",
                  "plate_width_mm,sinkage_mm,pressure_kPa\n50,10,120\n50,10,121\n200,20,"
                  "240\n200,20,238\n");
  EXPECT_NE(one.find("at one sinkage"), std::string::npos) << one;
  EXPECT_NE(one.find("sinkage_mm"), std::string::npos) << one;
  const std::string point =
      input_error("point.csv",
                  "plate_width_mm,sinkage_mm,pressure_kPa\n50,10,120\n50,10,120\n200,10,"
                  "120\n200,10,120\n");
  EXPECT_NE(point.find("at one sinkage"), std::string::npos) << point;
  // Two sinkages per plate but one pressure at both: a pressure that does not grow with sinkage
  // (n at the search's floor), determined but impossible: warned with the data's reason.
  const PlateData flat = read_plate_sinkage_csv(
      test::temp_file("flat.csv",
                      "plate_width_mm,sinkage_mm,pressure_kPa\n50,10,120\n50,20,120\n200,10,"
                      "120\n200,20,120\n"));
  const BevameterResult r = identify_bevameter(flat);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings[0].find("outside 0-2"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("does not grow"), std::string::npos) << r.warnings[0];
}

TEST(BevameterPlates, ImpossibleFitsAreWarnedWithTheDatasReason) {
  // n = 2.5: a pressure rising as z^2.5 (a hard layer under the plate).
  std::ostringstream csv;
  csv << "plate_width_mm,sinkage_mm,pressure_kPa,cycle\n";
  for (double b : {0.05, 0.2})
    for (double z = 0.005; z <= 0.0301; z += 0.005)
      csv << b * 1e3 << "," << z * 1e3 << "," << (50 / b + 3e5) * std::pow(z, 2.5) << ",0\n";
  // Two unloading cycles whose slopes rise faster than z_max: 1e4 kN/m^3 at 10 mm, 6e4 at 30 mm
  // (k0 = -1.5e4 < 0).
  for (auto [zmax, ku, cycle] : {std::tuple{0.01, 1e4, 1}, std::tuple{0.03, 6e4, 2}}) {
    const double pmax = (50 / 0.05 + 3e5) * std::pow(zmax, 2.5);
    for (double dz : {0.0, 0.00005, 0.0001})
      csv << 50 << "," << (zmax - dz) * 1e3 << "," << pmax - ku * dz << "," << cycle << "\n";
  }
  const BevameterResult r =
      identify_bevameter(read_plate_sinkage_csv(test::temp_file("hard.csv", csv.str())));
  EXPECT_NEAR(r.n, 2.5, 1e-4);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_NE(r.warnings[0].find("n = 2.5 is outside 0-2"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("as z^2.5"), std::string::npos) << r.warnings[0];
  EXPECT_NEAR(r.k0, -1.5e4, 1);
  EXPECT_NE(r.warnings[1].find("k0 = -15000 kN/m^3 < 0"), std::string::npos) << r.warnings[1];
  EXPECT_NE(r.warnings[1].find("10000 at 10 mm, 60000 at 30 mm"), std::string::npos)
      << r.warnings[1];
  // The physical fit a soil file takes instead: k_u = Au z_max through the origin.
  EXPECT_NEAR(r.Au_through_origin, (1e4 * 0.01 + 6e4 * 0.03) / (0.01 * 0.01 + 0.03 * 0.03), 1);
}

}  // namespace
}  // namespace modaltyre::rheology
