// A .tir's longitudinal laws against the model's runs (slip_compare.h).
#include "modaltyre/tir/slip_compare.h"

#include <algorithm>
#include <cmath>

namespace modaltyre::tir {
namespace {

struct Stats {
  double sum = 0, max = 0;
  int n = 0;
  void add(double r) {
    sum += r * r;
    max = std::max(max, std::abs(r));
    ++n;
  }
  std::optional<double> rms() const {
    return n ? std::optional<double>(std::sqrt(sum / n)) : std::nullopt;
  }
  std::optional<double> largest() const { return n ? std::optional<double>(max) : std::nullopt; }
};

}  // namespace

SlipComparison compare_slip_runs(const MfTyre& tir, const SlipRuns& runs, bool dimensionless,
                                 double model_fnomin_N, double model_radius_m) {
  SlipComparison out;
  out.speed_m_s = runs.speed_m_s;
  out.mu = runs.mu;
  const MfBasis b = tir.mf_basis();
  // The file's load for the model's, and its radius against the model's (1 for the same size).
  const double f_scale = dimensionless ? b.fnomin_N / model_fnomin_N : 1.0;
  const double r_scale = dimensionless ? b.unloaded_radius_m / model_radius_m : 1.0;
  Stats force, rolling, radius;
  const auto moment_row = [&](const SlipCurve& c) {
    RollingRow row{c.speed_m_s, c.free.fz_N, c.free.rolling_moment_Nm, std::nullopt};
    if (tir.rolling) {
      // M_y / (F_z R0) is the dimensionless measure: F_z and R0 scale together.
      const double my = mf_rolling_moment_Nm(*tir.rolling, tir.scaling, b, c.free.fx_N * f_scale,
                                             c.free.fz_N * f_scale, c.speed_m_s);
      row.tir_moment_Nm = my / (f_scale * r_scale);
      rolling.add((*row.tir_moment_Nm - row.model_moment_Nm) / std::abs(row.model_moment_Nm));
    }
    out.rolling.push_back(row);
  };
  for (const SlipCurve& c : runs.curves) {
    const auto force_row = [&](const SlipPoint& p) {
      SlipForceRow row{c.target_load_N, p.fz_N, p.kappa, p.fx_N, std::nullopt};
      if (tir.longitudinal) {
        row.tir_fx_N =
            mf_fx0_N(*tir.longitudinal, tir.scaling, b, p.kappa, p.fz_N * f_scale, c.speed_m_s) /
            f_scale;
        force.add((*row.tir_fx_N - p.fx_N) / p.fz_N);
      }
      out.force.push_back(row);
    };
    force_row(c.free);
    for (const SlipPoint& p : c.points) force_row(p);
    moment_row(c);
    RadiusRow rr{c.free.fz_N, c.effective_radius_m, std::nullopt};
    if (tir.effective_radius) {
      // The same speed: the file's tyre spins at Omega R0 / R0_file.
      rr.tir_radius_m = mf_effective_radius_m(*tir.effective_radius, b, c.free.fz_N * f_scale,
                                              c.free_spin_rad_s / r_scale) /
                        r_scale;
      radius.add((*rr.tir_radius_m - rr.model_radius_m) / model_radius_m);
    }
    out.radius.push_back(rr);
  }
  for (const SlipCurve& c : runs.free_runs) moment_row(c);
  out.rms_fx_over_fz = force.rms();
  out.max_fx_over_fz = force.largest();
  out.rms_rolling = rolling.rms();
  out.max_rolling = rolling.largest();
  out.rms_radius_over_r0 = radius.rms();
  out.force_reason = tir.longitudinal_reason;
  out.rolling_reason = tir.rolling_reason;
  out.radius_reason = tir.radius_reason;
  return out;
}

}  // namespace modaltyre::tir
