// The hammer CSV's standard-deviation columns (written by `ema`, docs/uncertainty.md section 5)
// reach the propagation's inputs: freq_std_hz becomes each mode's frequency input (added in
// variance to a stated modal.frequency_std_percent), radial_std the noise of the shapes when it
// exceeds the one-harmonic residual's, so the amplitude's std follows it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "../support/data_paths.h"
#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/uncertainty/inputs.h"
#include "planted_ring.h"

namespace modaltyre::uncertainty {
namespace {

namespace fs = std::filesystem;
using modaltyre_test::kConfig2d;
constexpr double kPrintedRound = 1e-9;  // the CSV's printed digits

// Noise-free planted ring shapes (planted_ring.h) with stated standard deviations:
// freq_std_hz = freq_std_rel f, radial_std = tangential_std = shape_std.
std::string hammer_csv(double freq_std_rel, double shape_std, bool all_columns = true) {
  modaltyre_test::PlantedRing o;
  o.precision = 12;
  o.freq_std_rel = freq_std_rel;
  o.shape_std = shape_std;
  o.radial_std_column = all_columns;
  return modaltyre_test::planted_ring_csv(o);
}

class HammerStd : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("modaltyre_hstd_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& text) {
    const fs::path p = dir_ / "h.csv";
    std::ofstream(p) << text;
    return p.string();
  }
  fs::path dir_;
};

TEST_F(HammerStd, FrequencyAndShapeStdBecomeThePropagationsInputs) {
  const double f_rel = 0.004, shape_std = 0.02;
  const std::string csv = write(hammer_csv(f_rel, shape_std));
  for (const double stated_percent : {0.0, 1.0}) {
    const auto config = contact::load_tyre_config(
        kConfig2d, {"modal.hammer_csv=" + csv,
                    "modal.frequency_std_percent=" + std::to_string(stated_percent)});
    const auto modes = contact::config_modes(config);
    int frequencies = 0, amplitudes = 0;
    for (const auto& in : collect_inputs(config, modes)) {
      const auto& m = modes.modes.at(in.mode);
      if (in.kind == InputKind::mode_frequency) {
        ++frequencies;
        EXPECT_NEAR(in.rel_std, std::hypot(f_rel, stated_percent / 100), kPrintedRound) << in.name;
        EXPECT_NE(in.source.find("freq_std_hz"), std::string::npos) << in.source;
      }
      if (in.kind == InputKind::mode_amplitude) {
        ++amplitudes;
        // Noise-free shapes: the residual is zero, the stated noise is the noise; Re c and Im c
        // each carry sigma / sqrt(N/2) (N/2 = 6; N = 12 at order 0), the amplitude |c|^2
        // twice its relative std (a rotation's amplitude is its tangential order-0 term).
        const bool rotation = m.kind == modal::ModeKind::rotation;
        const double n2 = m.apparent_order == 0 ? 12.0 : 6.0;
        const double c = std::abs(rotation ? m.tangential.coefficient(0) : m.c_radial);
        const double expected = 2 * shape_std / std::sqrt(n2) / c;
        EXPECT_NEAR(in.rel_std, expected, 1e-6 * expected) << in.name;
        EXPECT_NE(in.source.find("radial_std"), std::string::npos) << in.source;
      }
    }
    EXPECT_GT(frequencies, 0);
    EXPECT_GT(amplitudes, 0);
  }
}

TEST_F(HammerStd, TheFourColumnsComeTogether) {
  const std::string csv = write(hammer_csv(0.004, 0.02, /*all_columns=*/false));
  try {
    modal::read_hammer_csv(csv);
    FAIL() << "three of the four std columns accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("radial_std"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace modaltyre::uncertainty
