// Mode identification: harmonic order, kind and spatial aliasing of hammer-test modes, on a
// synthetic held-out tyre (N = 12 and N = 18) and on the bundled SF-350 data.
#include "modaltyre/modal/mode_identification.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "modal_test_constants.h"
#include "modaltyre/modal/hammer_data.h"

namespace modaltyre::modal {
namespace {

using test::kPi;
// Ring mass normalisation of data/README: a^2 = 1/(pi mu R), 1/(2 pi mu R) for k = 0.
using test::kMu;
using test::kR;
// Measurement noise of the held-out tyre, as a fraction of the radial amplitude.
constexpr double kNoise = 0.05;
// Pair members of one order differ in frequency by this factor (slight non-axisymmetry).
constexpr double kPairSplit = 1.008;
// An aliased mode's true order counts as unambiguous when every other alias candidate's
// frequency on the true dispersion law is at least this far (in log) from the measured one;
// pair split (0.8 %) and fit error (< 1 %) are an order of magnitude smaller.
constexpr double kUnambiguousLog = 0.10;

/// Held-out tyre: f_k^2 = A + B k^2, a pair per order 1..top, breathing, rigid rotation.
struct SyntheticMode {
  int id;
  double freq_hz;
  int order;  ///< true order; -1 = rigid rotation
};
constexpr double kA = 85.0 * 85.0, kB = 24.0 * 24.0;  // [Hz^2]
double law_hz(int k) { return std::sqrt(kA + kB * k * k); }

/// `breathing_after`: the breathing mode lies between orders b and b+1 of the radial family.
std::vector<SyntheticMode> held_out_modes(int breathing_after, int top) {
  std::vector<SyntheticMode> m;
  for (int k = 1; k <= top; ++k) {
    m.push_back({0, law_hz(k), k});
    m.push_back({0, law_hz(k) * kPairSplit, k});
  }
  // Breathing between orders 1 and 2 as on the SF-350 (125.6 Hz between 113 and 134 Hz), or
  // higher: it is an extensional mode outside the radial family and may lie above orders >= 2.
  // Rigid rotation up among the aliased orders (as the SF-350's 250 Hz).
  m.push_back({0, 0.5 * (law_hz(breathing_after) + law_hz(breathing_after + 1)), 0});
  m.push_back({0, 0.5 * (law_hz(7) + law_hz(8)), -1});
  std::sort(m.begin(), m.end(), [](auto& a, auto& b) { return a.freq_hz < b.freq_hz; });
  for (std::size_t i = 0; i < m.size(); ++i) m[i].id = static_cast<int>(i + 1);
  return m;
}

/// Writes the held-out tyre as an N-point hammer CSV; returns its path.
std::string write_held_out(int N, const std::vector<SyntheticMode>& modes, unsigned seed, int tag) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 2 * kPi);
  std::normal_distribution<double> gauss(0, 1);
  const double a1 = 1 / std::sqrt(kPi * kMu * kR), a0 = 1 / std::sqrt(2 * kPi * kMu * kR);
  const auto path = std::filesystem::temp_directory_path() /
                    ("modaltyre_held_out_" + std::to_string(::getpid()) + "_" + std::to_string(N) +
                     "_" + std::to_string(seed) + "_" + std::to_string(tag) + ".csv");
  std::ofstream out(path);
  out << "mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential\n";
  out.precision(10);
  std::map<int, double> first_psi;  // order -> phase of the first pair member
  for (const auto& m : modes) {
    const int k = m.order;
    double psi = U(rng);
    if (k > 0 && (2 * k) % N == 0) {
      // Order N/2: the samples see a (-1)^i cos(k psi); a shape with its nodes on the sample
      // points is invisible to any method, so keep both twins >= 50 % visible.
      psi = (kPi / 4 + (U(rng) / (2 * kPi) - 0.5) * kPi / 6) / k;
    }
    if (k > 0) {
      if (first_psi.count(k))
        psi = first_psi[k] + kPi / (2 * k);  // orthogonal twin
      else
        first_psi[k] = psi;
    }
    const double a = k == 0 || k < 0 ? a0 : a1;
    for (int i = 0; i < N; ++i) {
      const double th = 2 * kPi * i / N;
      double r, t;
      if (k < 0) {
        r = 0.0;  // rigid rotation: no radial motion, constant tangential
        t = a;
      } else if (k == 0) {
        r = a;
        t = 0.0;
      } else {
        r = a * std::cos(k * (th - psi));
        t = a / k * std::sin(k * (th - psi));
      }
      r += kNoise * a * gauss(rng);
      t += kNoise * a * gauss(rng);
      out << m.id << ',' << m.freq_hz << ",0.03," << i + 1 << ',' << 360.0 * i / N << ',' << r
          << ',' << t << '\n';
    }
  }
  return path.string();
}

/// Apparent order of true order k sampled at N points (folding).
int folded(int k, int N) {
  const int r = k % N;
  return std::min(r, N - r);
}

class HeldOutTyre : public ::testing::TestWithParam<std::tuple<int, unsigned, int>> {};

// Breathing placed between orders 1-2, 3-4 or 7-8 of the family.
// Every resolvable mode (k < N/2) is radial with the right order and not aliased; every mode
// with k >= N/2 is flagged aliased with its folded apparent order and, where the dispersion of
// the resolved orders makes it unambiguous, the right likely order; the rotation is found.
TEST_P(HeldOutTyre, OrdersKindsAndAliasing) {
  const auto [N, seed, breathing_after] = GetParam();
  // Orders up to 10 as the brief's tyre, and up to N + 1 so that orders N - 1, N, N + 1 fold
  // onto apparent orders 1, 0, 1 (where they meet breathing and rigid translation).
  const auto truth = held_out_modes(breathing_after, std::max(10, N + 1));
  const auto path = write_held_out(N, truth, seed, breathing_after);
  const auto data = read_hammer_csv(path);
  ASSERT_EQ(data.points, N);
  const auto id = identify_modes(data);
  ASSERT_EQ(id.modes.size(), truth.size());

  int unambiguous_checked = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const auto& t = truth[i];
    const auto& m = id.modes[i];
    SCOPED_TRACE("N=" + std::to_string(N) + " mode " + std::to_string(m.id) + " true order " +
                 std::to_string(t.order) + " at " + std::to_string(t.freq_hz) + " Hz");
    ASSERT_EQ(m.id, t.id);
    if (t.order < 0) {
      EXPECT_EQ(m.kind, ModeKind::rotation);
      EXPECT_FALSE(m.aliased);
      continue;
    }
    EXPECT_EQ(m.kind, ModeKind::radial);
    EXPECT_EQ(m.apparent_order, folded(t.order, N));
    if (2 * t.order < N) {
      EXPECT_FALSE(m.aliased);
      EXPECT_EQ(m.order(), t.order);
      continue;
    }
    EXPECT_TRUE(m.aliased);
    // The true order must be among the listed candidates.
    EXPECT_NE(std::find(m.alias_candidates.begin(), m.alias_candidates.end(), t.order),
              m.alias_candidates.end());
    // Unambiguous on the true law: all other orders that fold onto the same apparent order
    // (and are unresolvable) are far away in frequency.
    std::vector<int> competitors;  // other unresolvable orders that fold here, at a similar f
    for (int c = N / 2; c <= 5 * N; ++c) {
      if (c == t.order || folded(c, N) != m.apparent_order) continue;
      if (std::abs(std::log(law_hz(c) / t.freq_hz)) < kUnambiguousLog) competitors.push_back(c);
    }
    if (competitors.empty()) {
      EXPECT_EQ(m.likely_order, t.order);
      EXPECT_EQ(m.order(), t.order);
      ++unambiguous_checked;
    } else {
      // Ambiguous (e.g. orders N - 1 and N + 1 within 10 %): one of the close orders.
      competitors.push_back(t.order);
      EXPECT_NE(std::find(competitors.begin(), competitors.end(), m.likely_order),
                competitors.end());
    }
  }
  // Nearly every aliased order is unambiguous on this law: make sure the check really ran.
  int aliased_true = 0;
  for (const auto& t : truth) aliased_true += (t.order >= 0 && 2 * t.order >= N);
  EXPECT_GE(unambiguous_checked, aliased_true - 2);
  // The resolved orders >= 2 give the dispersion law back.
  ASSERT_TRUE(id.dispersion.valid);
  std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(Points, HeldOutTyre,
                         ::testing::Combine(::testing::Values(12, 18),
                                            ::testing::Values(1u, 2u, 3u),
                                            ::testing::Values(1, 3, 7)),
                         [](const auto& info) {
                           return std::to_string(std::get<0>(info.param)) + "Points_Seed" +
                                  std::to_string(std::get<1>(info.param)) + "_BreathingAfterOrder" +
                                  std::to_string(std::get<2>(info.param));
                         });

// Bundled SF-350 data (seed 001 Table 2 frequencies): orders 1,1,0,2,2,3,3,4,4,5,5 for modes
// 1-11; modes 12, 13, 15, 16 aliased with likely orders 6, 6, 7, 8; mode 14 rigid rotation.
TEST(Sf350, TableTwoModes) {
  const auto data =
      read_hammer_csv(std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_hammer_12pt.csv");
  ASSERT_EQ(data.points, 12);
  const auto id = identify_modes(data);
  ASSERT_EQ(id.modes.size(), 16u);
  const int orders[] = {1, 1, 0, 2, 2, 3, 3, 4, 4, 5, 5};
  for (int i = 0; i < 11; ++i) {
    const auto& m = id.modes[i];
    EXPECT_EQ(m.id, i + 1);
    EXPECT_EQ(m.kind, ModeKind::radial) << "mode " << m.id;
    EXPECT_EQ(m.apparent_order, orders[i]) << "mode " << m.id;
    EXPECT_FALSE(m.aliased) << "mode " << m.id;
  }
  const std::map<int, int> likely = {{12, 6}, {13, 6}, {15, 7}, {16, 8}};
  for (const auto& [mode, order] : likely) {
    const auto& m = id.modes[mode - 1];
    EXPECT_EQ(m.kind, ModeKind::radial) << "mode " << mode;
    EXPECT_TRUE(m.aliased) << "mode " << mode;
    EXPECT_EQ(m.likely_order, order) << "mode " << mode;
  }
  EXPECT_EQ(id.modes[13].kind, ModeKind::rotation);
  EXPECT_FALSE(id.modes[13].aliased);
  EXPECT_TRUE(id.dispersion.valid);
  EXPECT_EQ(id.dispersion.orders_used, 4);  // orders 2..5
}

}  // namespace
}  // namespace modaltyre::modal
