// `sweep --uncertainty` (issue 35, docs/uncertainty.md section 8): each case's standard
// deviations of sinking, length and width are footprint --uncertainty's at the same loads, and
// the CSV reads back as measured data with them as the rows' noise.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "../support/data_paths.h"
#include "cli_runner.h"

namespace {

using modaltyre_test::CliFixture;

using modaltyre_test::kSrc;
constexpr double kPrinted = 1e-9;  // %.10g in the CSV, round_sig in the JSON

class SweepBands : public CliFixture {};

// Splits a CSV line (the sweep's: no quoted commas in these rows).
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out(1);
  for (char c : line) {
    if (c == ',') {
      out.emplace_back();
    } else {
      out.back().push_back(c);
    }
  }
  return out;
}

TEST_F(SweepBands, CasesCarryFootprintsStdAndReadBackAsNoise) {
  const auto csv = dir_ / "loads.csv";
  const auto sweep = run({"sweep", kSrc + "/configs/sweeps/table3_loads.yaml", "--uncertainty",
                          "--output", csv.string(), "--threads", "2"});
  ASSERT_EQ(sweep.exit_code, 0) << sweep.err;
  const auto fp = run({"footprint", kSrc + "/configs/sf350_2d_table3.yaml", "--uncertainty",
                       "--json", "--uncertainty-method", "auto"});
  ASSERT_EQ(fp.exit_code, 0) << fp.err;
  const auto j = nlohmann::json::parse(fp.out);
  std::istringstream text(modaltyre_test::slurp(csv));
  std::string line;
  std::getline(text, line);
  const auto header = cells(line);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(col("length_std_mm"), header.size()) << line;
  std::size_t row = 0;
  while (std::getline(text, line)) {
    const auto c = cells(line);
    ASSERT_LT(row, j["cases"].size());
    const auto& u = j["cases"][row]["uncertainty"];
    const double s = std::stod(c[col("sinking_std_mm")]), l = std::stod(c[col("length_std_mm")]);
    EXPECT_GT(s, 0.0);
    EXPECT_NEAR(s, u["sinking_mm"]["std"].get<double>(), kPrinted * 10) << line;
    EXPECT_NEAR(l, u["contact_length_mm"]["std"].get<double>(), kPrinted * 100) << line;
    ++row;
  }
  EXPECT_EQ(row, j["cases"].size());
  // Read back as measured data, the std columns as the rows' noise (the values are the model's
  // own, so every row lies inside its band).
  const auto v = run({"validate", kSrc + "/configs/sf350_2d_table3.yaml", csv.string(),
                      "--uncertainty", "--json", "--set", "validation.calibrate=[]"});
  ASSERT_EQ(v.exit_code, 0) << v.err;
  // Parsed into a named value: a range-for over a temporary's member dangles before C++23.
  const auto vj = nlohmann::json::parse(v.out);
  for (const auto& r : vj["rows"]) {
    EXPECT_TRUE(r["outside_band"].empty()) << r;
  }
}

}  // namespace
