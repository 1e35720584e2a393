// `discover --uncertainty` (issue 35, docs/uncertainty.md section 9): a gap the model's own
// uncertain inputs could produce is not named an effect. Data planted from the 2D SF-350 with
// three modal amplitudes moved by 2.2-3.1 of their standard deviations (the hammer shapes'
// residual noise: mode 4 +8 %, mode 6 +5 %, mode 8 -6 %), noise-free: without the model's
// uncertainty the load pattern the baseline cannot absorb is named belt_flattening; with it,
// that evidence is mostly discounted and nothing is named.
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::CliFixture;

using modaltyre_test::kSrc;

class DiscoverUncertainty : public CliFixture {};

// The bundled hammer CSV with the shapes of some modes scaled (amplitude^2 by factor).
std::string scaled_hammer(const std::map<int, double>& factor) {
  std::istringstream in(modaltyre_test::slurp(kSrc + "/configs/data/sf350_hammer_12pt.csv"));
  std::ostringstream out;
  out.precision(12);
  std::string line;
  std::getline(in, line);
  out << line << "\n";  // mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential
  while (std::getline(in, line)) {
    std::vector<std::string> c(1);
    for (char ch : line) {
      if (ch == ',') {
        c.emplace_back();
      } else {
        c.back().push_back(ch);
      }
    }
    const auto f = factor.find(std::stoi(c[0]));
    const double s = f == factor.end() ? 1.0 : std::sqrt(f->second);
    out << c[0] << "," << c[1] << "," << c[2] << "," << c[3] << "," << c[4] << ","
        << std::stod(c[5]) * s << "," << std::stod(c[6]) * s << "\n";
  }
  return out.str();
}

TEST_F(DiscoverUncertainty, AGapWithinTheModelsUncertaintyIsNotNamed) {
  const auto hammer = dir_ / "hammer_moved.csv";
  std::ofstream(hammer) << scaled_hammer({{4, 1.08}, {6, 1.05}, {8, 0.94}});
  const auto spec = dir_ / "moved.yaml";
  std::ofstream(spec) << "base: " << kSrc << "/configs/sf350_2d_table3.yaml\n"
                      << "set:\n  modal.hammer_csv: " << hammer.string() << "\n"
                      << "grid:\n  load_N: [1500, 2500, 3500, 4500, 5500, 6500, 7500, 8500, "
                         "9500]\noutput: moved.csv\n";
  const auto data = dir_ / "moved.csv";
  const auto sweep = run({"sweep", spec.string(), "--output", data.string()});
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  const std::string config = kSrc + "/configs/sf350_2d_table3.yaml";
  const auto plain = run({"discover", config, data.string(), "--json"});
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const auto p = nlohmann::json::parse(plain.out);
  ASSERT_EQ(p["effects"].size(), 1u) << p["conclusion"];  // the false name this guards against
  const auto with = run({"discover", config, data.string(), "--json", "--uncertainty"});
  ASSERT_EQ(with.exit_code, 0) << with.err;
  const auto w = nlohmann::json::parse(with.out);
  EXPECT_TRUE(w["effects"].empty()) << w["conclusion"];
  EXPECT_FALSE(w["uncertainty_inputs"].empty());
  const auto& first = w["rounds"][0][0];
  EXPECT_EQ(first["name"], p["effects"][0]["name"]);
  EXPECT_GT(first["uncertainty_discount"].get<double>(), 0.5 * first["delta_bic"].get<double>())
      << first;
}

}  // namespace
