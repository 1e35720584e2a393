#pragma once
// Slip runs made from known MF 6.2 laws (a passenger tyre's order of values), for the fits' and
// the comparison's round trips (slip_fit_test.cc, slip_compare_test.cc).
#include <vector>

#include "modaltyre/tir/slip_fit.h"

namespace modaltyre_test {

using namespace modaltyre::tir;

inline MfBasis basis() {
  MfBasis b;
  b.unloaded_radius_m = 0.3;
  b.fnomin_N = 4000;
  b.longvl_m_s = 60 / 3.6;
  b.nominal_pressure_Pa = b.pressure_Pa = 2.2e5;
  b.vertical_stiffness_N_m = 2.1e5;
  return b;
}

struct Planted {
  MfLongitudinal fx;
  MfRolling my;
  MfEffectiveRadius re;
};

inline Planted planted() {
  Planted p;
  p.fx.pcx1 = 1.58, p.fx.pdx1 = 1.04, p.fx.pdx2 = -0.083;
  p.fx.pex1 = 0.11, p.fx.pex2 = 0.31, p.fx.pex3 = 0.05, p.fx.pex4 = 0.05;
  p.fx.pkx1 = 21.7, p.fx.pkx2 = 13.8, p.fx.pkx3 = -0.41;
  p.fx.phx1 = 2e-4, p.fx.phx2 = 1e-3, p.fx.pvx1 = -0.01, p.fx.pvx2 = 0.002;
  p.my.qsy1 = 0.0085, p.my.qsy2 = 0.002, p.my.qsy3 = 0.0015, p.my.qsy4 = 8.5e-5, p.my.qsy7 = 0.9;
  p.re.breff = 8.4, p.re.dreff = 0.26, p.re.freff = 0.07;
  return p;
}

/// A run made from the planted laws: F_z drifting with the slip as the model's does.
inline SlipCurve planted_run(const Planted& p, double load_N, double speed_m_s,
                             const std::vector<double>& slips) {
  const MfBasis b = basis();
  const auto point = [&](double kappa) {
    SlipPoint s;
    s.kappa = kappa;
    s.fz_N = load_N * (1 - 0.05 * kappa);
    s.fx_N = mf_fx0_N(p.fx, {}, b, kappa, s.fz_N);
    s.rolling_moment_Nm = mf_rolling_moment_Nm(p.my, {}, b, s.fx_N, s.fz_N, speed_m_s);
    s.loaded_radius_m = 0.28;
    return s;
  };
  SlipCurve c;
  c.target_load_N = load_N;
  c.speed_m_s = speed_m_s;
  c.free = point(0);
  c.effective_radius_m = mf_effective_radius_m(p.re, b, c.free.fz_N, 0);
  c.free_spin_rad_s = speed_m_s / c.effective_radius_m;
  for (double k : slips) c.points.push_back(point(k));
  return c;
}

}  // namespace modaltyre_test
