// Issue 16: the physical lower bounds of the config keys. A tiny positive value (1e-308) of a
// width, mass, load, ramp or length was a failed computation (exit 1) or a run without end; it
// is an input error naming the key and the allowed range, and the bound itself is accepted.
#include "modaltyre/contact/tyre_config.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <ostream>
#include <string>

#include "../support/data_paths.h"
#include "modaltyre/core/errors.h"

namespace {

using modaltyre::InputError;
using modaltyre::contact::load_tyre_config;

using modaltyre_test::kConfig2d;
using modaltyre_test::kConfig3d;
using modaltyre_test::kSrc;

struct Bound {
  std::string name;    // test name
  std::string config;  // the bundled config the key belongs to
  std::string key;     // dotted key
  std::string lowest;  // the smallest accepted value
  std::string range;   // as the message states it
};

// Test names and the "GetParam() =" note print the case's name, not its bytes.
void PrintTo(const Bound& b, std::ostream* os) { *os << b.name; }

// The error of `key=value` on `config`, or "" when it is accepted.
std::string error_of(const Bound& b, const std::string& value) {
  try {
    load_tyre_config(b.config, {b.key + "=" + value});
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "--set");
    EXPECT_EQ(e.where().key, b.key);
    return e.what();
  }
  return "";
}

class PhysicalLowerBound : public ::testing::TestWithParam<Bound> {};

TEST_P(PhysicalLowerBound, TinyValueIsAnInputErrorStatingTheRange) {
  const Bound& b = GetParam();
  for (const char* tiny : {"1e-308", "5e-324"}) {
    const std::string msg = error_of(b, tiny);
    EXPECT_NE(msg.find(b.range), std::string::npos) << tiny << ": " << msg;
  }
}

TEST_P(PhysicalLowerBound, TheBoundItselfIsAccepted) {
  EXPECT_EQ(error_of(GetParam(), GetParam().lowest), "");
}

INSTANTIATE_TEST_SUITE_P(
    Keys, PhysicalLowerBound,
    ::testing::Values(
        Bound{"TreadWidth", kConfig3d, "footprint_3d.tread_width_mm", "20", "[20, 2000]"},
        Bound{"LateralBeltBending", kConfig3d, "footprint_3d.lateral_belt.bending_stiffness_Nm",
              "0.18", "[0.18, 1e+12]"},
        Bound{"TanDelta", kConfig2d, "tread.tan_delta", "0.01", "0 (an elastic tread)"},
        Bound{"HubMass", kConfig2d, "transient.hub_mass_kg", "0.1", "[0.1, 100000]"},
        Bound{"TreadReferenceFrequency", kConfig2d, "transient.tread_reference_frequency_hz",
              "0.001", "[0.001, 10000]"},
        Bound{"LoadHoldLoad", kConfig2d, "transient.load_hold.load_N", "10", "[10, 1e+07]"},
        Bound{"FreeVibrationLoad", kConfig2d, "transient.free_vibration.load_N", "10",
              "[10, 1e+07]"},
        Bound{"FreeVibrationInitialLoad", kConfig2d, "transient.free_vibration.initial_load_N",
              "10", "[10, 1e+07]"},
        Bound{"RollingLoad", kConfig2d, "transient.rolling.load_N", "10", "[10, 1e+07]"},
        Bound{"CleatLoad", kConfig2d, "transient.cleat.load_N", "10", "[10, 1e+07]"},
        // The output step of sf350_2d_table3.yaml is 2 ms.
        Bound{"RollingRamp", kConfig2d, "transient.rolling.ramp_s", "0.002",
              "0 (a speed step) or at least one output step (transient.output_step_ms) in [0.002"},
        Bound{"CleatRamp", kConfig2d, "transient.cleat.ramp_s", "0.002",
              "0 (a speed step) or at least one output step (transient.output_step_ms) in [0.002"},
        // Four candidate units of 0.5 mm.
        Bound{"CleatLength", kConfig2d, "transient.cleat.length_mm", "2", "[2, 2000]"}),
    [](const ::testing::TestParamInfo<Bound>& info) { return info.param.name; });

TEST(PhysicalLowerBounds, ZeroStillMeansOffForTheRampsAndTheLossFactor) {
  EXPECT_EQ(load_tyre_config(kConfig2d, {"transient.rolling.ramp_s=0"}).transient.rolling.ramp_s,
            0);
  EXPECT_EQ(load_tyre_config(kConfig2d, {"transient.cleat.ramp_s=0"}).transient.cleat.ramp_s, 0);
  EXPECT_EQ(load_tyre_config(kConfig2d, {"tread.tan_delta=0"}).tread.tan_delta, 0);
}

// In a file the message names the file and the key's line.
TEST(PhysicalLowerBounds, AFileValueIsNamedAtItsLine) {
  std::ifstream in(kConfig2d);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "hub_mass_kg: 20";
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos);
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
  text.replace(at, from.size(), "hub_mass_kg: 1e-308");
  const auto dir = std::filesystem::temp_directory_path() /
                   ("modaltyre_tyre_config_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir / "data");
  std::filesystem::copy_file(kSrc + "/configs/data/sf350_hammer_12pt.csv",
                             dir / "data/sf350_hammer_12pt.csv",
                             std::filesystem::copy_options::overwrite_existing);
  const std::string path = (dir / "tiny_hub.yaml").string();
  std::ofstream(path) << text;
  try {
    load_tyre_config(path);
    ADD_FAILURE() << "a hub of 1e-308 kg was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, path);
    EXPECT_EQ(e.where().line, line);
    EXPECT_EQ(e.where().key, "transient.hub_mass_kg");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
