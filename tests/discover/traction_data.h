#pragma once
// Traction test rows made by the model for the discover tests (traction_evidence_test.cc,
// traction_uncertainty_test.cc): each row rolled alone from a cold start, its pull, sinkage and
// torque times (1 + noise N(0, 1)), written as a traction CSV and read back as the CLI reads it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/ground/ground_settings.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::discover::traction_data {

inline const std::string kSource = MODALTYRE_SOURCE_DIR;
inline constexpr double kUnit_mm = 4;  // discover's evaluation mesh in these tests (the data's too)

// The 2D SF-350 (0.9 s per 20-slip curve at its own 0.5 mm mesh; the 3D default takes ~3 s) on
// LETE sand (Wong, Table 2.3), on a 4 mm mesh; `soil_sets`: --set overrides of the soil file.
inline contact::TyreConfig lete_config(const std::vector<std::string>& soil_sets = {}) {
  contact::TyreConfig c =
      contact::load_tyre_config(kSource + "/configs/sf350_2d_table3.yaml",
                                {"contact.unit_length_mm=" + std::to_string(kUnit_mm)});
  c.ground = ground::load_ground_file(kSource + "/configs/soils/lete_sand.yaml", soil_sets);
  return c;
}

struct Row {
  double load_N, slip;
  int pass = 1;
};

inline std::vector<Row> curve_rows(const std::vector<double>& loads,
                                   const std::vector<double>& slips) {
  std::vector<Row> rows;
  for (double F : loads)
    for (double s : slips) rows.push_back({F, s});
  return rows;
}

// A traction CSV's text written and read back as the CLI reads it.
inline studies::MeasurementSet as_measurements(const std::string& csv,
                                               const contact::TyreConfig& config,
                                               const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path p = fs::temp_directory_path() /
                     ("modaltyre_traction_" + std::to_string(::getpid()) + "_" + name + ".csv");
  std::ofstream(p) << csv;
  studies::MeasurementSet set = studies::read_measurements(p.string(), config);
  fs::remove(p);
  return set;
}

// Each row run alone from a cold start (not grouped as TractionRows groups them), its pull,
// sinkage and torque times (1 + noise N(0, 1)), written as CSV and read back as the CLI reads it.
// `base`: the options every row runs with (its speed written as the rows' speed_kmh).
inline studies::MeasurementSet make_traction_data(const contact::TyreConfig& truth,
                                                  const std::vector<Row>& rows, double noise,
                                                  unsigned seed, const std::string& name,
                                                  const contact::TractionOptions& base = {}) {
  const contact::TyreModel model = contact::build_tyre_model(truth);
  std::mt19937 rng(seed);
  std::normal_distribution<double> n01;
  std::ostringstream csv;
  csv.precision(10);
  csv << "load_N,slip,pass,drawbar_pull_N,soil_sinkage_mm,torque_Nm,speed_kmh\n";
  for (const Row& r : rows) {
    contact::TractionOptions o = base;
    o.passes = r.pass;
    const auto res = contact::steady_traction(model, truth.ground, {{r.load_N, r.slip}}, o);
    const contact::TractionResult& t = res.back();
    EXPECT_TRUE(t.ok() && t.pass == r.pass) << t.message;
    auto noisy = [&](double v) { return v * (1 + noise * n01(rng)); };
    csv << r.load_N << "," << r.slip << "," << r.pass << "," << noisy(t.drawbar_pull_N) << ","
        << noisy(t.soil_sinkage_m * 1e3) << "," << noisy(t.torque_Nm) << ","
        << base.speed_m_per_s * 3.6 << "\n";
  }
  return as_measurements(csv.str(), truth, name);
}

}  // namespace modaltyre::discover::traction_data
