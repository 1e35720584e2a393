#include "modaltyre/contact/predictor.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "modaltyre/contact/ground_patch.h"
#include "modaltyre/contact/pneumatic_share.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/ground/rigid_wheel.h"

namespace modaltyre::contact {
namespace {

Prediction failed(std::string why) {
  Prediction p;
  p.message = std::move(why);
  return p;
}

Prediction failed(SolveStatus status, std::string why) {
  Prediction p = failed(std::move(why));
  p.status = status;
  return p;
}

// ---- the effect-free path: the model's own operator -------------------------------------------

// A plain solve_footprint() result as a Prediction: the config's width, no rolling resistance.
Prediction from_footprint(FootprintResult result, const TyreConfig& config) {
  Prediction p;
  p.status = result.status;
  p.message = result.message;
  p.sinking_mm = result.sinking_m * 1e3;
  p.length_mm = result.contact_length_m * 1e3;
  p.width_mm = config.tread.width_m * 1e3;
  p.elastic_load_N = result.load.load_N;
  p.footprint = std::move(result);
  return p;
}

Prediction effect_free(const TyreModel& model, const OperatingConditions& c,
                       std::span<const char> warm) {
  return from_footprint(solve_footprint(model, {c.load_N, c.horizontal_force_N}, warm),
                        model.config);
}

// ---- the effects path, one step per effect ---------------------------------------------------

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

// Kernels of a modified basis on the model's grid, built the way build_tyre_model built the
// static ones (FFT when the orders fit the grid).
modal::LagKernels kernels_for(const TyreModel& m, const modal::ModalBasis& basis,
                              const modal::RollingState& rolling) {
  const int cand = m.candidates();
  return basis.max_order * 2 <= m.units_around
             ? modal::build_periodic_kernels(basis, m.units_around, cand, rolling)
             : modal::build_lag_kernels(basis, m.dtheta_rad, cand, rolling);
}

// Whether the row's pressure differs from the model's and the ring fit can move the carcass
// to it (carcass_source.h): then the kernels are rebuilt for the row.
/// Below it a row's pressure is refused when the ring's terms act (the config reader's bound).
constexpr double kMinRingPressure_kPa = 10;

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

TyreParameters parameters_of(const TyreConfig& config) {
  return {config.compliance_scale, config.tread, config.effects, config.footprint_3d,
          config.pneumatic_share};
}

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

// The one place that decides between the effect-free and the effects path.
// The row's pressure acts through the pneumatic share too (pneumatic_share.h).
bool conditions_act(const TyreConfig& config) {
  return config.effects.any() || config.pneumatic_share > 0;
}

Prediction predict(const TyreModel& model, const OperatingConditions& c,
                   const PredictOptions& options) {
  const bool flat_road =
      model.config.ground.model == ground::GroundModel::rigid && !model.config.rigid;
  if (!conditions_act(model.config) && c.load_N > 0 && !model.config.footprint_3d && flat_road &&
      !pressure_acts(model, c)) {
    return effect_free(model, c, options.warm_active);
  }
  return predict(model, parameters_of(model.config), c, options);
}

std::vector<Prediction> predict_all(const TyreModel& model,
                                    const std::vector<OperatingConditions>& conditions) {
  std::vector<Prediction> out;
  const bool chain = !conditions_act(model.config);
  std::vector<char> warm;
  for (const auto& c : conditions) {
    PredictOptions o;
    if (chain) o.warm_active = warm;
    out.push_back(predict(model, c, o));
    if (chain && out.back().footprint.ok()) warm = out.back().footprint.active;
  }
  return out;
}

namespace {

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

// ---- the 3D patch (patch3d.h) ---------------------------------------------------------------

// The mean of the one or two columns nearest the centre plane.
template <class Value>
double centre_line(int columns, Value value) {
  return columns % 2 ? value(columns / 2) : 0.5 * (value(columns / 2 - 1) + value(columns / 2));
}

// A 3D result as a Prediction: the footprint's units are the sections in contact (resultant,
// centre-line pressure), its edges the longest column's, its contour the centre line's.
Prediction from_patch3d(const Patch3d& patch, Patch3dResult r, double elastic_load_N) {
  Prediction p;
  FootprintResult& f = p.footprint;
  f.status = r.status;
  f.message = r.message;
  f.iterations = r.contact_iterations;
  f.sinking_m = r.sinking_m;
  f.contact_length_m = r.length_m;
  f.equilibrium_residual = r.equilibrium_residual;
  f.complementarity_residual = r.complementarity_residual;
  f.active = r.section_active;
  double longest = -1;
  for (const auto& e : r.column_edges) {
    if (e.contact && e.front_x_m - e.rear_x_m > longest) {
      longest = e.front_x_m - e.rear_x_m;
      f.rear_edge_x_m = e.rear_x_m;
      f.front_edge_x_m = e.front_x_m;
    }
  }
  const auto& z = patch.column_drop_m();
  for (int i = 0; i < r.sections; ++i) {
    // Height of the centre line above the road: its gap, 0 in contact.
    const double gap = centre_line(
        r.columns, [&](int j) { return z[j] + r.belt_deflection(i, j) - r.section_approach_m[i]; });
    f.contour_x_m.push_back(r.x_m[i]);
    f.contour_height_m.push_back(std::max(gap, 0.0));
    if (!(r.section_force_N[i] > 0)) continue;
    PatchUnit u;
    u.x_m = r.x_m[i];
    u.dx_m = r.dx_m[i];
    u.fz_N = r.section_force_N[i];
    u.pressure_Pa = centre_line(r.columns, [&](int j) { return r.pressure_Pa(i, j); });
    f.units.push_back(u);
  }
  p.status = r.status;
  p.message = r.message;
  p.sinking_mm = r.sinking_m * 1e3;
  p.length_mm = r.length_m * 1e3;
  p.width_mm = r.width_m * 1e3;
  p.elastic_load_N = elastic_load_N;
  p.patch3d = std::make_shared<const Patch3dResult>(std::move(r));
  return p;
}

// The 3D patch with the parameters' carcass level and kernels, tread and soil (patch3d.h
// Patch3dPhysics); the effects it cannot take fail with their reason.
Prediction patch3d_path(const TyreModel& m, const TyreParameters& P, const OperatingConditions& c,
                        const PredictOptions& options) {
  const EffectsConfig& E = P.effects;
  if (!(c.load_N > 0)) return failed("load must be greater than 0 N");
  for (const auto& e : effect_catalogue()) {
    if (!e.is_option() && E.enabled(e.id) && !e.refused_with_3d.empty()) {
      return failed(e.name + " cannot be combined with footprint_3d: " + e.refused_with_3d);
    }
  }
  if (c.horizontal_force_N != 0) {
    return failed("the 3D patch (footprint_3d) takes no horizontal force; use a 2D config");
  }
  double elastic = 0;
  std::string why;
  if (!elastic_load(E, c, elastic, why)) return failed(why);
  Patch3dPhysics physics;
  physics.carcass_scale = carcass_scale(m, P, c, elastic);
  modal::LagKernels flattened;
  const bool flattening = E.belt_flattening.enabled && E.belt_flattening.stiffness_MPa > 0;
  physics.rolling = E.rolling_speed.enabled && c.speed_kmh > 0;  // seed 001 eq. 2-5
  if (flattening || physics.rolling || pressure_acts(m, c)) {
    flattened = rebuilt_kernels(m, E, physics.carcass_scale, physics.rolling, flattening,
                                c.speed_m_per_s(), c.pressure_Pa());
    physics.kernels = &flattened;
  }
  if (E.tread_coupling.enabled) physics.tread_coupling_m = E.tread_coupling.coupling_length_m();
  physics.tread = &P.tread;
  physics.tread_creep = tread_creep(E, c);
  physics.inflation_pressure_Pa = c.pressure_Pa();  // the sidewalls' softening (row's pressure)
  if (E.soil_compliance.enabled && c.surface == Surface::soil) {
    physics.soil_m_per_Pa = E.soil_compliance.layer_m() / E.soil_compliance.modulus_Pa();
  }
  try {
    // On a soil: Bekker's b = min(contact width, contact length), iterated with the solution
    // (only k_c / b depends on it; docs/soil.md section 4).
    const ground::GroundSettings& G = m.config.ground;
    const bool soil = G.soil();
    const bool b_acts = G.model == ground::GroundModel::bekker && G.bekker.k_c > 0;
    double b = P.footprint_3d->tread_width_m;
    std::unique_ptr<ground::PressureSinkage> law;
    std::vector<char> warm(options.warm_active.begin(), options.warm_active.end());
    for (int it = 0;; ++it) {
      if (soil) {
        law = G.normal_law(b);
        physics.soil = law.get();
      }
      const Patch3d patch(m, *P.footprint_3d, physics);
      const bool warm_fits = static_cast<int>(warm.size()) == patch.sections();
      Patch3dResult r =
          patch.solve(elastic, warm_fits ? warm : std::vector<char>(), options.warm_cells);
      if (!r.ok()) return failed(r.status, r.message);
      const double next = std::min(r.width_m, r.length_m);
      if (soil && b_acts && std::abs(next - b) > 1e-7 * b) {
        if (it == 50) return failed("Bekker's width b = min(width, length) did not settle");
        warm = r.section_active;
        b = it < 10 ? next : 0.5 * (b + next);
        continue;
      }
      Prediction p = from_patch3d(patch, std::move(r), elastic);
      if (physics.rolling)  // the cells' moment about the axle over the loaded radius
        p.rolling_resistance_N =
            p.patch3d->force_moment_Nm / (m.config.outer_radius_m - p.patch3d->sinking_m);
      if (soil) {
        p.on_soil = p.footprint.on_soil = true;
        p.footprint.soil_sinkage_m = p.patch3d->soil_sinkage_m;
        p.footprint.tyre_deflection_m = p.footprint.sinking_m - p.footprint.soil_sinkage_m;
        p.footprint.bekker_width_m = b;
        p.soil_sinkage_mm = p.footprint.soil_sinkage_m * 1e3;
        p.tyre_deflection_mm = p.footprint.tyre_deflection_m * 1e3;
        p.bekker_width_mm = b * 1e3;
        // Each unit (a section in contact, in order): its deepest cell's soil sinkage.
        const Patch3dResult& q = *p.patch3d;
        std::size_t k = 0;
        for (int i = 0; i < q.sections && k < p.footprint.units.size(); ++i) {
          if (!(q.section_force_N[i] > 0)) continue;
          double deepest = 0;
          for (int j = 0; j < q.columns; ++j)
            deepest = std::max(deepest, q.soil_depth_m[std::size_t(i) * q.columns + j]);
          p.footprint.units[k++].soil_depth_m = deepest;
        }
      }
      if (!std::isfinite(p.sinking_mm) || !std::isfinite(p.length_mm) ||
          !std::isfinite(p.width_mm)) {
        return failed("prediction is not finite");
      }
      return p;
    }
  } catch (const std::invalid_argument& e) {  // settings a calibration or sweep made invalid
    return failed(e.what());
  }
}

}  // namespace

namespace {

// tyre.rigid on a soil: the rigid cylinder of the outer radius pressed into the soil
// (ground/rigid_wheel.h, the static symmetric contact), as wide as the tread (3D) or the contact
// width (2D). Sinking = soil sinkage; no tyre deflection.
Prediction rigid_wheel_path(const TyreModel& m, const TyreParameters& P,
                            const OperatingConditions& c) {
  const double width = P.footprint_3d ? P.footprint_3d->tread_width_m : P.tread.width_m;
  const ground::RigidWheelResult w =
      ground::rigid_wheel_static(m.config.ground, {m.config.outer_radius_m, width}, c.load_N);
  if (!w.ok()) return failed(w.status, w.message);
  Prediction p;
  p.status = SolveStatus::converged;
  p.message = "the rigid wheel (tyre.rigid): " + w.message;
  p.sinking_mm = p.soil_sinkage_mm = w.sinkage_m * 1e3;
  p.length_mm = w.contact_length_m * 1e3;
  p.width_mm = width * 1e3;
  p.bekker_width_mm = w.bekker_width_m * 1e3;
  p.on_soil = true;
  p.elastic_load_N = c.load_N;
  FootprintResult& f = p.footprint;
  f.status = SolveStatus::converged;
  f.message = p.message;
  f.sinking_m = w.sinkage_m;
  f.contact_length_m = w.contact_length_m;
  f.rear_edge_x_m = -0.5 * w.contact_length_m;
  f.front_edge_x_m = 0.5 * w.contact_length_m;
  f.equilibrium_residual = std::abs(w.vertical_N - c.load_N) / c.load_N;
  f.on_soil = true;
  f.soil_sinkage_m = w.sinkage_m;
  f.bekker_width_m = w.bekker_width_m;
  return p;
}

Prediction structural(const TyreModel& model, const TyreParameters& parameters,
                      const OperatingConditions& c, const PredictOptions& options) {
  if (model.config.rigid && model.config.ground.soil() && c.load_N > 0)
    return rigid_wheel_path(model, parameters, c);
  return parameters.footprint_3d ? patch3d_path(model, parameters, c, options)
                                 : effects_path(model, parameters, c, options);
}

// modal.pneumatic_share (pneumatic_share.h, docs/footprint.md section 8): the structural tyre
// carries F_s, the pressure beta p over its contact area the rest; the horizontal force stays on
// the structural tyre (the pressure acts normal to the road).
Prediction pneumatic_split(const TyreModel& model, const TyreParameters& parameters,
                           const OperatingConditions& c, const PredictOptions& options,
                           double pressure_Pa) {
  std::vector<char> warm(options.warm_active.begin(), options.warm_active.end());
  std::vector<double> warm_cells;  // the 3D patch's lateral patterns of the last solve
  std::vector<std::pair<double, Prediction>> solved;
  Prediction failure;
  auto area_at = [&](double F, double& area) {
    OperatingConditions cs = c;
    cs.load_N = F;
    PredictOptions o;
    o.warm_active = warm;
    o.warm_cells = warm_cells;
    Prediction p = structural(model, parameters, cs, o);
    if (!p.ok()) {
      failure = std::move(p);
      return false;
    }
    warm = p.footprint.active;
    if (p.patch3d) warm_cells = p.patch3d->cell_force_N;
    area =
        p.patch3d ? contact_area_m2(*p.patch3d) : contact_area_m2(p.footprint, p.width_mm * 1e-3);
    solved.emplace_back(F, std::move(p));
    return true;
  };
  const LoadSplit split = split_pneumatic_load(c.load_N, pressure_Pa, area_at);
  if (!split.ok()) {
    if (!failure.ok() && !failure.message.empty()) return failure;
    std::ostringstream msg;
    msg.precision(12);
    msg << "pneumatic share: no load split F_s + p A = " << c.load_N << " N after " << split.solves
        << " solves (" << to_string(split.status) << "; last F_s " << split.structural_load_N
        << " N, residual " << split.residual_N << " N)";
    return failed(msg.str());
  }
  Prediction p;
  for (auto& [F, q] : solved) {
    if (F == split.structural_load_N) p = std::move(q);
  }
  const double pneumatic_N = pressure_Pa * split.area_m2;
  p.elastic_load_N += pneumatic_N;
  FootprintResult& f = p.footprint;
  if (p.patch3d) {
    Patch3dResult r = *p.patch3d;
    add_pneumatic_pressure(r, pressure_Pa, r.load_N + pneumatic_N);
    // The units are the sections in contact, in order (from_patch3d): their resultants and
    // centre-line pressures gain the pneumatic part.
    std::size_t k = 0;
    for (int i = 0; i < r.sections && k < f.units.size(); ++i) {
      if (!(r.section_force_N[i] > 0)) continue;
      f.units[k].fz_N = r.section_force_N[i];
      f.units[k].pressure_Pa = centre_line(r.columns, [&](int j) { return r.pressure_Pa(i, j); });
      ++k;
    }
    f.equilibrium_residual = r.equilibrium_residual;
    p.patch3d = std::make_shared<const Patch3dResult>(std::move(r));
  } else {
    add_pneumatic_pressure(f, pressure_Pa, p.width_mm * 1e-3, f.load.load_N + pneumatic_N);
  }
  return p;
}

}  // namespace

Prediction predict(const TyreModel& model, const TyreParameters& parameters,
                   const OperatingConditions& c, const PredictOptions& options) {
  if (pressure_acts(model, c) && c.pressure_kPa < kMinRingPressure_kPa) {
    Prediction p = failed("pressure " + std::to_string(c.pressure_kPa) +
                          " kPa: below 10 kPa the ring's hoop tension and sidewall foundation "
                          "vanish (an uninflated tyre is not a modal carcass)");
    p.footprint.load = {c.load_N, c.horizontal_force_N};
    return p;
  }
  const double pneumatic_Pa = parameters.pneumatic_share * c.pressure_Pa();
  Prediction p = pneumatic_Pa > 0 && c.load_N > 0
                     ? pneumatic_split(model, parameters, c, options, pneumatic_Pa)
                     : structural(model, parameters, c, options);
  p.footprint.load = {c.load_N, c.horizontal_force_N};  // the applied load, failed or not
  return p;
}

}  // namespace modaltyre::contact
