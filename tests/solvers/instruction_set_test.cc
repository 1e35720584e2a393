// The kernels' instruction set and its switch MODALTYRE_ISA (solvers/instruction_set.h): the
// values and the CPU decide the path; this process follows its own environment (the kernel tests
// run again with MODALTYRE_ISA=portable, tests/CMakeLists.txt); a wrong value is refused by the
// command line with the variable's name.
#include "modaltyre/solvers/instruction_set.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string>

#include "../app/cli_runner.h"

namespace modaltyre::solvers {
namespace {

TEST(InstructionSet, ValuesCapThePathTheCpuRuns) {
  const auto avx2 = InstructionSet::avx2_fma, portable = InstructionSet::portable;
  // Unset or empty: the best the CPU runs.
  EXPECT_EQ(parse_instruction_set(nullptr, true), avx2);
  EXPECT_EQ(parse_instruction_set("", true), avx2);
  EXPECT_EQ(parse_instruction_set(nullptr, false), portable);
  // portable forces the portable loops; avx2 allows AVX2 + FMA only where the CPU runs them.
  EXPECT_EQ(parse_instruction_set("portable", true), portable);
  EXPECT_EQ(parse_instruction_set("avx2", true), avx2);
  EXPECT_EQ(parse_instruction_set("avx2", false), portable);
  // Anything else is not an instruction set of the kernels.
  for (const char* bad : {"AVX2", "avx512", "sse2", "avx2 ", "native", "0"})
    EXPECT_FALSE(parse_instruction_set(bad, true).has_value()) << bad;
}

TEST(InstructionSet, ThisProcessFollowsItsEnvironment) {
  const char* value = std::getenv(kInstructionSetVariable);
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  const bool cpu = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  const bool cpu = false;
#endif
  EXPECT_EQ(instruction_set(), *parse_instruction_set(value, cpu));
  if (value != nullptr && std::string(value) == "portable") {
    EXPECT_EQ(instruction_set(), InstructionSet::portable);
  }
  EXPECT_NE(instruction_set_label().find(instruction_set_name(instruction_set())),
            std::string::npos);
  EXPECT_NO_THROW(check_instruction_set_variable());
}

class InstructionSetCli : public modaltyre_test::CliFixture {};

TEST_F(InstructionSetCli, AWrongValueIsRefusedWithTheVariablesName) {
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  const auto bad = run_with("env MODALTYRE_ISA=avx512",
                            {"transient", config, "--scenario", "free-vibration", "--json"});
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("MODALTYRE_ISA"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("'avx512'"), std::string::npos) << bad.err;
  EXPECT_TRUE(bad.out.empty()) << bad.out;
}

// The two paths give the same bits (each kernel's stated order of operations): the 3D default's
// free vibration and cleat, the time series and every output of the summary but the timing.
TEST_F(InstructionSetCli, BothPathsGiveTheSameTransient) {
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
  for (const std::string scenario : {"free-vibration", "cleat"}) {
    nlohmann::json out[2];
    std::string series[2];
    const char* isa[2] = {"portable", "avx2"};
    for (int p = 0; p < 2; ++p) {
      const std::string csv = (dir_ / (scenario + "_" + isa[p] + ".csv")).string();
      const auto r =
          run_with(std::string("env MODALTYRE_ISA=") + isa[p],
                   {"transient", config, "--scenario", scenario, "--json", "--csv", csv});
      ASSERT_EQ(r.exit_code, 0) << r.err;
      out[p] = nlohmann::json::parse(r.out);
      out[p].erase("wall_s");
      out[p].erase("real_time_factor");
      series[p] = modaltyre_test::slurp(csv);
    }
    EXPECT_EQ(out[0], out[1]) << scenario;
    EXPECT_GT(out[0].at("samples").get<int>(), 100) << scenario;
    EXPECT_EQ(series[0], series[1]) << scenario;
    EXPECT_GT(series[0].size(), 10000u) << scenario;
  }
}

}  // namespace
}  // namespace modaltyre::solvers
