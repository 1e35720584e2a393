#pragma once
// Helpers shared by the rheology tests: temporary CSV files and running the CLI.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"

namespace modaltyre::rheology::test {

inline std::string temp_file(const std::string& name, const std::string& content) {
  // One folder per process: ctest -j runs tests of this executable side by side.
  const auto dir = std::filesystem::temp_directory_path() /
                   ("modaltyre_rheology_tests_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  std::ofstream(path) << content;
  return path.string();
}

/// Runs the CLI with arguments; returns its exit code; stdout goes to `out` if given.
inline int run_cli(const std::string& args, const std::string& out = "") {
  const std::string cmd = std::string(MODALTYRE_CLI) + " " + args + " > " +
                          (out.empty() ? std::string("/dev/null") : out) + " 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Fixed-seed Gaussian noise.
struct Noise {
  std::mt19937 rng{20240605u};
  std::normal_distribution<double> n{0.0, 1.0};
  double operator()() { return n(rng); }
};

/// The SF-350's free radius [m] (configs/sf350_2d_table3.yaml).
inline constexpr double kR0 = 0.2948;

/// SF-350 geometry as configs/sf350_2d_table3.yaml gives it (r0 294.8 mm, contact width 130 mm),
/// section height 117 mm, and a 350 kg test mass: the three-element tests' tyre.
inline ThreeElementOptions sf350_three_element_options() {
  ThreeElementOptions o;
  o.r0_m = kR0;
  o.tread_width_m = 0.13;
  o.section_height_m = 0.117;
  o.mass_kg = 350.0;
  return o;
}

/// Rolling tests of a planted Kelvin-Voigt soil (E2 = 3 MPa, eta2 = 50 kPa s) under a rigid
/// wheel r0 = 500 mm, B_tr = 300 mm in a 300 mm layer: front angles 12-24 deg, rear 0.55 of it,
/// speeds 0.5-3 m/s, forces from the model (noise-free).
inline SoilOptions planted_soil_wheel() { return {0.5, 0.3}; }
inline SoilData planted_soil_rows() {
  const SoilOptions o = planted_soil_wheel();
  SoilData data;
  for (double a1 : {12.0, 16.0, 20.0, 24.0})
    for (double V : {0.5, 1.5, 3.0}) {
      SoilRow r;
      r.alpha1_rad = a1 * M_PI / 180;
      r.alpha2_rad = 0.55 * r.alpha1_rad;
      r.total_sinking_m = o.r0_m * (1 - std::cos(r.alpha1_rad));
      r.elastic_sinking_m = o.r0_m * (1 - std::cos(r.alpha2_rad));
      r.layer_m = 0.30;
      r.speed_m_s = V;
      data.rows.push_back(soil_forces(r, 3.0e6, 5.0e4, o));
    }
  return data;
}

}  // namespace modaltyre::rheology::test
