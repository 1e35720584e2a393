// The effects path on the 2D patch (predictor.h), one step per effect, and the Pasternak tread.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "modaltyre/contact/ground_patch.h"
#include "predictor_paths.h"

namespace modaltyre::contact {

// The Pasternak tread of tread_coupling (predictor.h).
std::vector<double> pasternak_tread_lags(double k_r, double ell, double ds, int max_lags) {
  if (!(ell > 0)) return {1.0 / k_r};
  const double a = (ell / ds) * (ell / ds);
  const double s = std::sqrt(1 + 4 * a);
  const double rho = (1 + 2 * a - s) / (2 * a);
  std::vector<double> g{1.0 / (k_r * s)};
  while (static_cast<int>(g.size()) < max_lags && g.back() * rho > 1e-12 * g.front()) {
    g.push_back(g.back() * rho);
  }
  return g;
}

namespace predictor_paths {

// ---- the effects path, one step per effect ---------------------------------------------------

namespace {

// Kernels of a modified basis on the model's grid, built the way build_tyre_model built the
// static ones (FFT when the orders fit the grid).
modal::LagKernels kernels_for(const TyreModel& m, const modal::ModalBasis& basis,
                              const modal::RollingState& rolling) {
  const int cand = m.candidates();
  return basis.max_order * 2 <= m.units_around
             ? modal::build_periodic_kernels(basis, m.units_around, cand, rolling)
             : modal::build_lag_kernels(basis, m.dtheta_rad, cand, rolling);
}

// Horizontal force: the static cross-compliance, carcass part scaled like the vertical one; its
// tread part (the model's springs) is swapped for this prediction's in assemble().
Eigen::MatrixXd horizontal_coupling(const TyreModel& m, const CarcassAssembly& a, double ratio,
                                    double scale) {
  Eigen::MatrixXd horizontal = vertical_from_horizontal(m);
  for (int j = 0; j < m.candidates(); ++j) {
    const double cj = a.cos_theta[j], sj = a.sin_theta[j];
    horizontal(j, j) -= cj * (-sj) / m.k_radial_N_m + sj * cj / m.k_tangential_N_m;
  }
  horizontal *= ratio * scale;
  return horizontal;
}

// The operator of one width: tread springs per unit from the modulus and the width (seed 001
// eq. 6-9), creeping while the load is held (tread_relaxation, `creep`), optionally
// shear-coupled (tread_coupling); Winkler soil under rows on soil (soil_compliance).
PatchOperator assemble(const TyreModel& m, const CarcassAssembly& a, const TyreParameters& P,
                       const modal::LagKernels* kernels, const Eigen::MatrixXd& carcass,
                       const Eigen::MatrixXd& horizontal, double scale, double creep, bool soil,
                       double ratio, bool rolling, double width) {
  const EffectsConfig& E = P.effects;
  const auto& T = P.tread;
  const int cand = m.candidates();
  const double ds = m.unit_length_m;
  const TreadSprings k = tread_springs(T, width, ds);
  const double k_r = k.radial_N_m, k_t = k.tangential_N_m;
  const std::vector<double>& cos_ = a.cos_theta;
  const std::vector<double>& sin_ = a.sin_theta;
  PatchOperator op;
  op.kernels = kernels;
  op.carcass_scale = scale;
  op.tread_radial_lag = pasternak_tread_lags(
      k_r / creep, E.tread_coupling.enabled ? E.tread_coupling.coupling_length_m() : 0, ds, cand);
  op.tread_tangential_compliance = creep / k_t;
  op.width_m = width;
  op.horizontal_ratio = ratio;
  op.symmetric = !rolling && ratio == 0.0;
  op.compliance = scale * carcass;
  const int lags = static_cast<int>(op.tread_radial_lag.size());
  for (int j = 0; j < cand; ++j) {
    const double cj = cos_[j], sj = sin_[j];
    for (int i = std::max(0, j - lags + 1); i < std::min(cand, j + lags); ++i) {
      op.compliance(i, j) += cos_[i] * cj * op.tread_radial_lag[std::abs(i - j)];
    }
    op.compliance(j, j) += sj * sj * op.tread_tangential_compliance;
    if (soil) {
      // Winkler soil under the unit (static part of seed 000 eq. 23): z = p H / E2.
      op.compliance(j, j) +=
          E.soil_compliance.layer_m() / (E.soil_compliance.modulus_Pa() * width * ds * cj);
    }
  }
  if (ratio != 0.0) {
    op.compliance += horizontal;
    for (int j = 0; j < cand; ++j) {  // tread under the unit's own horizontal force (eq. 6)
      const double cj = cos_[j], sj = sin_[j];
      op.compliance(j, j) +=
          ratio * (cj * (-sj) * op.tread_radial_lag[0] + sj * cj * op.tread_tangential_compliance);
    }
  }
  if (op.symmetric) op.compliance = 0.5 * (op.compliance + op.compliance.transpose()).eval();
  return op;
}

// contact_width: chord of the transverse crown arc pressed in by the sinking.
double crown_width(const EffectsConfig& E, double sinking_m) {
  // 2 r s = 2 (r_mm 1e-3) s exactly: a factor 2 does not round.
  return std::clamp(2 * std::sqrt(2 * E.contact_width.crown_radius_m() * sinking_m), 1e-3,
                    E.contact_width.max_width_m());
}

}  // namespace

// dry_friction (seed 000, Saint-Venant element in parallel): the element carries F_f against the
// motion, the elastic tyre the rest. False when the load does not exceed F_f on loading.
bool elastic_load(const EffectsConfig& E, const OperatingConditions& c, double& load_N,
                  std::string& why) {
  load_N = c.load_N;
  if (!E.dry_friction.enabled) return true;
  const double ff = E.dry_friction.friction_force_N;
  load_N += c.branch == Branch::unloading ? ff : -ff;
  if (load_N > 0) return true;
  std::ostringstream msg;
  msg << "load " << c.load_N << " N does not exceed the dry-friction force " << ff
      << " N: the tyre does not deflect on the loading branch";
  why = msg.str();
  return false;
}

// The carcass compliance factor: the parameters' level against the model's, inflation_pressure
// and load_stiffening.
double carcass_scale(const TyreModel& m, const TyreParameters& P, const OperatingConditions& c,
                     double elastic_load_N) {
  const EffectsConfig& E = P.effects;
  double scale = P.compliance_scale / m.config.compliance_scale;
  if (E.inflation_pressure.enabled) {
    // seed 000 eq. (3): h ~ (1 + p_W)^-1, p_W in bar (docs/rheology.md).
    const double p_bar = c.pressure_bar();
    const double p0_bar = E.inflation_pressure.modal_test_pressure_bar();
    scale *= std::pow((1 + p0_bar) / (1 + p_bar), E.inflation_pressure.exponent);
  }
  if (E.load_stiffening.enabled) {
    scale *=
        std::pow(elastic_load_N / E.load_stiffening.reference_load_N, -E.load_stiffening.exponent);
  }
  return scale;
}

// Whether the row's pressure differs from the model's and the ring fit can move the carcass
// to it (carcass_source.h): then the kernels are rebuilt for the row.
bool pressure_acts(const TyreModel& m, const OperatingConditions& c) {
  return m.carcass.fit.valid && c.pressure_Pa() != m.carcass.operating_pressure_Pa;
}

// The carcass kernels when rolling_speed (at a speed > 0), belt_flattening or the row's
// pressure change them; otherwise the model's static ones are used.
modal::LagKernels rebuilt_kernels(const TyreModel& m, const EffectsConfig& E, double scale,
                                  bool rolling, bool flattening, double speed_m_per_s,
                                  double pressure_Pa) {
  // The row's pressure moves every order's stiffness by the ring's pressure terms first.
  modal::ModalBasis basis = basis_at_pressure(m.basis, m.carcass, m.config.carcass, pressure_Pa);
  if (flattening) {
    // Foundation kappa on orders >= 2: c_k -> c_k / (1 + pi R kappa c_k), c_k the order's
    // (scaled) static radial compliance; every term of the order gets the same factor.
    const double kappa = E.belt_flattening.stiffness_Pa();
    const double R0 = m.config.outer_radius_m;
    std::vector<double> factor(basis.max_order + 1, 1.0);
    for (int k = 2; k <= basis.max_order; ++k) {
      const double ck = scale * basis.static_rr(k);
      factor[k] = ck > 0 ? 1.0 / (1.0 + M_PI * R0 * kappa * ck) : 1.0;
    }
    for (auto& t : basis.terms) {
      if (t.order < 2 || t.order > basis.max_order) continue;
      t.P_rr *= factor[t.order];
      t.P_rt *= factor[t.order];
      t.P_tt *= factor[t.order];
    }
  }
  modal::RollingState rs;
  if (rolling) {
    // rolling_speed: steady-rolling receptance at the row's speed (seed 001 eq. 2-5).
    for (auto& t : basis.terms) t.damping_ratio *= E.rolling_speed.damping_scale;
    rs.speed_m_s = speed_m_per_s;
    rs.radius_m = m.config.outer_radius_m;
  }
  return kernels_for(m, basis, rs);
}

// tread_relaxation: seed 001 eq. (10), Kelvin-Voigt creep of the tread while the load is held.
double tread_creep(const EffectsConfig& E, const OperatingConditions& c) {
  if (!E.tread_relaxation.enabled || !(c.hold_s > 0)) return 1;
  return 1 + E.tread_relaxation.creep_ratio *
                 (1 - std::exp(-c.hold_s / E.tread_relaxation.time_constant_s));
}

Prediction effects_path(const TyreModel& m, const TyreParameters& P, const OperatingConditions& c,
                        const PredictOptions& options) {
  const EffectsConfig& E = P.effects;
  if (!(c.load_N > 0)) return failed("load must be greater than 0 N");
  double elastic = 0;
  std::string why;
  if (!elastic_load(E, c, elastic, why)) return failed(why);
  const double scale = carcass_scale(m, P, c, elastic);
  const CarcassAssembly& assembly = m.carcass_assembly();

  const bool rolling = E.rolling_speed.enabled && c.speed_kmh > 0;
  const bool flattening = E.belt_flattening.enabled && E.belt_flattening.stiffness_MPa > 0;
  modal::LagKernels own_kernels;
  Eigen::MatrixXd own_vertical;
  const modal::LagKernels* kernels = &m.kernels;
  const Eigen::MatrixXd* carcass = &assembly.carcass_vertical;
  const bool pressured = pressure_acts(m, c);
  if (rolling || flattening || pressured) {
    own_kernels =
        rebuilt_kernels(m, E, scale, rolling, flattening, c.speed_m_per_s(), c.pressure_Pa());
    own_vertical = carcass_vertical_compliance(own_kernels, m.theta);
    kernels = &own_kernels;
    carcass = &own_vertical;
  }
  const double creep = tread_creep(E, c);
  const bool soil = E.soil_compliance.enabled && c.surface == Surface::soil;
  const double ratio = c.horizontal_force_N / c.load_N;
  const Eigen::MatrixXd horizontal =
      ratio != 0.0 ? horizontal_coupling(m, assembly, ratio, scale) : Eigen::MatrixXd();

  double width = P.tread.width_m;
  if (E.contact_width.enabled) width = std::min(width, E.contact_width.max_width_m());
  Prediction out;
  std::vector<char> warm(options.warm_active.begin(), options.warm_active.end());
  const int max_width_iterations = E.contact_width.enabled ? 60 : 1;
  for (int it = 0; it < max_width_iterations; ++it) {
    PatchOperator op = assemble(m, assembly, P, kernels, *carcass, horizontal, scale, creep, soil,
                                ratio, rolling, width);
    const LoadCase lc{elastic, c.horizontal_force_N * elastic / c.load_N};
    if (m.config.ground.model == ground::GroundModel::rigid) {
      out.footprint = solve_patch(m, std::move(op), lc, warm);
    } else {  // a profile or a soil (ground_patch.h)
      GroundPatchInput in;
      in.warm_active = warm;
      out.footprint = solve_ground_patch(m, std::move(op), lc, m.config.ground, in);
    }
    if (!out.footprint.ok()) return failed(out.footprint.status, out.footprint.message);
    warm = out.footprint.active;
    if (!E.contact_width.enabled) break;
    const double next = crown_width(E, out.footprint.sinking_m);
    const bool done = std::abs(next - width) < 1e-7 * width;
    width = it < 8 ? next : 0.5 * (width + next);  // damped once it has not settled quickly
    if (done) break;
    if (it + 1 == max_width_iterations) {
      return failed("contact width did not converge with the sinking (crown_radius_mm too large?)");
    }
  }
  const FootprintResult& f = out.footprint;
  out.status = SolveStatus::converged;
  out.elastic_load_N = elastic;
  out.sinking_mm = f.sinking_m * 1e3;
  out.length_mm = f.contact_length_m * 1e3;
  out.width_mm = width * 1e3;
  out.on_soil = f.on_soil;
  out.soil_sinkage_mm = f.soil_sinkage_m * 1e3;
  out.tyre_deflection_mm = f.tyre_deflection_m * 1e3;
  out.bekker_width_mm = f.bekker_width_m * 1e3;
  double moment = 0;
  for (const auto& u : f.units) moment += u.fz_N * u.x_m;
  out.rolling_resistance_N = rolling ? moment / (m.config.outer_radius_m - f.sinking_m) : 0.0;
  if (!std::isfinite(out.sinking_mm) || !std::isfinite(out.length_mm) ||
      !std::isfinite(out.rolling_resistance_N)) {
    return failed("prediction is not finite");
  }
  return out;
}

}  // namespace predictor_paths
}  // namespace modaltyre::contact
