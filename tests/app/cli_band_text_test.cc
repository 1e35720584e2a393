// Issue 44 item 2: the text of `--uncertainty` prints each band as value [2.5 %, 97.5 %], the
// JSON's value, p025 and p975 to the printed digits (sinking at 4 kN on the init config was
// printed as 15.8 +- 8.0 while the JSON's skewed band was 13.0-26.3 mm), and says which band it
// is; a band of zero width says that no input moves it.
#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::CliFixture;
using modaltyre_test::CliRun;

using modaltyre_test::kSrc;

class BandText : public CliFixture {};

struct Printed {
  double value, lo, hi;
  double resolution;  // half a unit of the last printed digit
};

// Every "v [a, b]" of a text, in order.
std::vector<Printed> printed_bands(const std::string& text) {
  static const std::regex band(R"((-?\d+(?:\.(\d+))?) \[(-?\d+(?:\.\d+)?), (-?\d+(?:\.\d+)?)\])");
  std::vector<Printed> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), band); it != std::sregex_iterator();
       ++it) {
    const auto& m = *it;
    const int decimals = static_cast<int>(m[2].length());
    out.push_back({std::stod(m[1]), std::stod(m[3]), std::stod(m[4]),
                   0.5 * std::pow(10.0, -decimals) * (1 + 1e-9)});
  }
  return out;
}

TEST_F(BandText, FootprintPrintsThePercentileBandOfItsJson) {
  const std::vector<std::string> args = {
      "footprint", kSrc + "/configs/sf350_init.yaml", "--load", "2000", "4000", "--uncertainty",
      "--set",     "contact.unit_length_mm=2"};
  const CliRun text = run(args);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  auto json_args = args;
  json_args.push_back("--json");
  const CliRun json = run(json_args);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_NE(text.out.find("[2.5 %, 97.5 %]"), std::string::npos) << text.out;
  const auto j = nlohmann::json::parse(json.out);
  const auto printed = printed_bands(text.out);
  std::vector<const nlohmann::json*> bands;
  for (const auto& c : j["cases"]) {
    for (const char* k : {"sinking_mm", "contact_length_mm", "width_mm", "peak_pressure_kPa",
                          "mean_pressure_kPa"}) {
      const auto& b = c["uncertainty"][k];
      if (b["p975"].get<double>() > b["p025"].get<double>()) bands.push_back(&b);
    }
  }
  ASSERT_EQ(printed.size(), bands.size()) << text.out;
  for (std::size_t i = 0; i < printed.size(); ++i) {
    const auto& b = *bands[i];
    EXPECT_NEAR(printed[i].value, b["value"].get<double>(), printed[i].resolution) << b;
    EXPECT_NEAR(printed[i].lo, b["p025"].get<double>(), printed[i].resolution) << b;
    EXPECT_NEAR(printed[i].hi, b["p975"].get<double>(), printed[i].resolution) << b;
    // The sampled band is skewed: value +- 2 sigma would not be it.
    EXPECT_LE(printed[i].lo, printed[i].value);
    EXPECT_GE(printed[i].hi, printed[i].value);
  }
}

// No output of a config init wrote has a band of zero width: the tread width, the compound's
// modulus and the flat crown are assumptions, and init states their spreads (3D and 2D).
TEST_F(BandText, NoOutputOfAnInitConfigHasAZeroBand) {
  for (const bool two_d : {false, true}) {
    const std::string out = (dir_ / (two_d ? "t2d.yaml" : "t3d.yaml")).string();
    std::vector<std::string> init = {"init",
                                     "--size",
                                     "205/55R16",
                                     "--test-pressure-kPa",
                                     "200",
                                     "--frequencies",
                                     "114,137,165,196,228,260",
                                     "--output",
                                     out};
    if (two_d) init.push_back("--2d");
    const CliRun wrote = run(init);
    ASSERT_EQ(wrote.exit_code, 0) << wrote.err;
    const std::string yaml = modaltyre_test::slurp(out);
    for (const char* key : {"modulus_std_percent", "contact_width_std_percent"})
      EXPECT_NE(yaml.find(key), std::string::npos) << key;
    EXPECT_EQ(yaml.find("round_limit_radius_mm") != std::string::npos, !two_d);
    const CliRun f = run({"footprint", out, "--load", "4000", "--uncertainty", "--json"});
    ASSERT_EQ(f.exit_code, 0) << f.err;
    const auto j = nlohmann::json::parse(f.out);
    for (const auto& [name, b] : j["cases"][0]["uncertainty"].items()) {
      EXPECT_GT(b["p975"].get<double>(), b["p025"].get<double>()) << name << (two_d ? " 2D" : "");
      EXPECT_LE(b["p025"].get<double>(), b["value"].get<double>()) << name;
      EXPECT_GE(b["p975"].get<double>(), b["value"].get<double>()) << name;
    }
  }
}

}  // namespace
