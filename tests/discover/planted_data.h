#pragma once
// Measurement sets with planted effects for the discover tests: rows predicted by the SF-350
// model on discover's own 2 mm mesh with hidden effect values, relative Gaussian noise (seeded),
// written as CSV and read back like the CLI reads them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/studies/measurements.h"

namespace modaltyre::discover::planted {

using contact::Branch;
using contact::OperatingConditions;
using contact::Surface;
using contact::TyreConfig;

inline const std::string kConfig =
    std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
// The default tyre: the 3D patch.
inline const std::string kConfig3d = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
// The carcass with the dispersion extension (orders up to the mesh's Nyquist order) instead of
// the default's measured orders only.
inline const std::string kExtended = "modal.extend_orders=true";

struct Planted {
  std::string effect;                                  // name; "" = none
  std::function<void(contact::EffectsConfig&)> truth;  // switches it on with hidden values
  /// An option effect's truth (contact/effects.h): sets the option's keys in the config.
  std::function<void(TyreConfig&)> option_truth;
  std::string config = kConfig;          // the tyre config the data come from and discover runs on
  std::map<std::string, double> hidden;  // key -> planted value
  std::vector<OperatingConditions> rows;
  std::vector<std::string> observables = {"sinking_mm", "length_mm"};
  double noise = 0.015;
  unsigned seed = 1;
  std::vector<std::string> overrides;  // of the tyre config, for data and discover alike
  double unit_length_mm = 2;           // the data's mesh (discover's --unit-length-mm)
};

/// Test names print the planted effect and the size, not the struct's bytes.
inline void PrintTo(const Planted& p, std::ostream* os) {
  *os << (p.effect.empty() ? "no effect" : p.effect) << ", " << p.rows.size() << " rows, "
      << 100 * p.noise << " % noise";
}

inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + ";";
  return s;
}

// Writes the measurement CSV of a planted data set and reads it back like the CLI would.
inline studies::MeasurementSet make_data(const Planted& p, const std::string& name) {
  // One generator per tyre config, built once.
  static std::map<std::string, std::pair<TyreConfig, std::unique_ptr<const contact::TyreModel>>>
      generators;
  std::vector<std::string> o = p.overrides;
  o.push_back("contact.unit_length_mm=" + std::to_string(p.unit_length_mm));
  auto it = generators.find(p.config + joined(o));
  if (it == generators.end()) {
    TyreConfig c = contact::load_tyre_config(p.config, o);
    auto g = std::make_unique<const contact::TyreModel>(contact::build_tyre_model(c));
    it = generators.emplace(p.config + joined(o), std::make_pair(std::move(c), std::move(g))).first;
  }
  const TyreConfig& gen_cfg = it->second.first;
  const contact::TyreModel& gen = *it->second.second;
  TyreConfig truth = gen_cfg;
  if (p.truth) p.truth(truth.effects);
  if (p.option_truth) p.option_truth(truth);
  std::mt19937 rng(p.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const auto path = std::filesystem::temp_directory_path() /
                    ("modaltyre_hidden_" + std::to_string(::getpid()) + "_" + name + ".csv");
  std::ofstream out(path);
  out << "load_N,pressure_kPa,hold_s,speed_kmh,branch,surface";
  for (const auto& o : p.observables) out << "," << o;
  out << "\n";
  out.precision(10);
  for (const auto& c : p.rows) {
    const contact::Prediction pr = contact::predict(gen, contact::parameters_of(truth), c);
    EXPECT_TRUE(pr.ok()) << pr.message;
    out << c.load_N << "," << c.pressure_kPa << "," << c.hold_s << "," << c.speed_kmh << ","
        << contact::branch_name(c.branch) << "," << contact::surface_name(c.surface);
    for (const auto& o : p.observables) out << "," << pr.observable(o) * (1 + p.noise * unit(rng));
    out << "\n";
  }
  out.close();
  return studies::read_measurements(path.string(), gen_cfg);
}

inline std::vector<OperatingConditions> grid(
    const std::vector<double>& loads, const std::function<void(OperatingConditions&, int)>& vary,
    int levels) {
  static const TyreConfig cfg = contact::load_tyre_config(kConfig);
  std::vector<OperatingConditions> rows;
  for (int l = 0; l < levels; ++l) {
    for (double f : loads) {
      OperatingConditions c = cfg.default_conditions(f);
      if (vary) vary(c, l);
      rows.push_back(c);
    }
  }
  return rows;
}

// A creeping tread (creep ratio 0.8, 40 s) hidden in twelve 2D SF-350 footprints: six loads,
// each standing and held 60 s, seed 3 (fold_start_test.cc, configured_start_test.cc).
inline Planted creeping_tread() {
  Planted p;
  p.truth = [](auto& e) {
    e.tread_relaxation.enabled = true;
    e.tread_relaxation.creep_ratio = 0.8;
    e.tread_relaxation.time_constant_s = 40;
  };
  const double hold[] = {0, 60};
  p.rows = grid(
      {2000, 3200, 4400, 5600, 6800, 8000}, [&](auto& c, int l) { c.hold_s = hold[l]; }, 2);
  p.seed = 3;
  return p;
}

inline const std::vector<double> kLoads5 = {2000, 3500, 5000, 6500, 8000};
inline const std::vector<double> kLoads9 = {1500, 2500, 3500, 4500, 5500, 6500, 7500, 8500, 9500};

}  // namespace modaltyre::discover::planted
