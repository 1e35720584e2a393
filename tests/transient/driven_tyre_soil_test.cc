// The tyre driven by its hub on a soil (driven_tyre.h; docs/soil.md section 8): a hub pressed
// slowly onto LETE sand and held carries the static footprint's load on the same soil at that
// sinking, and a hub rolling at traction's steady sinking carries traction's load once the
// soil's memory has moved under it (the rut behind, virgin soil ahead). 2D units at 5 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "../support/data_paths.h"
#include "../support/lete_sand.h"
#include "modaltyre/contact/traction.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/transient/soil_contact.h"
#include "modaltyre/transient/transient.h"

namespace modaltyre::transient {
namespace {

using namespace modaltyre::contact;

using modaltyre_test::kConfig2d;
using modaltyre_test::kLeteBekker;

// The press against the static footprint (issue 46's 1 %): the hub moves at 20 mm/s, slow
// against the tread's relaxation and with no bounce (the hub is prescribed), so the pressed soil
// is the static footprint's. Measured: see the test's output.
constexpr double kDrivenSoilPressTol = 0.01;
// Rolling at traction's sinking against its load: traction.h settles to 1e-4 of the sinkage
// profile; the transient's memory moves once per accepted step (the load control's rolling test
// of soil_transient_test.cc holds 1 %).
constexpr double kDrivenSoilRollingTol = 0.01;

TransientModel soil_model(std::vector<std::string> extra) {
  std::vector<std::string> o = {"contact.unit_length_mm=5", "contact.window_mm=400",
                                "transient.dynamic_max_order=16", "transient.relaxation=false",
                                "transient.rolling.load_N=3000"};
  o.insert(o.end(), kLeteBekker.begin(), kLeteBekker.end());
  o.insert(o.end(), extra.begin(), extra.end());
  return build_transient_model(build_tyre_model(load_tyre_config(kConfig2d, o)));
}

TEST(DrivenTyreSoil, APressHeldCarriesTheStaticFootprintsLoadOnTheSoil) {
  const TransientModel M = soil_model({});
  // The driven tyre's Bekker width: the footprint's at the config's rolling load.
  double b = 0;
  static_soil_contact(M, 3000, 0.0, &b);
  const StaticContact s = static_soil_contact(M, 4000, b);
  ASSERT_GT(s.sinking_m, 0.02);  // LETE sand: the hub sinks more than on the road (14 mm)
  DrivenTyreOptions opt;
  opt.max_deflection_m = 2 * s.sinking_m;
  DrivenTyre tyre(M, opt);
  tyre.reset(HubState{0, 0, 0});
  const double ramp = s.sinking_m / 0.02;  // 20 mm/s
  ASSERT_TRUE(tyre.advance(ramp, HubState{s.sinking_m, 0, 0}).ok);
  ASSERT_TRUE(tyre.advance(ramp + 0.3, HubState{s.sinking_m, 0, 0}, HubInterpolation::hold).ok);
  const WheelLoad w = tyre.load();
  std::cout << "press onto LETE sand to " << s.sinking_m * 1e3 << " mm: F_z " << w.fz_N
            << " N (static footprint 4000 N), soil sinkage " << w.soil_sinkage_m * 1e3
            << " mm (static " << s.soil_depth_m.maxCoeff() * 1e3 << " mm)\n";
  EXPECT_NEAR(w.fz_N / 4000, 1.0, kDrivenSoilPressTol);
  EXPECT_NEAR(w.soil_sinkage_m / s.soil_depth_m.maxCoeff(), 1.0, kDrivenSoilPressTol);
  // Started at the static state itself: its load at once.
  DrivenTyre at(M, opt);
  at.reset(HubState{s.sinking_m, 0, 0});
  EXPECT_NEAR(at.load().fz_N / 4000, 1.0, 1e-3);
}

TEST(DrivenTyreSoil, RollingAtTractionsSinkingCarriesItsLoadOnceTheRutIsBehind) {
  // Frictionless sand (no shear: the driven tyre has no tangential contact) at 2 km/h.
  const TransientModel M =
      soil_model({"ground.bekker.cohesion_kPa=0", "ground.bekker.friction_angle_deg=0"});
  const TractionResult tr = traction_pass(M.tyre, M.tyre.config.ground, {3000, 0.0}, 0);
  ASSERT_TRUE(tr.ok()) << tr.message;
  const double V = 2 / 3.6;
  DrivenTyreOptions opt;
  opt.max_deflection_m = 2 * tr.sinking_m;
  opt.distance_m = [V](double t) { return V * t; };
  DrivenTyre tyre(M, opt);
  const HubState hub{tr.sinking_m, V, std::nan("")};  // free rolling
  tyre.reset(hub);
  const double standing = tyre.load().fz_N;
  for (double t = 0.01; t < 1.5 + 1e-9; t += 0.01)
    ASSERT_TRUE(tyre.advance(t, hub, HubInterpolation::hold).ok);
  const WheelLoad w = tyre.load();
  std::cout << "rolling at traction's sinking " << tr.sinking_m * 1e3 << " mm: F_z " << w.fz_N
            << " N (traction 3000 N; standing there " << standing << " N), compaction resistance "
            << w.compaction_resistance_N << " N (traction " << tr.motion_resistance_N << " N)\n";
  // Standing at that sinking the rear carries too; rolling it rests on the rut.
  EXPECT_GT(standing, 1.2 * 3000);
  EXPECT_NEAR(w.fz_N / 3000, 1.0, kDrivenSoilRollingTol);
  EXPECT_NEAR(w.compaction_resistance_N / tr.motion_resistance_N, 1.0, kDrivenSoilRollingTol);

  // A tread window too small for the rolling contact: the step that reaches beyond it is redone
  // with every unit from the soil's memory at its start, and the run is the one with every unit
  // from the start (to the integrators' tolerance: their state sizes differ).
  DrivenTyreOptions narrow = opt, every = opt;
  narrow.max_deflection_m = 0.3 * tr.sinking_m;
  every.max_deflection_m = 0;
  DrivenTyre a(M, narrow), e(M, every);
  a.reset(hub);
  e.reset(hub);
  for (double t = 0.01; t < 0.6 + 1e-9; t += 0.01) {
    ASSERT_TRUE(a.advance(t, hub, HubInterpolation::hold).ok);
    ASSERT_TRUE(e.advance(t, hub, HubInterpolation::hold).ok);
  }
  EXPECT_TRUE(a.widened());
  EXPECT_NEAR(a.load().fz_N, e.load().fz_N, 1e-3 * 3000);
  EXPECT_NEAR(a.load().soil_sinkage_m, e.load().soil_sinkage_m, 1e-3 * tr.soil_sinkage_m);
}

TEST(DrivenTyreSoil, WhatTheSoilTransientRefusesIsRefused) {
  const TransientModel rigid = soil_model({"tyre.rigid=true"});
  EXPECT_THROW(DrivenTyre{rigid}, InputError);
  const TransientModel plain = soil_model({});
  DrivenTyreOptions opt;
  opt.road_profile = [](double, double, double* slope) {
    if (slope) *slope = 0;
    return 0.0;
  };
  EXPECT_THROW(DrivenTyre(plain, opt), InputError);
}

}  // namespace
}  // namespace modaltyre::transient
