// The 3D patch's outputs end to end (issue 18): `footprint` prints the width, its JSON carries
// width_mm and the pressure map per case, --map-csv writes the map, --plot the footprint image;
// `validate` compares and calibrates on measured widths; `discover` keeps its catalogue honest.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::kConfig3d;
using modaltyre_test::kTable3;
const std::string k2d = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_fig5.yaml";

class Footprint3dCli : public modaltyre_test::CliFixture {};

TEST_F(Footprint3dCli, TextTablePrintsTheWidthGrowingWithLoadInsideTheTread) {
  const auto r = run({"footprint", kConfig3d, "--load", "2131", "--load", "8321"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  std::string line;
  std::vector<double> widths;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.find("width_mm") != std::string::npos) header = true;
    double load = 0, sinking = 0, length = 0, width = 0;
    if (header &&
        std::sscanf(line.c_str(), "%lf %lf %lf %lf", &load, &sinking, &length, &width) == 4) {
      widths.push_back(width);
    }
  }
  ASSERT_TRUE(header) << r.out;
  ASSERT_EQ(widths.size(), 2u) << r.out;
  EXPECT_GT(widths[0], 50);
  EXPECT_LT(widths[0], widths[1]);
  EXPECT_LE(widths[1], 150);  // footprint_3d.tread_width_mm: the shoulder limit
}

// The map is the cell pressures: integrated over the cells it carries the load, symmetric in y.
TEST_F(Footprint3dCli, JsonCarriesWidthAndAMapThatCarriesTheLoad) {
  const auto r = run({"footprint", kConfig3d, "--load", "3261", "--load", "7322", "--json"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"]["patch"], "3d");
  EXPECT_EQ(j["model"]["tread_width_mm"], 150);
  ASSERT_EQ(j["cases"].size(), 2u);
  for (const auto& c : j["cases"]) {
    const double load = c["load_N"].get<double>();
    ASSERT_TRUE(c.contains("width_mm"));
    EXPECT_GT(c["width_mm"].get<double>(), 100);
    const auto& m = c["map"];
    const auto x = m["x_mm"].get<std::vector<double>>();
    const auto y = m["y_mm"].get<std::vector<double>>();
    const auto p = m["pressure_kPa"].get<std::vector<std::vector<double>>>();
    ASSERT_EQ(p.size(), y.size());  // one row per y
    ASSERT_EQ(y.size(), 30u);       // 150 mm in 5 mm columns
    const double dy_mm = y[1] - y[0];
    double force = 0, area_mm2 = 0;
    for (std::size_t k = 0; k < y.size(); ++k) {
      ASSERT_EQ(p[k].size(), x.size());
      for (std::size_t i = 1; i + 1 < x.size(); ++i) {
        EXPECT_NEAR(p[k][i], p[y.size() - 1 - k][i], 1e-4 * (1 + p[k][i]));  // symmetric in y
        const double cell_mm2 = 0.5 * (x[i + 1] - x[i - 1]) * dy_mm;
        force += p[k][i] * 1e3 * cell_mm2 * 1e-6;
        if (p[k][i] > 0) area_mm2 += cell_mm2;
      }
    }
    EXPECT_NEAR(c["contact_area_mm2"].get<double>(), area_mm2, 0.005 * area_mm2);
    // Map positions are the deformed sections' (dx within 0.5 % of the cells' own length).
    EXPECT_NEAR(force, load, 0.005 * load);
    EXPECT_LT(c["contact_area_mm2"].get<double>(),
              c["width_mm"].get<double>() * c["contact_length_mm"].get<double>());
  }
}

TEST_F(Footprint3dCli, MapCsvHasOneLinePerCellOfEachCaseAndMatchesTheJson) {
  const auto csv = (dir_ / "map.csv").string();
  const auto r = run({"footprint", kConfig3d, "--load", "5478", "--json", "--map-csv", csv});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& m = j["cases"][0]["map"];
  std::istringstream in(modaltyre_test::slurp(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "load_N,x_mm,y_mm,pressure_kPa");
  std::size_t rows = 0;
  double peak = 0;
  while (std::getline(in, line)) {
    double load = 0, x = 0, y = 0, p = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf", &load, &x, &y, &p), 4) << line;
    EXPECT_EQ(load, 5478);
    peak = std::max(peak, p);
    ++rows;
  }
  EXPECT_EQ(rows, m["x_mm"].size() * m["y_mm"].size());
  EXPECT_NEAR(peak, j["cases"][0]["peak_pressure_kPa"].get<double>(), 1e-3 * peak);
}

// footprint --uncertainty --map-csv (issue 35): the band as two more maps. Every cell lies in
// its band; the peak cell's band is the peak pressure's (the same quantity while the peak stays
// in that cell under the +-1 sigma perturbations); cells out of contact have none.
TEST_F(Footprint3dCli, MapCsvCarriesTheBandAsTwoMaps) {
  const auto csv = (dir_ / "map_band.csv").string();
  const auto r = run({"footprint", kConfig3d, "--load", "5478", "--json", "--map-csv", csv,
                      "--uncertainty", "--uncertainty-method", "linear"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  std::istringstream in(modaltyre_test::slurp(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "load_N,x_mm,y_mm,pressure_kPa,pressure_p025_kPa,pressure_p975_kPa");
  double peak = -1, peak_lo = 0, peak_hi = 0;
  std::size_t rows = 0, outside = 0;
  while (std::getline(in, line)) {
    double load = 0, x = 0, y = 0, p = 0, lo = 0, hi = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &load, &x, &y, &p, &lo, &hi), 6)
        << line;
    EXPECT_LE(lo, p + 1e-6 * (1 + p)) << line;
    EXPECT_GE(hi, p - 1e-6 * (1 + p)) << line;
    if (p == 0 && hi == 0) ++outside;
    if (p > peak) peak = p, peak_lo = lo, peak_hi = hi;
    ++rows;
  }
  EXPECT_GT(outside, 0u);  // the map's margin and the tread's corners
  const auto& band = j["cases"][0]["uncertainty"]["peak_pressure_kPa"];
  const double width = band["p975"].get<double>() - band["p025"].get<double>();
  ASSERT_GT(width, 0);
  EXPECT_NEAR((peak_hi - peak_lo) / width, 1.0, 0.02);
}

TEST_F(Footprint3dCli, MapCsvIsRefusedWithExitTwoOnA2dConfigOrABadPath) {
  auto r = run({"footprint", k2d, "--load", "5000", "--map-csv", (dir_ / "m.csv").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("footprint_3d"), std::string::npos) << r.err;
  EXPECT_FALSE(modaltyre_test::fs::exists(dir_ / "m.csv"));
  r = run(
      {"footprint", kConfig3d, "--load", "5000", "--map-csv", (dir_ / "no" / "m.csv").string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--map-csv"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
  r = run({"footprint", kConfig3d, "--load", "5000", "--map-csv", dir_.string()});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("directory"), std::string::npos) << r.err;
}

TEST_F(Footprint3dCli, PlotDrawsTheFootprintImageWithContourAndCentreLine) {
  const auto svg = (dir_ / "fp.svg").string();
  const auto r = run({"footprint", kConfig3d, "--load", "2131", "--load", "8321", "--plot", svg});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = modaltyre_test::slurp(svg);
  EXPECT_NE(text.find("</svg>"), std::string::npos);
  EXPECT_NE(text.find("<image"), std::string::npos);  // the pressure map as a raster
  EXPECT_NE(text.find("W = "), std::string::npos);    // each image states its width
  EXPECT_NE(text.find("centre-line contact pressure"), std::string::npos);
  EXPECT_NE(text.find("pressure [kPa]"), std::string::npos);  // the colour bar
}

TEST_F(Footprint3dCli, HorizontalForceIsRefusedWithExitTwo) {
  const auto r = run({"footprint", kConfig3d, "--load", "5000", "--fx", "500"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--fx"), std::string::npos) << r.err;
}

// The config's declared calibration (compliance scale and crown radius on sinking and width of
// rows 1 and 6) reproduces its stated values; the width of rows 2-5 is a prediction.
TEST_F(Footprint3dCli, ValidateComparesAndCalibratesOnMeasuredWidth) {
  const auto r = run({"validate", kConfig3d, kTable3, "--json", "--set", "modal.compliance_scale=1",
                      "--set", "footprint_3d.crown.radius_mm=800"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["calibrated"]["modal.compliance_scale"].get<double>(), 0.93595, 2e-3);
  EXPECT_NEAR(j["calibrated"]["footprint_3d.crown.radius_mm"].get<double>(), 1058.5, 5);
  EXPECT_EQ(j["calibration"]["observables"], (nlohmann::json{"sinking_mm", "width_mm"}));
  EXPECT_EQ(j["predicted_rows"]["width_mm"], 4);
  for (const auto& row : j["rows"]) {
    const double w = row["predicted"]["width_mm"].get<double>();
    EXPECT_NEAR(row["rel_error"]["width_mm"].get<double>(),
                w / row["measured"]["width_mm"].get<double>() - 1, 1e-6);
  }
  const double width_rms = j["rms_rel_error"]["width_mm"].get<double>();
  EXPECT_GT(width_rms, 0.0);
  EXPECT_LT(width_rms, 0.10);  // docs/validation.md: 8.5 %
}

TEST_F(Footprint3dCli, ValidateRefusesAFourthCalibratedKey) {
  const auto r = run({"validate", kConfig3d, kTable3, "--set",
                      "validation.calibrate=[modal.compliance_scale, footprint_3d.crown.radius_mm, "
                      "tread.modulus_MPa, tread.thickness_mm]"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("validation.calibrate"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("three"), std::string::npos) << r.err;
}

// On the 3D patch discover re-fits the crown radius and offers no effect the patch refuses.
// On 4 mm sections and 10 mm columns: what is checked is which parameters and candidates the 3D
// patch takes, not the mesh (the 1 mm default tries every candidate for ~60 s of CPU, too long
// under the sanitizers).
TEST_F(Footprint3dCli, DiscoverOnTable3RefitsTheCrownAndOffersNoRefusedEffect) {
  const auto r = run({"discover", kConfig3d, kTable3, "--json", "--max-effects", "1",
                      "--unit-length-mm", "4", "--set", "footprint_3d.lateral_cell_mm=10"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["baseline_parameters"].contains("footprint_3d.crown.radius_mm"));
  EXPECT_FALSE(j["baseline_parameters"].contains("tread.modulus_MPa"));
  EXPECT_TRUE(j["gap_before"].contains("width_mm"));
  for (const auto& c : j["candidates"]) {
    const std::string name = c["name"];
    if (name == "contact_width") {
      EXPECT_FALSE(c["testable"].get<bool>()) << name;
      EXPECT_NE(c["reason"].get<std::string>().find("3D patch"), std::string::npos);
    }
  }
}

// The transient runs the 3D patch of a 3D config (docs/transient.md section 7): --json carries
// the width and the contact area, --map-times / --map-csv the contact maps.
TEST_F(Footprint3dCli, TransientRunsThe3dPatchWithWidthAndMaps) {
  const auto map = (dir_ / "tmap.csv").string();
  const auto r =
      run({"transient", kConfig3d, "--scenario", "free-vibration", "--json", "--set",
           "contact.unit_length_mm=2", "--set", "footprint_3d.lateral_cell_mm=7.5", "--set",
           "transient.free_vibration.duration_s=0.06", "--map-times", "0,0.05", "--map-csv", map});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["patch"], "3d");
  EXPECT_GT(j["final"]["width_mm"].get<double>(), 50.0);
  EXPECT_GT(j["final"]["contact_area_mm2"].get<double>(), 1000.0);
  const std::string text = modaltyre_test::slurp(map);
  EXPECT_EQ(text.rfind("time_s,x_mm,y_mm,pressure_kPa\n", 0), 0u) << text.substr(0, 80);
  EXPECT_NE(text.find("\n0.05,"), std::string::npos);
}

}  // namespace
