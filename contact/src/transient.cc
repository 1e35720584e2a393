#include "modaltyre/contact/transient.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <sstream>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/leading_eigenpairs.h"

namespace modaltyre::contact {
namespace {

using cd = std::complex<double>;

/// Eigenvalues of the residual compliance below this fraction of the largest are dropped: their
/// displacements are at the rounding level of the sum.
constexpr double kResidualEigenCutoff = 1e-13;
/// Absolute tolerance of displacement-like states [m] (0.1 um, ~1e-5 of a sinking).
constexpr double kDisplacementTolerance = 1e-7;
/// Offset of the contact root functions [m]: a switch is located where the tip penetration
/// crosses this, 1e4 times the rounding noise of g (~1e-16 m) and 1e5 times below
/// kDisplacementTolerance. A unit grazing the road with zero force (g = 0 to rounding, e.g. the
/// centre of a ladder-like static patch) otherwise makes CVODE return a root at every rounding
/// flip of g without advancing in time. The kink of f = k max(0, g) is located to eta / |g'|.
constexpr double kRootOffset_m = 1e-12;
/// Root returns in a row within kZenoWindow_s of each other before the run is stopped as
/// chattering (never a hang): a located switch is normally followed by a step.
constexpr int kZenoRootReturns = 1000;
constexpr double kZenoWindow_s = 1e-12;
/// Output samples of one run (memory and CSV rows): 1e6 is 2000 s at the default 2 ms.
constexpr double kMaxTransientSamples = 1e6;
/// Upwind stencil of the tread advection, de/dtheta ~ (c0 e_i + c1 e_{i+1} + c2 e_{i+2}) / dtheta:
/// second-order one-sided from the front. First order (-1, 1, 0) converged the rolling resistance
/// at O(dtheta): 59.3 / 60.6 / 61.2 / 61.5 N at 2 / 1 / 0.5 / 0.25 mm, against 61.3 / 61.6 /
/// 61.7 / 61.8 N with this one (60 km/h, docs/transient.md section 1).
constexpr double kUpwind[3] = {-1.5, 2.0, -0.5};
/// Minimum damping ratio used for the relaxation time of the quasi-static residual orders.
constexpr double kResidualMinDamping = 0.01;

/// Length beyond each end of the contact patch whose units enter the Jacobian as if in contact
/// (see TransientSystem::jacobian); 4 units at the default 0.5 mm mesh (measured best of 0-10).
constexpr double kJacobianEdgeMargin_m = 2e-3;

/// Residual eigenpairs with lambda below this fraction of the largest are not integrated: their
/// diagonal is lumped into the tread spring (docs/transient.md, "truncated residual"). 0.3 keeps
/// 16 of 725 pairs at the default 0.5 mm mesh and moves the static footprint at 4000 N by
/// 0.01 % (sinking) and 0.002 % (length); measured figures in docs/transient.md section 1.
constexpr double kResidualKeepFraction = 0.3;

/// Vertical compliance on the candidates from lag kernels (as in tyre_model.cc, no tread).
Eigen::MatrixXd vertical_from_kernels(const TyreModel& t, const modal::LagKernels& K) {
  const int m = t.candidates();
  Eigen::MatrixXd C(m, m);
  for (int i = 0; i < m; ++i) {
    const double ci = std::cos(t.theta[i]), si = std::sin(t.theta[i]);
    for (int j = 0; j < m; ++j) {
      const double cj = std::cos(t.theta[j]), sj = std::sin(t.theta[j]);
      const modal::Transfer2x2 h = K.at(i - j);
      C(i, j) = (h.r_from_r * cj + h.r_from_t * sj) * ci + (h.t_from_r * cj + h.t_from_t * sj) * si;
    }
  }
  return 0.5 * (C + C.transpose());
}

}  // namespace

Scenario parse_scenario(const std::string& name) {
  if (name == "load-hold") return Scenario::load_hold;
  if (name == "free-vibration") return Scenario::free_vibration;
  if (name == "rolling") return Scenario::rolling;
  if (name == "cleat") return Scenario::cleat;
  throw InputError(
      InputLocation{"--scenario", 0, ""},
      "unknown scenario '" + name + "': expected one of load-hold, free-vibration, rolling, cleat");
}

const char* to_string(Scenario s) {
  switch (s) {
    case Scenario::load_hold:
      return "load-hold";
    case Scenario::free_vibration:
      return "free-vibration";
    case Scenario::rolling:
      return "rolling";
    case Scenario::cleat:
      return "cleat";
  }
  return "?";
}

// ---------------------------------------------------------------------------------------------
// Model

TransientModel build_transient_model(const TyreModel& tyre) {
  TransientModel M;
  M.tyre = tyre;
  M.settings = tyre.config.transient;
  const auto& S = M.settings;
  const int m = tyre.candidates();
  M.m = m;
  const int K = S.dynamic_max_order;

  // Dynamic coordinates from the terms of order <= K.
  struct Coord {
    int order;
    double omega, zeta;
    Eigen::VectorXd pr, pt;
    int partner;
    double sign;
  };
  std::vector<Coord> coords;
  modal::ModalBasis residual = tyre.basis;
  residual.terms.clear();
  for (const auto& t : tyre.basis.terms) {
    if (t.order > K) {
      residual.terms.push_back(t);
      continue;
    }
    // Rank-one pieces of the Hermitian 2x2 P (Cholesky with pivoting on the larger diagonal).
    std::vector<std::pair<cd, cd>> pieces;
    const double prr = t.P_rr.real(), ptt = t.P_tt.real();
    if (prr >= ptt && prr > 0) {
      const double a = std::sqrt(prr);
      pieces.push_back({cd(a, 0), std::conj(t.P_rt) / a});
      const double d = ptt - std::norm(t.P_rt) / prr;
      if (d > 1e-12 * std::max(ptt, 1e-300)) pieces.push_back({cd(0, 0), cd(std::sqrt(d), 0)});
    } else if (ptt > 0) {
      const double a = std::sqrt(ptt);
      pieces.push_back({t.P_rt / a, cd(a, 0)});  // a_r conj(a_t) = P_rt
      const double d = prr - std::norm(t.P_rt) / ptt;
      if (d > 1e-12 * std::max(prr, 1e-300)) pieces.push_back({cd(std::sqrt(d), 0), cd(0, 0)});
    }
    const double sw = std::sqrt(t.weight);
    for (const auto& [ar, at] : pieces) {
      const int members = t.order == 0 ? 1 : 2;
      const int first = static_cast<int>(coords.size());
      for (int c = 0; c < members; ++c) {
        Coord co;
        co.order = t.order;
        co.omega = t.omega_rad_s;
        co.zeta = t.damping_ratio * S.modal_damping_scale;
        co.pr.resize(m);
        co.pt.resize(m);
        for (int i = 0; i < m; ++i) {
          const cd e = std::polar(1.0, t.order * tyre.theta[i]);
          const cd vr = ar * e, vt = at * e;
          co.pr(i) = sw * (c == 0 ? vr.real() : vr.imag());
          co.pt(i) = sw * (c == 0 ? vt.real() : vt.imag());
        }
        co.partner = members == 2 ? first + (1 - c) : -1;
        co.sign = members == 2 ? (c == 0 ? 1.0 : -1.0) : 0.0;
        coords.push_back(std::move(co));
      }
    }
  }
  M.nq = static_cast<int>(coords.size());
  M.psi.resize(m, M.nq);
  M.phi_r.resize(m, M.nq);
  M.phi_t.resize(m, M.nq);
  for (int j = 0; j < M.nq; ++j) {
    const Coord& c = coords[j];
    M.omega.push_back(c.omega);
    M.zeta.push_back(c.zeta);
    M.order.push_back(c.order);
    M.partner.push_back(c.partner);
    M.pair_sign.push_back(c.sign);
    M.phi_r.col(j) = c.pr;
    M.phi_t.col(j) = c.pt;
    for (int i = 0; i < m; ++i) {
      M.psi(i, j) = c.pr(i) * std::cos(tyre.theta[i]) + c.pt(i) * std::sin(tyre.theta[i]);
    }
  }

  // Residual orders: static vertical compliance, eigen-decomposed.
  if (!residual.terms.empty()) {
    M.residual_kernels = modal::build_lag_kernels(residual, tyre.dtheta_rad, m);
    const Eigen::MatrixXd R = vertical_from_kernels(tyre, M.residual_kernels);
    // Only the pairs kept are computed (the tridiagonal's eigenvalues, then inverse iteration):
    // the full eigenvector matrix was ~0.3 s of every model build at 0.5 mm.
    const solvers::EigenPairs kept =
        solvers::leading_eigenpairs(R, std::max(kResidualEigenCutoff, kResidualKeepFraction));
    M.nr = static_cast<int>(kept.values.size());
    M.V = kept.vectors;
    M.lambda = kept.values;
    // The dropped eigenpairs keep their diagonal (self-compliance of each unit), lumped into the
    // tread spring below; only their off-diagonal coupling is lost (docs/transient.md section 1).
    M.residual_lumped = (R.diagonal() - (M.V.array().square().matrix() * M.lambda)).cwiseMax(0.0);
    double wmin = 1e300, zsum = 0;
    int kmin = 1 << 30;
    for (const auto& t : residual.terms) {
      wmin = std::min(wmin, t.omega_rad_s);
      kmin = std::min(kmin, t.order);
      zsum += t.damping_ratio * S.modal_damping_scale;
    }
    const double zmean = zsum / residual.terms.size();
    M.residual_min_order = kmin;
    M.residual_min_omega = wmin;
    M.tau_residual_s = 2 * std::max(zmean, kResidualMinDamping) / wmin;
  } else {
    M.V.resize(m, 0);
    M.lambda.resize(0);
    M.residual_kernels = modal::LagKernels{};
    M.residual_lumped = Eigen::VectorXd::Zero(m);
  }

  // Tread.
  const double ratio = S.instantaneous_stiffness_ratio;
  M.k_relaxed.resize(m);
  M.k_contact.resize(m);
  M.k_kv.resize(m);
  M.c_kv.resize(m);
  M.x_road.resize(m);
  M.tread_time_constant_s =
      tyre.config.tread.tan_delta / (2 * M_PI * S.tread_reference_frequency_hz);
  for (int i = 0; i < m; ++i) {
    const double c = std::cos(tyre.theta[i]), s = std::sin(tyre.theta[i]);
    const double k = 1.0 / (c * c / tyre.k_radial_N_m + s * s / tyre.k_tangential_N_m);
    M.k_relaxed(i) = k;
    M.x_road(i) = tyre.config.outer_radius_m * s;
    // The lumped residual compliance acts in series with the (instantaneous) tread spring.
    const double d = M.residual_lumped(i);
    if (S.relaxation) {
      M.k_contact(i) = 1.0 / (1.0 / (ratio * k) + d);
      M.k_kv(i) = k * ratio / (ratio - 1);
      M.c_kv(i) = M.k_kv(i) * M.tread_time_constant_s;
    } else {
      M.k_contact(i) = 1.0 / (1.0 / k + d);
      M.k_kv(i) = 0;
      M.c_kv(i) = 0;
    }
  }
  if (S.relaxation && !(M.tread_time_constant_s > 0)) {
    throw InputError(InputLocation{tyre.config.source, 0, "transient.relaxation"},
                     "tread relaxation needs tread.tan_delta > 0 (or set transient.relaxation: "
                     "false)");
  }
  M.psi_by_unit = M.psi.transpose();
  M.V_by_unit = M.V.transpose();
  return M;
}

Eigen::MatrixXd TransientModel::at_rest_compliance() const {
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(m, m);
  for (int j = 0; j < nq; ++j) C += psi.col(j) * psi.col(j).transpose() / (omega[j] * omega[j]);
  if (nr > 0) C += V * lambda.asDiagonal() * V.transpose();
  for (int i = 0; i < m; ++i) C(i, i) += 1.0 / k_relaxed(i) + residual_lumped(i);
  return C;
}

TruncationError truncation_error(const TransientModel& model, double load_N) {
  TruncationError e;
  const Eigen::MatrixXd C = model.at_rest_compliance();
  e.compliance_rel = (C - model.tyre.vertical_compliance).cwiseAbs().maxCoeff() /
                     model.tyre.vertical_compliance.cwiseAbs().maxCoeff();
  TyreModel truncated = model.tyre;
  truncated.vertical_compliance = C;
  const LoadCase load{load_N, 0};
  const FootprintResult exact = solve_patch(model.tyre, static_operator(model.tyre, 0.0), load);
  const FootprintResult approx = solve_patch(truncated, static_operator(truncated, 0.0), load);
  if (!exact.converged || !approx.converged)
    throw ComputationError("truncation_error: footprint did not converge");
  e.sinking_rel = approx.sinking_m / exact.sinking_m - 1.0;
  e.length_rel = approx.contact_length_m / exact.contact_length_m - 1.0;
  return e;
}

// ---------------------------------------------------------------------------------------------
// Scenarios

// Speed ramp from rest: smoothstep V (3 s^2 - 2 s^3), s = t / ramp_s. The acceleration rises
// from 0 and returns to 0: a linear ramp's jump of V' at t = 0 (infinite jerk) excited the
// lightly damped carcass modes, and resolving their ringing took ~1000 steps of 0.4 ms in the
// first 0.4 s of the default rolling run (docs/transient.md section 3).
double ScenarioPlan::speed(double t) const {
  if (speed_m_s == 0) return 0;
  if (ramp_s <= 0 || t >= ramp_s) return speed_m_s;
  const double s = std::max(t, 0.0) / ramp_s;
  return speed_m_s * s * s * (3 - 2 * s);
}
double ScenarioPlan::acceleration(double t) const {
  if (ramp_s <= 0 || t >= ramp_s || t < 0) return 0;
  const double s = t / ramp_s;
  return speed_m_s * 6 * s * (1 - s) / ramp_s;
}
double ScenarioPlan::distance(double t) const {
  if (ramp_s <= 0) return speed_m_s * t;
  if (t <= ramp_s) {
    const double s = std::max(t, 0.0) / ramp_s;
    return speed_m_s * ramp_s * s * s * s * (1 - 0.5 * s);
  }
  return 0.5 * speed_m_s * ramp_s + speed_m_s * (t - ramp_s);
}
double ScenarioPlan::step_limit(double t) const {
  return t >= step_limit_from_s && t < step_limit_until_s ? step_limit_s : 0.0;
}

ScenarioPlan plan_scenario(const TransientModel& model, Scenario s) {
  const auto& T = model.settings;
  const std::string src = model.tyre.config.source;
  ScenarioPlan p;
  p.scenario = s;
  switch (s) {
    case Scenario::load_hold: {
      const auto& L = T.load_hold;
      if (L.hold_s < 0) {
        throw InputError(InputLocation{src, 0, "transient.load_hold.hold_s"},
                         "hold time must not be negative");
      }
      const double t_ramp = L.load_N / L.ramp_rate_N_s;
      p.duration_s = t_ramp + L.hold_s;
      p.breakpoints = {t_ramp};
      const double F = L.load_N, rate = L.ramp_rate_N_s;
      p.load = [F, rate](double t) { return std::min(F, rate * std::max(t, 0.0)); };
      break;
    }
    case Scenario::free_vibration: {
      const auto& V = T.free_vibration;
      if (V.initial_load_N == V.load_N) {
        throw InputError(InputLocation{src, 0, "transient.free_vibration.initial_load_N"},
                         "equals load_N: the tyre would not vibrate");
      }
      p.duration_s = V.duration_s;
      p.initial_load_N = V.initial_load_N;
      const double F = V.load_N;
      p.load = [F](double) { return F; };
      break;
    }
    case Scenario::rolling: {
      const auto& R = T.rolling;
      p.duration_s = R.duration_s;
      p.initial_load_N = R.load_N;
      p.speed_m_s = R.speed_m_s;
      p.ramp_s = R.ramp_s;
      if (R.ramp_s > 0 && R.ramp_s < R.duration_s) p.breakpoints = {R.ramp_s};
      const double F = R.load_N;
      p.load = [F](double) { return F; };
      break;
    }
    case Scenario::cleat: {
      const auto& C = T.cleat;
      p.initial_load_N = C.load_N;
      p.speed_m_s = C.speed_m_s;
      p.ramp_s = C.ramp_s;

      p.cleat = true;
      p.cleat_height_m = C.height_m;
      p.cleat_length_m = C.length_m;
      const double xw = model.x_road.maxCoeff();
      const double settle = 0.1;  // steady rolling before the cleat enters the window
      const double t_arrive = C.ramp_s + settle;
      p.cleat_start_m = xw + 0.5 * C.length_m + p.distance(t_arrive);
      // Until the cleat has left the window at the back, plus the same settling time.
      const double travel = p.cleat_start_m + xw + 0.5 * C.length_m;
      const double t_leave = C.ramp_s + (travel - p.distance(C.ramp_s)) / C.speed_m_s;
      p.duration_s = t_leave + settle;
      // The road moves under the tyre: CVODE cannot see a cleat that enters and leaves a unit
      // between two steps (a settled run stepped 26 ms and jumped onto it: 114 kN). While the
      // cleat is in the window the step is bounded by half the passage time of one of its
      // cosine edges.
      p.step_limit_from_s = t_arrive;
      p.step_limit_until_s = t_leave;
      p.step_limit_s = 0.5 * (0.25 * C.length_m) / C.speed_m_s;
      p.breakpoints = {t_arrive, t_leave};
      if (C.ramp_s > 0) p.breakpoints.push_back(C.ramp_s);
      const double F = C.load_N;
      p.load = [F](double) { return F; };
      if (C.height_m >= model.tyre.sag.maxCoeff()) {
        throw InputError(InputLocation{src, 0, "transient.cleat.height_mm"},
                         "cleat higher than the tyre's sag at the edge of the candidate window; "
                         "increase contact.window_mm");
      }
      break;
    }
  }
  if (!(p.duration_s > 0)) {
    throw InputError(InputLocation{src, 0, "transient"},
                     std::string("scenario ") + to_string(s) + " has zero duration");
  }
  if (model.settings.output_step_s > p.duration_s) {
    throw InputError(InputLocation{src, 0, "transient.output_step_ms"},
                     "output step longer than the scenario");
  }
  // Every output step is a sample held in memory and a CSV row: bounded, so that a tiny step
  // (1e-308 ms) or a long run is refused at once instead of filling the memory.
  const double samples = p.duration_s / model.settings.output_step_s;
  if (!(samples <= kMaxTransientSamples)) {
    std::ostringstream msg;
    msg << "output step " << model.settings.output_step_s * 1e3 << " ms over the scenario's "
        << p.duration_s << " s gives " << samples << " samples; at most " << kMaxTransientSamples
        << " are written: use an output step of at least "
        << p.duration_s / kMaxTransientSamples * 1e3 << " ms or a shorter scenario";
    throw InputError(InputLocation{src, 0, "transient.output_step_ms"}, msg.str());
  }
  return p;
}

// ---------------------------------------------------------------------------------------------
// The ODE

TransientSystem::TransientSystem(const TransientModel& model, const ScenarioPlan& plan)
    : model_(model), plan_(plan) {}

double TransientSystem::road(double t, int i, double* slope) const {
  if (slope) *slope = 0;
  if (!plan_.cleat) return 0;
  const double L = plan_.cleat_length_m, H = plan_.cleat_height_m;
  const double xi = model_.x_road(i) - (plan_.cleat_start_m - plan_.distance(t));
  const double a = 0.25 * L;  // cosine edges, a quarter of the length each
  const double ax = std::abs(xi);
  if (ax >= 0.5 * L) return 0;
  if (ax <= 0.5 * L - a) return H;
  const double u = M_PI * (ax - (0.5 * L - a)) / a;
  if (slope) *slope = -0.5 * H * std::sin(u) * M_PI / a * (xi > 0 ? 1.0 : -1.0);
  return 0.5 * H * (1 + std::cos(u));
}

void TransientSystem::tip_penetration(double t, const double* y, Eigen::VectorXd& g) const {
  const auto& M = model_;
  const Eigen::Map<const Eigen::VectorXd> q(y, M.nq), r(y + 2 * M.nq, M.nr);
  const double z = y[M.z_index()];
  g.noalias() = M.psi * q;
  if (M.nr > 0) g.noalias() += M.V * r;
  // g = z + h - s - u (- e): the sign flips in place, no temporary.
  g = -g;
  g.array() += z;
  g -= M.tyre.sag;
  if (plan_.cleat)
    for (int i = 0; i < M.m; ++i) g(i) += road(t, i);
  if (M.settings.relaxation) g -= Eigen::Map<const Eigen::VectorXd>(y + M.e_index(), M.m);
}

void TransientSystem::forces_into(double t, const double* y, Eigen::VectorXd& f) const {
  tip_penetration(t, y, f);
  f = (f.array() > 0).select(model_.k_contact.array() * f.array(), 0.0);
}

Eigen::VectorXd TransientSystem::forces(double t, const double* y) const {
  Eigen::VectorXd f(model_.m);
  forces_into(t, y, f);
  return f;
}

void TransientSystem::roots(double t, const double* y, double* g) const {
  Eigen::Map<Eigen::VectorXd> gm(g, model_.m);
  scratch_g_.resize(model_.m);
  tip_penetration(t, y, scratch_g_);
  scratch_g_.array() -= kRootOffset_m;
  // CVODE treats an exact 0 as a root; when its root finder lands on one, the function is still
  // 0.0 a rounding step later, which cvRcheck2 rejects as "root found at and very near t"
  // (CV_ILL_INPUT). An exact 0 is reported as just below (the side of no force).
  gm = (scratch_g_.array() == 0.0).select(-std::numeric_limits<double>::min(), scratch_g_);
}

void TransientSystem::rhs(double t, const double* y, double* ydot) const {
  const auto& M = model_;
  const int nq = M.nq, nr = M.nr;
  Eigen::VectorXd& f = scratch_f_;
  Eigen::VectorXd& G = scratch_G_;
  f.resize(M.m);
  forces_into(t, y, f);
  // G = psi^T f and Vf = V^T f over the units in contact only (a third of the candidates at the
  // default load): columns of the transposed shapes, contiguous in memory.
  G.setZero(nq);
  Eigen::VectorXd& Vf = scratch_Vf_;
  Vf.setZero(nr);
  for (int i = 0; i < M.m; ++i) {
    if (f(i) == 0.0) continue;
    G.noalias() += f(i) * M.psi_by_unit.col(i);
    if (nr > 0) Vf.noalias() += f(i) * M.V_by_unit.col(i);
  }
  const double Omega = plan_.speed(t) / M.tyre.config.outer_radius_m;
  const double dOmega = plan_.acceleration(t) / M.tyre.config.outer_radius_m;
  for (int j = 0; j < nq; ++j) {
    const double qj = y[j], vj = y[nq + j], w = M.omega[j], ze = M.zeta[j];
    ydot[j] = vj;
    double a = G(j) - 2 * ze * w * vj - w * w * qj;
    const int p = M.partner[j];
    if (p >= 0 && Omega != 0) {
      const double b = M.order[j] * Omega, al = M.order[j] * dOmega, s = M.pair_sign[j];
      a += s * 2 * b * y[nq + p] + b * b * qj + s * (2 * ze * w * b + al) * y[p];
    }
    ydot[nq + j] = a;
  }
  if (nr > 0) {
    for (int l = 0; l < nr; ++l)
      ydot[2 * nq + l] = (M.lambda(l) * Vf(l) - y[2 * nq + l]) / M.tau_residual_s;
  }
  const int Z = M.z_index();
  ydot[Z] = y[Z + 1];
  ydot[Z + 1] = (plan_.load(t) - f.sum()) / M.settings.hub_mass_kg;
  if (M.settings.relaxation) {
    const int E = M.e_index();
    const double adv = Omega / M.tyre.dtheta_rad;
    // de/dtheta by the second-order one-sided (upwind) difference from the front, e = 0
    // entering: (-3 e_i + 4 e_{i+1} - e_{i+2}) / (2 dtheta).
    const double a0 = kUpwind[0] * adv, a1 = kUpwind[1] * adv, a2 = kUpwind[2] * adv;
    for (int i = 0; i < M.m; ++i) {
      const double e = y[E + i], e1 = i + 1 < M.m ? y[E + i + 1] : 0.0,
                   e2 = i + 2 < M.m ? y[E + i + 2] : 0.0;
      ydot[E + i] = a0 * e + a1 * e1 + a2 * e2 + (f(i) - M.k_kv(i) * e) / M.c_kv(i);
    }
  }
}

int64_t TransientSystem::nnz() const {
  const auto& M = model_;
  const int64_t N = M.nq + M.nr + 1;  // coupled columns q, r, z
  const int64_t E = M.settings.relaxation ? M.m : 0;
  // Room for the tread couplings of a third of the candidates (about the patch at the default
  // load); the adapter grows the matrix if more units come into contact. A larger reserve
  // costs time: CVODE zeroes the whole allocation at every Jacobian evaluation.
  return N * N + 2 * N * (E / 3) + 4 * E + 4 * M.nq + 2 + N;
}

void TransientSystem::jacobian(double t, const double* y, solvers::CscMatrix& J) const {
  const auto& M = model_;
  const int nq = M.nq, nr = M.nr, m = M.m;
  const bool relax = M.settings.relaxation;
  const int Z = M.z_index(), E = M.e_index();
  const int n = size();
  // d f_i / d g_i on the units in contact.
  const Eigen::VectorXd f = forces(t, y);
  Eigen::VectorXd kd(m);
  for (int i = 0; i < m; ++i) kd(i) = f(i) > 0 ? M.k_contact(i) : 0.0;
  // While the patch is moving (units switched since the last Jacobian), units within
  // kJacobianEdgeMargin of the patch ends enter the Jacobian as if in contact: a unit that
  // touches between two Jacobian evaluations otherwise leaves Newton's matrix without its
  // (stiff) spring, the iteration diverges and forces a new Jacobian and KLU factorisation per
  // entering unit. A spring too many slows the contraction, badly so for long steps, hence not
  // when the patch is settled (a hold, steady rolling).
  const bool moving = switches_since_jacobian_ > 0;
  switches_since_jacobian_ = 0;
  if (moving) {
    int first = -1, last = -1;
    for (int i = 0; i < m; ++i)
      if (kd(i) > 0) last = i, first = first < 0 ? i : first;
    const int margin =
        std::max(1, static_cast<int>(std::lround(kJacobianEdgeMargin_m / M.tyre.unit_length_m)));
    if (first >= 0) {
      for (int i = std::max(0, first - margin); i < first; ++i) kd(i) = M.k_contact(i);
      for (int i = last + 1; i <= std::min(m - 1, last + margin); ++i) kd(i) = M.k_contact(i);
    }
  }
  // B = d g / d (q, r, z) = [-psi, -V, 1]; rows of W: d(v', r', w')/d f = [psi^T; lambda/tau V^T;
  // -1/m 1^T]. Dense block D = W diag(kd) B  ((nq + nr + 1) squared).
  const int N = nq + nr + 1;
  std::vector<int> active;
  for (int i = 0; i < m; ++i)
    if (kd(i) > 0) active.push_back(i);
  const int na = static_cast<int>(active.size());
  // Sparsity pattern of the tread couplings: every unit that has been in contact at a Jacobian
  // evaluation of this run stays in it (explicit zeros once out of contact). The pattern then
  // changes only when a unit touches for the first time, and KLU refactors with its previous
  // ordering and pivots instead of analysing anew at every contact switch.
  in_pattern_.resize(m, 0);
  for (int i : active) in_pattern_[i] = 1;
  std::vector<int> pattern;
  if (relax)
    for (int i = 0; i < m; ++i)
      if (in_pattern_[i]) pattern.push_back(i);
  Eigen::MatrixXd B(na, N), Wt(na, N);
  const double mh = M.settings.hub_mass_kg;
  for (int a = 0; a < na; ++a) {
    const int i = active[a];
    for (int j = 0; j < nq; ++j) B(a, j) = -M.psi(i, j), Wt(a, j) = M.psi(i, j);
    for (int l = 0; l < nr; ++l) {
      B(a, nq + l) = -M.V(i, l);
      Wt(a, nq + l) = M.lambda(l) / M.tau_residual_s * M.V(i, l);
    }
    B(a, N - 1) = 1.0;
    Wt(a, N - 1) = -1.0 / mh;
  }
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(N, N);
  // Coefficient-based product: Eigen's blocked GEMM would start OpenMP threads (the library is
  // built with OpenMP for sweeps) for a product this small, and the run is meant for one core.
  if (na > 0) D.noalias() = Wt.transpose().lazyProduct(kd(active).asDiagonal() * B);
  // Row of the coupled block k in state numbering.
  auto row_of = [&](int k) { return k < nq ? nq + k : (k < N - 1 ? 2 * nq + (k - nq) : Z + 1); };
  const double Omega = plan_.speed(t) / M.tyre.config.outer_radius_m;
  const double dOmega = plan_.acceleration(t) / M.tyre.config.outer_radius_m;
  const double adv = Omega / M.tyre.dtheta_rad;

  J.clear(n);
  auto push = [&](int64_t r, double v) {
    J.row.push_back(r);
    J.value.push_back(v);
  };
  // Coupled column (q_j, r_l or z): k is its index in the coupled block.
  auto coupled_column = [&](int k) {
    for (int kk = 0; kk < N; ++kk) {
      const int r = row_of(kk);
      double v = D(kk, k);
      if (k < nq) {  // modal terms of column q_j
        const int j = k;
        if (kk == j) {
          v -= M.omega[j] * M.omega[j];
          if (M.partner[j] >= 0) v += std::pow(M.order[j] * Omega, 2);
        } else if (kk < nq && M.partner[kk] == j && Omega != 0) {
          const double b = M.order[kk] * Omega, al = M.order[kk] * dOmega;
          v += M.pair_sign[kk] * (2 * M.zeta[kk] * M.omega[kk] * b + al);
        }
      } else if (k < N - 1 && kk == k) {
        v -= 1.0 / M.tau_residual_s;
      }
      // The rows are ordered v (nq.. 2nq), r (2nq..), w (Z+1) which is increasing in kk.
      push(r, v);
    }
    if (relax) {
      for (int i : pattern) {  // zero for units of the pattern out of contact
        double bi;
        if (k < nq)
          bi = -M.psi(i, k);
        else if (k < N - 1)
          bi = -M.V(i, k - nq);
        else
          bi = 1.0;
        push(E + i, kd(i) * bi / M.c_kv(i));
      }
    }
  };
  int64_t col = 0;
  // q columns.
  for (int j = 0; j < nq; ++j, ++col) {
    J.col_ptr[col] = static_cast<int64_t>(J.row.size());
    coupled_column(j);
  }
  // v columns: q_j' = v_j; v_j' has -2 zeta omega; partner rows have +-2b.
  for (int j = 0; j < nq; ++j, ++col) {
    J.col_ptr[col] = static_cast<int64_t>(J.row.size());
    push(j, 1.0);
    const int p = M.partner[j];
    // Row nq + p (partner's acceleration) and nq + j (own), in increasing order.
    std::vector<std::pair<int, double>> rows = {{nq + j, -2 * M.zeta[j] * M.omega[j]}};
    if (p >= 0) rows.push_back({nq + p, M.pair_sign[p] * 2 * M.order[p] * Omega});
    std::sort(rows.begin(), rows.end());
    for (auto& [r, v] : rows) push(r, v);
  }
  // r columns.
  for (int l = 0; l < nr; ++l, ++col) {
    J.col_ptr[col] = static_cast<int64_t>(J.row.size());
    coupled_column(nq + l);
  }
  // z column.
  J.col_ptr[col] = static_cast<int64_t>(J.row.size());
  coupled_column(N - 1);
  ++col;
  // w column: z' = w.
  J.col_ptr[col] = static_cast<int64_t>(J.row.size());
  push(Z, 1.0);
  ++col;
  // e columns.
  if (relax) {
    for (int i = 0; i < m; ++i, ++col) {
      J.col_ptr[col] = static_cast<int64_t>(J.row.size());
      const double dfde = -kd(i);
      if (in_pattern_[i]) {
        for (int j = 0; j < nq; ++j) push(nq + j, M.psi(i, j) * dfde);
        for (int l = 0; l < nr; ++l)
          push(2 * nq + l, M.lambda(l) / M.tau_residual_s * M.V(i, l) * dfde);
        push(Z + 1, -dfde / mh);
      }
      // e_{i-2}' and e_{i-1}' depend on e_i (upwind from the front).
      if (i > 1) push(E + i - 2, kUpwind[2] * adv);
      if (i > 0) push(E + i - 1, kUpwind[1] * adv);
      push(E + i, kUpwind[0] * adv + (dfde - M.k_kv(i)) / M.c_kv(i));
    }
  }
  J.col_ptr[col] = static_cast<int64_t>(J.row.size());
  MODALTYRE_CHECK(col == n, "Jacobian column count");
}

std::vector<double> TransientSystem::absolute_tolerances() const {
  const auto& M = model_;
  std::vector<double> a(size(), kDisplacementTolerance);
  for (int j = 0; j < M.nq; ++j) {
    const double s = std::max(M.psi.col(j).cwiseAbs().maxCoeff(), 1e-300);
    a[j] = kDisplacementTolerance / s;
    a[M.nq + j] = a[j] * M.omega[j];
  }
  // Hub velocity: displacement tolerance over a 10 ms time scale.
  a[M.z_index() + 1] = kDisplacementTolerance * 100;
  return a;
}

std::vector<double> TransientSystem::static_state(double load_N) const {
  const auto& M = model_;
  std::vector<double> y(size(), 0.0);
  if (load_N <= 0) return y;
  const FootprintResult fr = solve_footprint(M.tyre, LoadCase{load_N, 0});
  if (!fr.converged) throw ComputationError("static initial state: " + fr.message);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(M.m);
  std::size_t k = 0;
  for (int i = 0; i < M.m; ++i)
    if (fr.active[i]) f(i) = fr.units.at(k++).fz_N;
  const Eigen::VectorXd G = M.psi.transpose() * f;
  for (int j = 0; j < M.nq; ++j) y[j] = G(j) / (M.omega[j] * M.omega[j]);
  if (M.nr > 0) {
    const Eigen::VectorXd Vf = M.V.transpose() * f;
    for (int l = 0; l < M.nr; ++l) y[2 * M.nq + l] = M.lambda(l) * Vf(l);
  }
  y[M.z_index()] = fr.sinking_m;
  if (M.settings.relaxation)
    for (int i = 0; i < M.m; ++i) y[M.e_index() + i] = f(i) / M.k_kv(i);
  return y;
}

double TransientSystem::energy(double t, const double* y) const {
  const auto& M = model_;
  double e = 0;
  for (int j = 0; j < M.nq; ++j)
    e += 0.5 * (y[M.nq + j] * y[M.nq + j] + M.omega[j] * M.omega[j] * y[j] * y[j]);
  const double w = y[M.z_index() + 1];
  e += 0.5 * M.settings.hub_mass_kg * w * w;
  const Eigen::VectorXd f = forces(t, y);
  for (int i = 0; i < M.m; ++i) e += 0.5 * f(i) * f(i) / M.k_contact(i);
  return e;
}

// ---------------------------------------------------------------------------------------------
// Driver

namespace {

TransientSample observe(const TransientModel& M, const TransientSystem& sys,
                        const ScenarioPlan& plan, double t, const double* y) {
  TransientSample s;
  s.t_s = t;
  // Tip penetration once (one pass over psi and V); forces and the edge interpolation use it.
  std::vector<double> g(M.m);
  sys.roots(t, y, g.data());
  Eigen::VectorXd f(M.m);
  for (int i = 0; i < M.m; ++i) f(i) = g[i] > 0 ? M.k_contact(i) * g[i] : 0.0;
  const double z = y[M.z_index()];
  const double R0 = M.tyre.config.outer_radius_m;
  s.applied_load_N = plan.load(t);
  s.hub_displacement_m = z;
  s.speed_m_s = plan.speed(t);
  s.load_N = f.sum();
  double sink = -1e300, moment = 0, slope_force = 0;
  int first = -1, last = -1;
  for (int i = 0; i < M.m; ++i) {
    double slope = 0;
    const double h = sys.road(t, i, &slope);
    sink = std::max(sink, z + h - M.tyre.sag(i));
    if (f(i) > 0) {
      if (first < 0) first = i;
      last = i;
      ++s.contact_units;
      moment += f(i) * M.x_road(i);
      slope_force += f(i) * slope;
    }
  }
  s.sinking_m = sink;
  s.pressure_centre_m = s.load_N > 0 ? moment / s.load_N : 0;
  s.longitudinal_force_N = -moment / (R0 - z) - slope_force;
  if (first >= 0) {
    // Deformed positions of the end units (as footprint.cc): dynamic modes from the state,
    // residual orders and tread quasi-statically from the current forces.
    const Eigen::Map<const Eigen::VectorXd> q(y, M.nq);
    auto deformed_x = [&](int i) {
      double ur = M.phi_r.row(i).dot(q), ut = M.phi_t.row(i).dot(q);
      const double th = M.tyre.theta[i];
      if (M.nr > 0) {
        for (int j = first; j <= last; ++j) {
          if (f(j) <= 0) continue;
          const modal::Transfer2x2 h = M.residual_kernels.at(i - j);
          const double fr = f(j) * std::cos(M.tyre.theta[j]), ft = f(j) * std::sin(M.tyre.theta[j]);
          ur += h.r_from_r * fr + h.r_from_t * ft;
          ut += h.t_from_r * fr + h.t_from_t * ft;
        }
      }
      ur += f(i) * std::cos(th) / M.tyre.k_radial_N_m;
      ut += f(i) * std::sin(th) / M.tyre.k_tangential_N_m;
      return (R0 - ur) * std::sin(th) + ut * std::cos(th);
    };
    // Patch edges as in footprint.cc: the level function phi = f C_ii inside and -gap outside,
    // interpolated linearly to its zero between the end unit and its outside neighbour.
    auto edge = [&](int inside, int outside) {
      const double x_in = deformed_x(inside);
      if (outside < 0 || outside >= M.m) return x_in;
      const double phi_in = f(inside) * M.tyre.vertical_compliance(inside, inside);
      const double phi_out = g[outside];
      const double w = phi_in / (phi_in - phi_out);
      return x_in + w * (deformed_x(outside) - x_in);
    };
    s.contact_length_m = edge(last, last + 1) - edge(first, first - 1);
  }
  return s;
}

/// Decides whether an output sample can repeat the last computed one: every state component
/// moved by less than kReuseFraction of its error weight (rtol |y| + atol) since then. The
/// samples are otherwise an O(m (nq + nr)) evaluation each, which dominated long settled holds.
class SampleReuse {
 public:
  SampleReuse(double rtol, std::vector<double> atol, bool allowed)
      : rtol_(rtol), atol_(std::move(atol)), allowed_(allowed) {}
  void remember(const std::vector<double>& y) { last_ = y; }
  bool unchanged(const std::vector<double>& y) const {
    if (!allowed_ || last_.size() != y.size()) return false;
    for (std::size_t k = 0; k < y.size(); ++k) {
      const double w = rtol_ * std::abs(last_[k]) + atol_[k];
      if (std::abs(y[k] - last_[k]) > kReuseFraction * w) return false;
    }
    return true;
  }

 private:
  /// Far below the integrator's own local error (1 in the same weighted norm).
  static constexpr double kReuseFraction = 1e-3;
  double rtol_;
  std::vector<double> atol_;
  bool allowed_;
  std::vector<double> last_;
};

}  // namespace

TransientResult run_transient(const TransientModel& M, Scenario scenario,
                              TransientRunOptions* options) {
  const auto wall0 = std::chrono::steady_clock::now();
  const ScenarioPlan plan = plan_scenario(M, scenario);
  TransientSystem sys(M, plan);
  TransientResult res;
  res.scenario = scenario;

  solvers::OdeProblem prob;
  prob.size = sys.size();
  prob.rhs = [&sys](double t, const double* y, double* yd) {
    sys.rhs(t, y, yd);
    return 0;
  };
  prob.jacobian = [&sys](double t, const double* y, const double*, solvers::CscMatrix& J) {
    sys.jacobian(t, y, J);
    return 0;
  };
  prob.roots = M.m;
  prob.root_functions = [&sys](double t, const double* y, double* g) {
    sys.roots(t, y, g);
    return 0;
  };
  solvers::OdeOptions opt;
  opt.relative_tolerance = M.settings.relative_tolerance;
  opt.absolute_tolerance = sys.absolute_tolerances();
  // BDF2 at most: orders 3-5 are not A-stable, and the lightly damped carcass modes (eigenvalues
  // near the imaginary axis, up to omega_K) made CVODE's stability-limit detection hold the order
  // at 2-3 anyway, with many more steps (measured: 5500 steps/s of free vibration at order <= 5
  // with detection, 1700 at order <= 2; docs/transient.md section 6).
  opt.max_order = 2;
  opt.stability_limit_detection = false;
  opt.lsetup_frequency = 50;
  opt.delta_gamma_max = 0.6;
  // Contact switches perturb Newton's matrix by a few springs: allow more (cheap) iterations
  // before a convergence failure forces a new Jacobian and factorisation (measured: 6 halves
  // the factorisations of a 0.5 mm load ramp against CVODE's 3).
  opt.max_nonlinear_iterations = 6;

  std::vector<double> y = sys.static_state(plan.initial_load_N);
  solvers::CvodeKlu ode(prob, opt, 0.0, y, sys.nnz());
  ode.set_max_step(plan.step_limit(0.0));

  const double T = plan.duration_s, dt = M.settings.output_step_s;
  res.samples.push_back(observe(M, sys, plan, 0.0, y.data()));
  SampleReuse reuse(opt.relative_tolerance, opt.absolute_tolerance, !plan.cleat);
  reuse.remember(y);
  std::vector<double> breaks = plan.breakpoints;
  std::sort(breaks.begin(), breaks.end());
  std::size_t next_break = 0;
  long out_index = 1;
  double t_out = std::min(dt, T);
  bool failed = false, all_out = false;
  const bool restart_at_switches = options && options->restart_at_switches;
  int roots_in_place = 0;
  double last_root_t = -1;
  std::vector<double> y_out(sys.size());
  // The output samples up to t_reached, interpolated inside the step just taken (CVodeGetDky):
  // one internal step at a time, so that neither the output step bounds the step size nor does
  // every output time cost an evaluation of the m root functions (advance() to each output
  // time did: 60000 of them in a 120 s hold at 2 ms, a quarter of its run time).
  auto emit_until = [&](double t_reached) {
    while (!all_out && t_out <= t_reached * (1 + 1e-14)) {
      ode.interpolate(std::min(t_out, t_reached), y_out);
      if (reuse.unchanged(y_out)) {
        // The state moved less than kReuseFraction of the integration tolerance since the
        // last computed sample (a settled hold, steady rolling on a flat road): the
        // observables are the same to that accuracy; only the time and the scenario's own
        // functions advance.
        TransientSample smp = res.samples.back();
        smp.t_s = t_out;
        smp.applied_load_N = plan.load(t_out);
        smp.speed_m_s = plan.speed(t_out);
        res.samples.push_back(smp);
      } else {
        res.samples.push_back(observe(M, sys, plan, t_out, y_out.data()));
        reuse.remember(y_out);
      }
      if (options && options->progress && !options->progress(t_out, T)) {
        res.message = "cancelled";
        return false;
      }
      if (t_out >= T) {
        all_out = true;
        break;
      }
      ++out_index;
      t_out = std::min(out_index * dt, T);
      if (T - t_out < 1e-9 * T) t_out = T;
    }
    return true;
  };
  while (!all_out) {
    while (next_break < breaks.size() && breaks[next_break] <= ode.time()) ++next_break;
    // Steps run up to the next breakpoint (a kink of F(t) or V(t)) or the end.
    const double stop = next_break < breaks.size() ? breaks[next_break] : T;
    const solvers::OdeStatus st = ode.step(stop);
    if (!st.ok()) {
      std::ostringstream msg;
      msg << "integrator failed at t = " << st.t << " s: " << st.message;
      res.message = msg.str();
      failed = true;
      break;
    }
    if (!emit_until(st.t)) {
      failed = true;
      break;
    }
    if (st.outcome == solvers::OdeOutcome::root) {
      // Chattering guard: root returns that no longer advance the time would loop for ever.
      roots_in_place = std::abs(st.t - last_root_t) <= kZenoWindow_s ? roots_in_place + 1 : 0;
      last_root_t = st.t;
      if (roots_in_place >= kZenoRootReturns) {
        std::ostringstream msg;
        msg << "contact switches chatter at t = " << st.t << " s (" << kZenoRootReturns
            << " root returns without the time advancing): a tread tip hovers at the road";
        res.message = msg.str();
        failed = true;
        break;
      }
      sys.contact_switched();
      // A unit's tip touched or left the road: f_i = k max(0, g_i) has a kink there, the
      // right-hand side stays continuous. The located root is counted and the integration
      // continues; BDF's error test shortens the step over the kink (a restart would also throw
      // away the history for a kink of one unit among many). Optionally restart as before.
      ++res.contact_events;
      if (restart_at_switches) ode.reinit(st.t, ode.state());
      continue;
    }
    if (next_break < breaks.size() && st.t >= breaks[next_break]) {
      ode.reinit(st.t, ode.state());
      ode.set_max_step(plan.step_limit(st.t));
      ++next_break;
    }
  }
  res.simulated_s = ode.time();
  res.stats = ode.stats();
  if (options && options->keep_final_state) options->final_state = ode.state();
  res.status = failed ? TransientStatus::failed : TransientStatus::completed;
  if (!failed) {
    std::ostringstream msg;
    msg << "completed: " << res.stats.steps << " steps, " << res.contact_events
        << " contact switches";
    res.message = msg.str();
  }
  // Rolling resistance: mean of -F_x over the last 10 % of the run.
  const double t_from = 0.9 * res.simulated_s;
  double sum = 0;
  int cnt = 0;
  for (const auto& s : res.samples)
    if (s.t_s >= t_from) sum += -s.longitudinal_force_N, ++cnt;
  res.rolling_resistance_N = cnt ? sum / cnt : 0;
  res.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace modaltyre::contact
