// Seed 000 eq. (22) on a decay from the transient simulator (issue 5 item 8: free-vibration
// data "from the transient simulator when it exists"). transient::run_transient bounces the hub
// on a nearly rigid carcass and Kelvin-Voigt tread units whose dashpots are known; the decay
// goes through the rheology's own fit (fit_free_decay, as `identify free-vibration` reads a
// measured t_s,deflection_mm file) and eq. (22) eta1 = 2 m delta / (T L_C) must give back
// eta1 L_C = the dashpots of the units in contact. Omega_ref = 60 Hz keeps the bounce lightly
// damped (log decrement ~0.5) so that the fit sees the several cycles a hammer-free drop test
// would record (at 20 Hz it is ~1.4: 1.5 cycles above 10 % of the release swing, which the fit
// refuses as not an oscillation).
#include <gtest/gtest.h>

#include <cmath>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/transient/transient.h"
#include "modaltyre/rheology/free_vibration.h"
#include "modaltyre/rheology/three_element.h"

namespace modaltyre::rheology {
namespace {

// As TransientTest.FreeVibrationDecayGivesTheViscosityGiven: the contact set breathes with the
// bounce (a few units at 5 mm), so the effective damping differs from the static-contact sum by
// some percent.
constexpr double kViscosityTol = 0.10;
// The decay's equilibrium is the static footprint's sinking at the final load (the hub settles
// there); the fit's h_Z0 carries the residual bounce of a finite record.
constexpr double kEquilibriumTol = 0.01;

TEST(rheology_FreeVibrationFromTransient, Eq22OnTheSimulatedDecayGivesTheTreadDashpots) {
  using namespace modaltyre::contact;
  using namespace modaltyre::transient;
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
  const TransientModel M = build_transient_model(build_tyre_model(load_tyre_config(
      config,
      {"contact.unit_length_mm=5", "contact.window_mm=220", "transient.dynamic_max_order=16",
       "modal.compliance_scale=0.001", "transient.instantaneous_stiffness_ratio=10000",
       "transient.tread_reference_frequency_hz=60", "transient.free_vibration.load_N=4000",
       "transient.free_vibration.initial_load_N=4200", "transient.free_vibration.duration_s=0.4",
       "transient.output_step_ms=0.25"})));
  const TransientResult r = run_transient(M, Scenario::free_vibration);
  ASSERT_TRUE(r.ok()) << r.message;

  DecaySignal signal;
  signal.path = "transient free-vibration";
  for (const auto& s : r.samples) {
    signal.t_s.push_back(s.t_s);
    signal.deflection_m.push_back(s.sinking_m);
    signal.line.push_back(static_cast<int>(signal.t_s.size()) + 1);
  }
  const DecayFit fit = fit_free_decay(signal);

  const FootprintResult st = solve_footprint(M.tyre, LoadCase{4000, 0});
  ASSERT_TRUE(st.ok());
  EXPECT_NEAR(fit.equilibrium_m / st.sinking_m, 1.0, kEquilibriumTol);
  const double eta1 =
      eta1_eq22(M.settings.hub_mass_kg, fit.log_decrement, fit.period_s, st.contact_length_m);
  // Dashpot of each series element seen from the unit's relaxed spring: c' (k / k')^2.
  double c_given = 0;
  for (int i = 0; i < M.m; ++i)
    if (st.active[i]) c_given += M.c_kv(i) * std::pow(M.k_relaxed(i) / M.k_kv(i), 2);
  EXPECT_NEAR(eta1 * st.contact_length_m / c_given, 1.0, kViscosityTol)
      << "T = " << fit.period_s << " s, delta = " << fit.log_decrement << ", eta1 = " << eta1
      << " Pa s";
}

}  // namespace
}  // namespace modaltyre::rheology
