// The carcass from frequencies alone (contact/carcass_source.h, docs/ring_model.md): a planted
// ring's static compliance comes back from its frequencies, its pressure and belt width; a free
// test's order-1 mode is moved to the held wheel; the operating pressure acts (the config's
// and a row's, the same way); the refusals name their keys.
#include "modaltyre/contact/carcass_source.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/config_tree.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::contact {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;
// Exact relations through one NNLS fit of exact data: rounding of the 4-unknown solve.
constexpr double kExactRelTol = 1e-7;

// A planted ring (passenger order of magnitude): mu 2.8 kg/m on R0 0.3 m, T = p b R at
// 200 kPa over b = 0.15 m, EI 1.5 N m^2, k_r 2.2 MN/m^2, k_t 0.7 MN/m^2.
struct Ring {
  double mu = 2.8, R = 0.3, p = 200e3, b = 0.15, EI = 1.5, kr = 2.2e6, kt = 0.7e6;
  double T(double pressure) const { return pressure * b * R; }
  // K_n at pressure p2 with membrane sidewalls (foundation proportional to the pressure).
  double K(int n, double p2) const {
    const double m = double(n) * n - 1, s = p2 / p;
    return EI * m * m / std::pow(R, 4) + T(p2) / (R * R) * m + s * (kr + kt / (double(n) * n));
  }
  double hz(int n) const { return std::sqrt(K(n, p) / (mu * (1 + 1.0 / (n * n)))) / kTwoPi; }
};

std::string list(const std::vector<double>& v) {
  std::ostringstream s;
  s.precision(17);
  s << "[";
  for (std::size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
  return s.str() + "]";
}

// A 2D config of the planted ring's frequencies of orders 1-6 (plus `modal_extra` keys).
TyreConfig ring_config(const Ring& r, double operating_kPa, const std::string& modal_extra,
                       std::vector<double> f1_override = {}) {
  std::vector<double> f;
  for (int n = 1; n <= 6; ++n) f.push_back(r.hz(n));
  if (!f1_override.empty()) f[0] = f1_override[0];
  const std::string yaml =
      "tyre:\n  outer_radius_mm: 300\n  inflation_pressure_kPa: " + std::to_string(operating_kPa) +
      "\nmodal:\n  frequencies_hz: " + list(f) + "\n  orders: [1, 2, 3, 4, 5, 6]\n" +
      "  test_pressure_kPa: 200\n  belt_width_mm: 150\n" + modal_extra +
      "tread:\n  modulus_MPa: 3\n  thickness_mm: 8\n  contact_width_mm: 150\n"
      "contact:\n  unit_length_mm: 2\n  window_mm: 300\n";
  return read_tyre_config(ConfigTree::from_string(yaml, "ring.yaml"));
}

TEST(CarcassSource, PlantedRingComplianceComesBackFromFrequenciesAndTension) {
  const Ring r;
  const TyreModel m = build_tyre_model(ring_config(r, 200, ""));
  EXPECT_TRUE(m.carcass.ring);
  EXPECT_EQ(m.carcass.mass_source, "tension");
  EXPECT_NEAR(m.carcass.mass_per_length_kg_m, r.mu, kExactRelTol * r.mu);
  EXPECT_NEAR(m.carcass.tension_N, r.T(r.p), kExactRelTol * r.T(r.p));
  // Measured orders and the extension alike: 1 / (pi R K_n), whatever the mass.
  for (int n : {1, 2, 4, 6, 9, 20, 60}) {
    const double expected = 1.0 / (M_PI * r.R * r.K(n, r.p));
    EXPECT_NEAR(m.basis.static_rr(n), expected, kExactRelTol * expected) << n;
  }
}

// A free test: the order-1 frequency is the two-mass system's (belt 2 pi R mu, wheel 7 kg); the
// carcass gets the held K_1 back.
TEST(CarcassSource, FreeTestOrderOneIsMovedToTheHeldWheel) {
  const Ring r;
  const double mb = kTwoPi * r.R * r.mu, mw = 7.0;
  const double k1 = M_PI * r.R * r.K(1, r.p);  // translation stiffness [N/m]
  const double free_hz = std::sqrt(k1 * (1 / mb + 1 / mw)) / kTwoPi;
  const TyreModel held = build_tyre_model(ring_config(r, 200, ""));
  const TyreModel free_test =
      build_tyre_model(ring_config(r, 200, "  boundary: free\n  wheel_mass_kg: 7\n", {free_hz}));
  const double expected = 1.0 / (M_PI * r.R * r.K(1, r.p));
  EXPECT_NEAR(free_test.basis.static_rr(1), expected, 1e-6 * expected);
  EXPECT_NEAR(free_test.basis.static_rr(1), held.basis.static_rr(1), 1e-6 * expected);
  // Taken as held, the free frequency makes order 1 stiffer: by (1 + m_b / m_w) = 1.75 at the
  // same mass, by less here because the off-family order 1 also moves the ring fit (and the
  // tension's mass); at least a quarter either way.
  const TyreModel naive = build_tyre_model(ring_config(r, 200, "", {free_hz}));
  EXPECT_GT(expected / naive.basis.static_rr(1), 1.25);
}

// The operating pressure moves every order to K_n(p): the tension exactly, membrane sidewalls in
// proportion, bending not. The config's pressure and a row's pressure give the same footprint.
TEST(CarcassSource, OperatingPressureActsOnTheRingTerms) {
  const Ring r;
  const TyreModel at250 = build_tyre_model(ring_config(r, 250, ""));
  for (int n : {1, 2, 5, 30}) {
    const double expected = 1.0 / (M_PI * r.R * r.K(n, 250e3));
    EXPECT_NEAR(at250.basis.static_rr(n), expected, 1e-6 * expected) << n;
  }
  const TyreModel at200 = build_tyre_model(ring_config(r, 200, ""));
  auto row = at200.config.default_conditions(4000);
  row.pressure_kPa = 250;
  const Prediction by_row = predict(at200, row);
  const Prediction by_config = predict(at250, at250.config.default_conditions(4000));
  ASSERT_TRUE(by_row.ok()) << by_row.message;
  ASSERT_TRUE(by_config.ok()) << by_config.message;
  EXPECT_NEAR(by_row.sinking_mm, by_config.sinking_mm, 1e-6 * by_config.sinking_mm);
  EXPECT_NEAR(by_row.length_mm, by_config.length_mm, 1e-6 * by_config.length_mm);
  // Higher pressure, less sinking; and the default row (the config's pressure) is unchanged.
  const Prediction base = predict(at200, at200.config.default_conditions(4000));
  EXPECT_LT(by_row.sinking_mm, base.sinking_mm);
}

TEST(CarcassSource, UninflatedRowIsRefused) {
  const TyreModel m = build_tyre_model(ring_config(Ring{}, 200, ""));
  auto row = m.config.default_conditions(4000);
  row.pressure_kPa = 0;
  const Prediction p = predict(m, row);
  EXPECT_FALSE(p.ok());
  EXPECT_NE(p.message.find("10 kPa"), std::string::npos) << p.message;
}

TEST(CarcassSource, UnstatedTestPressureIsSaidNotIgnored) {
  const Ring r;
  std::vector<double> f;
  for (int n = 1; n <= 6; ++n) f.push_back(r.hz(n));
  const std::string yaml =
      "tyre:\n  outer_radius_mm: 300\n  inflation_pressure_kPa: 200\nmodal:\n"
      "  frequencies_hz: " +
      list(f) +
      "\n  orders: [1, 2, 3, 4, 5, 6]\n  belt_width_mm: 150\n"
      "contact:\n  unit_length_mm: 2\n  window_mm: 300\n";
  const TyreModel m = build_tyre_model(read_tyre_config(ConfigTree::from_string(yaml, "x.yaml")));
  bool said = false;
  for (const auto& w : m.basis.warnings)
    said = said || w.find("test_pressure_kPa") != std::string::npos;
  EXPECT_TRUE(said);
}

// Each refusal names the key that fixes it.
// Unscaled hammer shapes (`ema --unscaled`, column scaling = unscaled) have no mass of their
// own: the config takes the ring's normalisation, so the planted ring's compliance comes back
// as from its frequency list, whatever the shapes' scale; 'shapes' and a missing mass scale
// are refused naming their keys.
TEST(CarcassSource, UnscaledShapesTakeTheRingsNormalisation) {
  const Ring r;
  const auto path = std::filesystem::temp_directory_path() /
                    ("modaltyre_unscaled_ring_" + std::to_string(::getpid()) + ".csv");
  {
    std::ofstream csv(path);
    csv.precision(17);
    csv << "mode,freq_hz,damping_ratio,point,angle_deg,radial,tangential,scaling\n";
    for (int n = 1; n <= 6; ++n) {
      const double scale = 0.37 * n;  // arbitrary, different per mode
      for (int i = 0; i < 12; ++i) {
        const double th = kTwoPi * i / 12;
        csv << n << "," << r.hz(n) << ",0.03," << i + 1 << "," << 30 * i << ","
            << scale * std::cos(n * th) << "," << scale * std::sin(n * th) / n << ",unscaled\n";
      }
    }
  }
  const std::string head =
      "tyre:\n  outer_radius_mm: 300\n  inflation_pressure_kPa: 200\n"
      "modal:\n  hammer_csv: " +
      path.string() + "\n  test_pressure_kPa: 200\n";
  const std::string tail =
      "tread:\n  modulus_MPa: 3\n  thickness_mm: 8\n  contact_width_mm: 150\n"
      "contact:\n  unit_length_mm: 2\n  window_mm: 300\n";
  const TyreModel m = build_tyre_model(
      read_tyre_config(ConfigTree::from_string(head + "  belt_width_mm: 150\n" + tail, "u.yaml")));
  EXPECT_TRUE(m.carcass.ring);
  EXPECT_EQ(m.carcass.mass_source, "tension");
  EXPECT_NEAR(m.carcass.mass_per_length_kg_m, r.mu, 1e-6 * r.mu);
  for (int n : {1, 2, 4, 6, 20}) {
    const double expected = 1.0 / (M_PI * r.R * r.K(n, r.p));
    EXPECT_NEAR(m.basis.static_rr(n), expected, 1e-6 * expected) << n;
  }
  auto refused_key = [&](const std::string& modal_extra) -> std::string {
    try {
      read_tyre_config(ConfigTree::from_string(head + modal_extra + tail, "u.yaml"));
    } catch (const InputError& e) {
      return e.where().key;
    }
    return "accepted";
  };
  EXPECT_EQ(refused_key("  belt_width_mm: 150\n  normalisation: shapes\n"), "modal.normalisation");
  EXPECT_EQ(refused_key(""), "modal.hammer_csv");
  std::filesystem::remove(path);
}

TEST(CarcassSource, RefusalsNameTheirKeys) {
  auto refused = [](const std::string& modal, const std::string& key) {
    const std::string yaml = "tyre:\n  outer_radius_mm: 300\nmodal:\n" + modal;
    try {
      read_tyre_config(ConfigTree::from_string(yaml, "bad.yaml"));
      ADD_FAILURE() << "accepted: " << modal;
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().key, "modal." + key) << e.what();
    }
  };
  refused("  frequencies_hz: [100, 120, 140]\n  belt_width_mm: 150\n", "orders");
  refused("  frequencies_hz: [100, 120, 140]\n  orders: [1, 2, 3]\n", "frequencies_hz");
  refused(
      "  frequencies_hz: [100, 120, 140]\n  orders: [1, 2, 3]\n  belt_width_mm: 150\n"
      "  boundary: free\n",
      "boundary");
  refused(
      "  frequencies_hz: [100, 120, 140]\n  orders: [1, 2, 3]\n  belt_width_mm: 150\n"
      "  normalisation: shapes\n",
      "normalisation");
  refused("  hammer_csv: h.csv\n  frequencies_hz: [100, 120, 140]\n  orders: [1, 2, 3]\n",
          "frequencies_hz");
}

}  // namespace
}  // namespace modaltyre::contact
