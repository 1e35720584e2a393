#include "modaltyre/contact/predictor.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "modaltyre/core/errors.h"

namespace modaltyre::contact {
namespace {

Prediction failed(std::string why) {
  Prediction p;
  p.message = std::move(why);
  return p;
}

// Kernels of a modified basis on the model's grid, built the way build_tyre_model built the
// static ones (FFT when the orders fit the grid).
modal::LagKernels kernels_for(const TyreModel& m, const modal::ModalBasis& basis,
                              const modal::RollingState& rolling) {
  const int cand = m.candidates();
  return basis.max_order * 2 <= m.units_around
             ? modal::build_periodic_kernels(basis, m.units_around, cand, rolling)
             : modal::build_lag_kernels(basis, m.dtheta_rad, cand, rolling);
}

}  // namespace

const std::vector<std::string>& observable_names() {
  static const std::vector<std::string> names = {"sinking_mm", "length_mm", "width_mm",
                                                 "rolling_resistance_N"};
  return names;
}

double Prediction::observable(const std::string& name) const {
  if (name == "sinking_mm") return sinking_mm;
  if (name == "length_mm") return length_mm;
  if (name == "width_mm") return width_mm;
  if (name == "rolling_resistance_N") return rolling_resistance_N;
  throw std::invalid_argument("unknown observable " + name);
}

Prediction prediction_from(FootprintResult result, const TyreConfig& config) {
  Prediction p;
  p.ok = result.converged;
  p.message = result.message;
  p.sinking_mm = result.sinking_m * 1e3;
  p.length_mm = result.contact_length_m * 1e3;
  p.width_mm = config.tread.width_m * 1e3;
  p.elastic_load_N = result.load.load_N;
  p.footprint = std::move(result);
  return p;
}

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

FootprintPredictor::FootprintPredictor(TyreModel model) : model_(std::move(model)) {
  carcass_vertical_ = carcass_vertical_compliance(model_.kernels, model_.theta);
  for (double th : model_.theta) cos_.push_back(std::cos(th)), sin_.push_back(std::sin(th));
}

Prediction FootprintPredictor::predict(const TyreConfig& params, const OperatingConditions& c,
                                       const std::vector<char>* warm) const {
  const TyreModel& m = model_;
  const EffectsConfig& E = params.effects;
  const double R0 = m.config.outer_radius_m;
  const int cand = m.candidates();
  const double ds = m.unit_length_m;
  if (!(c.load_N > 0)) return failed("load must be greater than 0 N");

  // Dry friction (seed 000, Saint-Venant element in parallel): the element carries F_f against
  // the motion, the elastic tyre the rest.
  double elastic_load = c.load_N;
  if (E.dry_friction.enabled) {
    const double ff = E.dry_friction.friction_force_N;
    elastic_load += c.branch == Branch::unloading ? ff : -ff;
    if (!(elastic_load > 0)) {
      std::ostringstream msg;
      msg << "load " << c.load_N << " N does not exceed the dry-friction force " << ff
          << " N: the tyre does not deflect on the loading branch";
      return failed(msg.str());
    }
  }

  // Carcass compliance factor.
  double scale = params.compliance_scale / m.config.compliance_scale;
  if (E.inflation_pressure.enabled) {
    // seed 000 eq. (3): h ~ (1 + p_W)^-1, p_W in bar (docs/rheology.md).
    const double p_bar = c.pressure_kPa * 1e-2;
    const double p0_bar = E.inflation_pressure.modal_test_pressure_kPa * 1e-2;
    scale *= std::pow((1 + p0_bar) / (1 + p_bar), E.inflation_pressure.exponent);
  }
  if (E.load_stiffening.enabled) {
    scale *=
        std::pow(elastic_load / E.load_stiffening.reference_load_N, -E.load_stiffening.exponent);
  }

  // Carcass kernels: static ones unless rolling or belt flattening change them.
  const bool rolling = E.rolling_speed.enabled && c.speed_kmh > 0;
  const bool flattening = E.belt_flattening.enabled && E.belt_flattening.stiffness_MPa > 0;
  modal::LagKernels own_kernels;
  Eigen::MatrixXd own_carcass;
  const modal::LagKernels* kernels = &m.kernels;
  const Eigen::MatrixXd* carcass = &carcass_vertical_;
  if (rolling || flattening) {
    modal::ModalBasis basis = m.basis;
    if (flattening) {
      // Foundation kappa on orders >= 2: c_k -> c_k / (1 + pi R kappa c_k), c_k the order's
      // (scaled) static radial compliance; every term of the order gets the same factor.
      const double kappa = E.belt_flattening.stiffness_MPa * 1e6;
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
      for (auto& t : basis.terms) t.damping_ratio *= E.rolling_speed.damping_scale;
      rs.speed_m_s = c.speed_kmh / 3.6;
      rs.radius_m = R0;
    }
    own_kernels = kernels_for(m, basis, rs);
    own_carcass = carcass_vertical_compliance(own_kernels, m.theta);
    kernels = &own_kernels;
    carcass = &own_carcass;
  }

  // Tread: springs per unit from the modulus and the width (seed 001 eq. 6-9), creeping while
  // the load is held (tread_relaxation), optionally shear-coupled (tread_coupling).
  const auto& T = params.tread;
  double creep = 1;
  if (E.tread_relaxation.enabled && c.hold_s > 0) {
    creep += E.tread_relaxation.creep_ratio *
             (1 - std::exp(-c.hold_s / E.tread_relaxation.time_constant_s));
  }
  const double G = T.modulus_Pa / (2 * (1 + T.poisson));
  const bool soil = E.soil_compliance.enabled && c.surface == Surface::soil;
  const double ratio = c.horizontal_force_N / c.load_N;
  // Horizontal force: the static cross-compliance, carcass part scaled like the vertical one;
  // its tread part (the model's springs) is swapped for this prediction's below.
  Eigen::MatrixXd horizontal;
  if (ratio != 0.0) {
    horizontal = vertical_from_horizontal(m);
    for (int j = 0; j < cand; ++j) {
      const double cj = cos_[j], sj = sin_[j];
      horizontal(j, j) -= cj * (-sj) / m.k_radial_N_m + sj * cj / m.k_tangential_N_m;
    }
    horizontal *= ratio * scale;
  }

  double width = T.width_m;
  if (E.contact_width.enabled) width = std::min(width, E.contact_width.max_width_mm * 1e-3);
  Prediction out;
  std::vector<char> warm_set = warm ? *warm : std::vector<char>{};
  const int max_width_iterations = E.contact_width.enabled ? 60 : 1;
  for (int it = 0; it < max_width_iterations; ++it) {
    const double k_r = T.modulus_Pa * width * ds / T.thickness_m;
    const double k_t = G * width * ds / T.thickness_m;
    PatchOperator op;
    op.kernels = kernels;
    op.carcass_scale = scale;
    op.tread_radial_lag = pasternak_tread_lags(
        k_r / creep, E.tread_coupling.enabled ? E.tread_coupling.coupling_length_mm * 1e-3 : 0, ds,
        cand);
    op.tread_tangential_compliance = creep / k_t;
    op.width_m = width;
    op.horizontal_ratio = ratio;
    op.symmetric = !rolling && ratio == 0.0;
    op.compliance = scale * *carcass;
    const int lags = static_cast<int>(op.tread_radial_lag.size());
    for (int j = 0; j < cand; ++j) {
      const double cj = cos_[j], sj = sin_[j];
      for (int i = std::max(0, j - lags + 1); i < std::min(cand, j + lags); ++i) {
        op.compliance(i, j) += cos_[i] * cj * op.tread_radial_lag[std::abs(i - j)];
      }
      op.compliance(j, j) += sj * sj * op.tread_tangential_compliance;
      if (soil) {
        // Winkler soil under the unit (static part of seed 000 eq. 23): z = p H / E2.
        op.compliance(j, j) += E.soil_compliance.layer_mm * 1e-3 /
                               (E.soil_compliance.modulus_MPa * 1e6 * width * ds * cj);
      }
    }
    if (ratio != 0.0) {
      op.compliance += horizontal;
      for (int j = 0; j < cand; ++j) {  // tread under the unit's own horizontal force (eq. 6)
        const double cj = cos_[j], sj = sin_[j];
        op.compliance(j, j) += ratio * (cj * (-sj) * op.tread_radial_lag[0] +
                                        sj * cj * op.tread_tangential_compliance);
      }
    }
    if (op.symmetric) op.compliance = 0.5 * (op.compliance + op.compliance.transpose()).eval();

    LoadCase lc{elastic_load, c.horizontal_force_N * elastic_load / c.load_N};
    out.footprint = solve_patch(m, std::move(op), lc, warm_set.empty() ? nullptr : &warm_set);
    if (!out.footprint.converged) return failed(out.footprint.message);
    warm_set = out.footprint.active;
    if (!E.contact_width.enabled) break;
    // Crown profile: chord of the transverse crown arc pressed in by the sinking.
    const double d = out.footprint.sinking_m;
    const double next = std::clamp(2 * std::sqrt(2 * E.contact_width.crown_radius_mm * 1e-3 * d),
                                   1e-3, E.contact_width.max_width_mm * 1e-3);
    const bool done = std::abs(next - width) < 1e-7 * width;
    width = it < 8 ? next : 0.5 * (width + next);  // damped once it has not settled quickly
    if (done) break;
    if (it + 1 == max_width_iterations) {
      return failed("contact width did not converge with the sinking (crown_radius_mm too large?)");
    }
  }
  const FootprintResult& f = out.footprint;
  out.ok = true;
  out.elastic_load_N = elastic_load;
  out.sinking_mm = f.sinking_m * 1e3;
  out.length_mm = f.contact_length_m * 1e3;
  out.width_mm = width * 1e3;
  double moment = 0;
  for (const auto& u : f.units) moment += u.fz_N * u.x_m;
  out.rolling_resistance_N = rolling ? moment / (R0 - f.sinking_m) : 0.0;
  if (!std::isfinite(out.sinking_mm) || !std::isfinite(out.length_mm) ||
      !std::isfinite(out.rolling_resistance_N)) {
    return failed("prediction is not finite");
  }
  return out;
}

}  // namespace modaltyre::contact
