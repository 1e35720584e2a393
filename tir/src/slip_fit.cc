// The MF 6.2 longitudinal, rolling-resistance and effective-radius fits (slip_fit.h).
#include "modaltyre/tir/slip_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <set>

#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/levenberg_marquardt.h"
#include "modaltyre/tir/model_curve.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::tir {
namespace {

constexpr double kDefaultSlips[] = {0.0025, 0.005, 0.01, 0.02, 0.035, 0.05,
                                    0.075,  0.1,   0.15, 0.2,  0.25,  0.3};
/// 40-120 km/h: below, the model's rolling resistance falls with the speed (the tread's
/// viscoelastic loss falls with its deformation's frequency: 0.012 F_z at 20 km/h, 0.018 at
/// 60 on the default), which MF's constant + linear + quartic law in speed cannot follow.
constexpr double kDefaultSpeeds_kmh[] = {40, 80, 100, 120};
constexpr double kDefaultLoadShares[] = {0.5, 0.75, 1.0, 1.25, 1.5};
/// Weight of E_x - 1 > 0 against the F_x residuals (fractions of F_z, ~1e-2): a violation of
/// 1e-3 costs as much as a 1 % force residual.
constexpr double kCurvaturePenalty = 10;
/// Loads over the fitted range at which E_x <= 1 is kept.
constexpr int kCurvatureLoads = 9;
/// BREFF's grid for the effective radius (log-spaced): the model's R_e hardly changes with the
/// load (the tread base rolls at Omega R_b whatever the load), which A3.6 follows with a large
/// BREFF; the grid bounds it.
constexpr double kBreffMin = 0.5, kBreffMax = 200;
constexpr int kBreffGrid = 120;
constexpr int kMaxLmIterations = 400;
constexpr std::size_t kMaxSlipLoads = 20, kMaxRollingSpeeds = 20;
/// Alternations of the M_y fit over load and speed with QSY2's (each shifts the other through
/// the free points' small F_x): the fourth round moves QSY1 by 5e-11 on the default.
constexpr int kRollingRounds = 4;

struct FxPoint {
  double kappa, fz_N, fx_N;
};

std::vector<FxPoint> fx_points(const std::vector<SlipCurve>& curves) {
  std::vector<FxPoint> pts;
  for (const auto& c : curves) {
    pts.push_back({0.0, c.free.fz_N, c.free.fx_N});
    for (const auto& p : c.points) pts.push_back({p.kappa, p.fz_N, p.fx_N});
  }
  return pts;
}

/// The F_x fit's unknowns, each over its typical size (the solver's steps are relative to
/// max(|x|, 1)): PCX1, PDX1, PDX2, PEX1-4, PKX1-3, PHX1-2, PVX1-2.
constexpr double kFxScale[14] = {1, 1, 0.1, 1, 1, 1, 1, 10, 10, 1, 1e-3, 1e-3, 1e-2, 1e-2};

MfLongitudinal unpack_fx(const Eigen::VectorXd& x) {
  double v[14];
  for (int i = 0; i < 14; ++i) v[i] = x(i) * kFxScale[i];
  MfLongitudinal c;
  c.pcx1 = v[0], c.pdx1 = v[1], c.pdx2 = v[2];
  c.pex1 = v[3], c.pex2 = v[4], c.pex3 = v[5], c.pex4 = v[6];
  c.pkx1 = v[7], c.pkx2 = v[8], c.pkx3 = v[9];
  c.phx1 = v[10], c.phx2 = v[11], c.pvx1 = v[12], c.pvx2 = v[13];
  return c;
}

double max_curvature(const MfLongitudinal& c, const MfBasis& b, double lo_N, double hi_N) {
  double m = -1e300;
  for (int i = 0; i < kCurvatureLoads; ++i) {
    const double fz = lo_N + (hi_N - lo_N) * i / (kCurvatureLoads - 1);
    // kappa = +-1 puts kappa_x on the side of its sign whatever S_Hx (|S_Hx| << 1).
    for (double kappa : {-1.0, 1.0}) m = std::max(m, mf_curvature_x(c, {}, b, kappa, fz));
  }
  return m;
}

Residual residual_of(const std::vector<double>& r) {
  Residual q;
  for (double v : r) {
    q.rms += v * v;
    q.max = std::max(q.max, std::abs(v));
  }
  q.rms = r.empty() ? 0 : std::sqrt(q.rms / static_cast<double>(r.size()));
  return q;
}

void fit_fx(TirSlipFit& f) {
  const auto pts = fx_points(f.curves);
  const MfBasis& b = f.basis;
  // Starting values from the data: the peak, the free-rolling offset, the slope at small slip.
  double peak = 0, offset = 0, sxy = 0, sxx = 0;
  int free_points = 0;
  for (const auto& p : pts) {
    peak = std::max(peak, std::abs(p.fx_N / p.fz_N));
    if (p.kappa == 0) offset += p.fx_N / p.fz_N, ++free_points;
  }
  offset /= std::max(free_points, 1);
  for (const auto& p : pts) {
    if (p.kappa == 0 || std::abs(p.kappa) > 0.0051) continue;
    sxy += p.kappa * (p.fx_N / p.fz_N - offset);
    sxx += p.kappa * p.kappa;
  }
  const double slope = sxx > 0 ? sxy / sxx : 10.0;
  const auto residual = [&](const Eigen::VectorXd& x) {
    const MfLongitudinal c = unpack_fx(x);
    Eigen::VectorXd r(static_cast<Eigen::Index>(pts.size()) + 2 * kCurvatureLoads);
    Eigen::Index k = 0;
    for (const auto& p : pts) r(k++) = (mf_fx0_N(c, {}, b, p.kappa, p.fz_N) - p.fx_N) / p.fz_N;
    for (int i = 0; i < kCurvatureLoads; ++i) {
      const double fz = f.fz_min_N + (f.fz_max_N - f.fz_min_N) * i / (kCurvatureLoads - 1);
      for (double kappa : {-1.0, 1.0})
        r(k++) = kCurvaturePenalty * std::max(0.0, mf_curvature_x(c, {}, b, kappa, fz) - 1);
    }
    return r;
  };
  solvers::LeastSquaresOptions lo;
  lo.max_iterations = kMaxLmIterations;
  std::optional<solvers::LeastSquaresResult> best;
  // The Magic Formula's fit has local minima: a few shapes C_x and curvatures E_x to start from.
  for (double cx : {1.0, 1.3, 1.65}) {
    for (double ex : {-0.5, 0.0, 0.5}) {
      Eigen::VectorXd x0 = Eigen::VectorXd::Zero(14);
      x0(0) = cx, x0(1) = peak, x0(3) = ex, x0(7) = slope / kFxScale[7];
      x0(12) = offset / kFxScale[12];
      const auto r = solvers::levenberg_marquardt(residual, x0, lo);
      if (std::isfinite(r.cost) && (!best || r.cost < best->cost)) best = r;
    }
  }
  if (!best) throw ComputationError("the longitudinal force fit failed (no finite cost)");
  f.longitudinal = unpack_fx(best->x);
  std::vector<double> r;
  for (const auto& p : pts)
    r.push_back((mf_fx0_N(f.longitudinal, {}, b, p.kappa, p.fz_N) - p.fx_N) / p.fz_N);
  f.fx_over_fz = residual_of(r);
  f.max_curvature = max_curvature(f.longitudinal, b, f.fz_min_N, f.fz_max_N);
}

struct MomentPoint {
  double fx_N, fz_N, v_m_s, moment_Nm;
};

double relative_moment_error(const MfRolling& c, const MfBasis& b, const MomentPoint& p) {
  return (mf_rolling_moment_Nm(c, {}, b, p.fx_N, p.fz_N, p.v_m_s) - p.moment_Nm) /
         std::abs(p.moment_Nm);
}

// QSY1, QSY3, QSY4, QSY7 on the free-rolling points (over load and speed), then QSY2 alone on
// the slip points. In one fit the slip points would pull the speed terms: the model's M_r
// changes along the slip curve through the spin (the rolling carcass), not through F_x (the
// tangential forces do not act on the carcass, docs/fmu.md section 4), by -7.5 % braking and
// +1.5 % driving at kappa 0.3 on the default, which a term linear in F_x only halves.
void fit_rolling(TirSlipFit& f) {
  const MfBasis& b = f.basis;
  std::vector<MomentPoint> free, slip;
  std::set<double> speeds;
  const auto add_run = [&](const SlipCurve& c) {
    free.push_back({c.free.fx_N, c.free.fz_N, c.speed_m_s, c.free.rolling_moment_Nm});
    speeds.insert(c.speed_m_s);
    for (const auto& p : c.points)
      slip.push_back({p.fx_N, p.fz_N, c.speed_m_s, p.rolling_moment_Nm});
  };
  for (const auto& c : f.curves) add_run(c);
  for (const auto& c : f.free_runs) add_run(c);
  // Which speed terms the runs determine: QSY3 needs two speeds, QSY4 three.
  const int most = 2 + static_cast<int>(std::min<std::size_t>(speeds.size() - 1, 2));
  // x = (QSY1, QSY7, QSY3, QSY4), scaled to order 1 (the solver's steps are relative to
  // max(|x|, 1)).
  constexpr double kScale[4] = {1e-2, 1, 1e-3, 1e-4};
  double mean = 0;
  for (const auto& c : f.curves) mean += c.free.rolling_moment_Nm / f.curves.size();
  const auto fit = [&](int terms, double qsy2) {
    const auto unpack = [terms, qsy2, &kScale](const Eigen::VectorXd& x) {
      MfRolling c;
      c.qsy2 = qsy2;
      c.qsy1 = x(0) * kScale[0];
      c.qsy7 = x(1) * kScale[1];
      if (terms > 2) c.qsy3 = x(2) * kScale[2];
      if (terms > 3) c.qsy4 = x(3) * kScale[3];
      return c;
    };
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(terms);
    x0(0) = -mean / (b.unloaded_radius_m * b.fnomin_N) / kScale[0];
    x0(1) = 1;
    const auto residual = [&](const Eigen::VectorXd& x) {
      const MfRolling c = unpack(x);
      Eigen::VectorXd r(static_cast<Eigen::Index>(free.size()));
      for (std::size_t i = 0; i < free.size(); ++i)
        r(static_cast<Eigen::Index>(i)) = relative_moment_error(c, b, free[i]);
      return r;
    };
    solvers::LeastSquaresOptions lo;
    lo.max_iterations = kMaxLmIterations;
    const auto r = solvers::levenberg_marquardt(residual, x0, lo);
    if (!std::isfinite(r.cost)) throw ComputationError("the rolling-resistance fit failed");
    return unpack(r.x);
  };
  // QSY2: M_y is linear in it, so the relative errors are e0 + a QSY2 (least squares); the
  // free points carry a small F_x too, so the two fits alternate (a few rounds settle them).
  const auto fit_qsy2 = [&](const MfRolling& c) {
    double saa = 0, sae = 0;
    MfRolling unit{};
    unit.qsy2 = 1, unit.qsy7 = c.qsy7;
    for (const auto& p : slip) {
      MfRolling without = c;
      without.qsy2 = 0;
      const double e0 = relative_moment_error(without, b, p);
      const double a =
          mf_rolling_moment_Nm(unit, {}, b, p.fx_N, p.fz_N, p.v_m_s) / std::abs(p.moment_Nm);
      saa += a * a;
      sae += a * e0;
    }
    return saa > 0 ? -sae / saa : 0.0;
  };
  double qsy2 = 0;
  for (int round = 0; round < kRollingRounds; ++round) {
    f.rolling = fit(most, qsy2);
    // QSY4 >= 0: a negative quartic term turns the moment propulsive at high speed (at about
    // 2.7 LONGVL on the default's free fit), beyond any run. The bound active: QSY4 = 0.
    if (f.rolling.qsy4 < 0) f.rolling = fit(3, qsy2);
    qsy2 = fit_qsy2(f.rolling);
    f.rolling.qsy2 = qsy2;
  }
  std::vector<double> rel, rel_slip;
  for (const auto& p : free) rel.push_back(relative_moment_error(f.rolling, b, p));
  for (const auto& p : slip) rel_slip.push_back(relative_moment_error(f.rolling, b, p));
  f.rolling_rel = residual_of(rel);
  f.rolling_slip_rel = residual_of(rel_slip);
}

void fit_radius(TirSlipFit& f) {
  const MfBasis& b = f.basis;
  const double scale = b.fnomin_N / b.vertical_stiffness_N_m;
  const auto n = static_cast<Eigen::Index>(f.curves.size());
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i)
    y(i) = b.unloaded_radius_m - f.curves[i].effective_radius_m;  // Q_RE0 = 1, Q_V1 = 0
  double best_sse = 1e300;
  for (int g = 0; g < kBreffGrid; ++g) {
    const double breff = kBreffMin * std::pow(kBreffMax / kBreffMin, double(g) / (kBreffGrid - 1));
    Eigen::MatrixXd A(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double x = f.curves[i].free.fz_N / b.fnomin_N;
      A(i, 0) = scale * std::atan(breff * x);  // DREFF
      A(i, 1) = scale * x;                     // FREFF
    }
    const Eigen::Vector2d c = A.colPivHouseholderQr().solve(y);
    const double sse = (A * c - y).squaredNorm();
    if (c.allFinite() && sse < best_sse) {
      best_sse = sse;
      f.radius = MfEffectiveRadius{1.0, 0.0, breff, c(0), c(1)};
    }
  }
  std::vector<double> r;
  for (const auto& c : f.curves) {
    r.push_back(mf_effective_radius_m(f.radius, b, c.free.fz_N, c.free_spin_rad_s) -
                c.effective_radius_m);
  }
  f.radius_m = residual_of(r);
}

}  // namespace

std::vector<double> default_slips() {
  std::vector<double> s;
  for (double k : kDefaultSlips) s.push_back(-k);
  for (double k : kDefaultSlips) s.push_back(k);
  return s;
}

std::vector<double> default_rolling_speeds_m_s() {
  std::vector<double> v;
  for (double kmh : kDefaultSpeeds_kmh) v.push_back(kmh / 3.6);
  return v;
}

TirSlipFit fit_slip_laws(MfBasis basis, double mu, std::vector<SlipCurve> curves,
                         std::vector<SlipCurve> free_runs) {
  std::set<double> loads;
  for (const auto& c : curves) loads.insert(c.target_load_N);
  if (loads.size() < 3) {
    throw InputError({"--slip-loads", 0, ""},
                     "give at least 3 different slip-curve loads: the laws' load terms need them");
  }
  TirSlipFit f;
  f.basis = basis;
  f.mu = mu;
  f.curves = std::move(curves);
  f.free_runs = std::move(free_runs);
  f.fz_min_N = 1e300, f.fz_max_N = 0;
  for (const auto& c : f.curves) {
    f.fz_min_N = std::min(f.fz_min_N, c.free.fz_N);
    f.fz_max_N = std::max(f.fz_max_N, c.free.fz_N);
    for (const auto& p : c.points) {
      f.fz_min_N = std::min(f.fz_min_N, p.fz_N);
      f.fz_max_N = std::max(f.fz_max_N, p.fz_N);
      f.kappa_min = std::min(f.kappa_min, p.kappa);
      f.kappa_max = std::max(f.kappa_max, p.kappa);
    }
  }
  fit_fx(f);
  fit_rolling(f);
  fit_radius(f);
  return f;
}

void check_slip_options(const SlipExportOptions& options) {
  SlipSettings run = options.run;
  if (run.slips.empty()) run.slips = default_slips();
  slip_run_steps(run);
  if (options.loads_N.size() > kMaxSlipLoads) {
    throw InputError({"--slip-loads", 0, ""},
                     "give at most " + std::to_string(kMaxSlipLoads) + " slip-curve loads");
  }
  for (double load : options.loads_N) {
    if (!(load > 0) || !(load <= 1e7))
      throw InputError({"--slip-loads", 0, ""}, "every load must be a number in (0, 1e7] N");
  }
  const std::set<double> distinct(options.loads_N.begin(), options.loads_N.end());
  if (!options.loads_N.empty() && distinct.size() < 3) {
    throw InputError({"--slip-loads", 0, ""},
                     "give at least 3 different slip-curve loads: the laws' load terms need them");
  }
  if (options.speeds_m_s.size() > kMaxRollingSpeeds) {
    throw InputError({"--rr-speeds-kmh", 0, ""},
                     "give at most " + std::to_string(kMaxRollingSpeeds) + " speeds");
  }
  for (double v : options.speeds_m_s) {
    if (!(v >= 1) || !(v <= 100))
      throw InputError({"--rr-speeds-kmh", 0, ""}, "every speed must be in [3.6, 360] km/h");
  }
}

SlipRuns run_slip(const contact::TyreModel& model, double fnomin_N,
                  const SlipExportOptions& options) {
  check_slip_options(options);
  SlipRuns out;
  SlipSettings run = options.run;
  if (run.slips.empty()) run.slips = default_slips();
  out.mu = run.mu;
  out.speed_m_s = run.speed_m_s;
  std::vector<double> loads = options.loads_N;
  if (loads.empty())
    for (double s : kDefaultLoadShares) loads.push_back(s * fnomin_N);
  const std::vector<double> speeds =
      options.speeds_m_s.empty() ? default_rolling_speeds_m_s() : options.speeds_m_s;
  SlipSettings free = run;
  free.slips.clear();
  for (double v : speeds) {
    free.speed_m_s = v;
    slip_run_steps(free);
  }
  const int total = static_cast<int>(loads.size()) * slip_run_holds(run) +
                    static_cast<int>(speeds.size()) * slip_run_holds(free);
  int done = 0;
  const auto tick = [&] {
    ++done;
    if (options.progress) options.progress(std::min(done, total), total);
  };
  // Every load's hub height: the static footprint's sinking (the FMU's press check: F_z within
  // 0.0003 % of the load there, docs/fmu.md section 6).
  std::vector<double> sorted = loads;
  sorted.push_back(fnomin_N);
  const ModelCurve statics = sample_model(model, sorted);
  const auto sinking = [&](double load) {
    for (const auto& p : statics.points)
      if (p.load_N == load) return p.sinking_m;
    throw ComputationError("no static sinking at " + std::to_string(load) + " N");
  };
  const auto transient =
      std::make_shared<const transient::TransientModel>(transient::build_transient_model(model));
  for (double load : loads)
    out.curves.push_back(model_slip_curve(transient, sinking(load), load, run, tick));
  for (double v : speeds) {
    free.speed_m_s = v;
    out.free_runs.push_back(model_slip_curve(transient, sinking(fnomin_N), fnomin_N, free, tick));
  }
  if (options.progress) options.progress(total, total);
  return out;
}

TirSlipFit fit_slip(const contact::TyreModel& model, MfBasis basis,
                    const SlipExportOptions& options) {
  SlipRuns runs = run_slip(model, basis.fnomin_N, options);
  basis.longvl_m_s = runs.speed_m_s;
  return fit_slip_laws(basis, runs.mu, std::move(runs.curves), std::move(runs.free_runs));
}

}  // namespace modaltyre::tir
