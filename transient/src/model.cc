#include "modaltyre/transient/model.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/leading_eigenpairs.h"

namespace modaltyre::transient {
namespace {

using contact::FootprintResult;
using contact::LoadCase;

using cd = std::complex<double>;

/// Eigenvalues of the residual compliance below this fraction of the largest are dropped: their
/// displacements are at the rounding level of the sum.
constexpr double kResidualEigenCutoff = 1e-13;
/// Minimum damping ratio used for the relaxation time of the quasi-static residual orders.
constexpr double kResidualMinDamping = 0.01;

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

/// [psi V] = T [Cq Cr] (model.h): thin SVD U S W^T, T = U S and [Cq Cr] = W^T on the singular
/// values above settings.contact_basis_cutoff of the largest: ||[psi V] - T [Cq Cr]||_2 is the
/// first dropped one, <= cutoff s_max. (Scaling every shape to unit norm first was tried: it
/// reproduces the small shapes better relative to their own norm, but the forces moved by the
/// same ~1e-8 either way, and the finite-difference check of the Jacobian hit its rounding
/// floor: 1.04e-5 against its 1e-5, 4.7e-6 unscaled.)
void build_contact_basis(TransientModel& M) {
  Eigen::MatrixXd B(M.m, M.nq + M.nr);
  B << M.psi, M.V;
  M.rank = 0;
  M.T.resize(M.m, 0);
  M.Cq.resize(0, M.nq);
  M.Cr.resize(0, M.nr);
  if (B.cols() > 0) {
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(B, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd& s = svd.singularValues();
    const double cutoff = M.settings.contact_basis_cutoff;
    while (M.rank < s.size() && s(M.rank) > cutoff * s(0)) ++M.rank;
    M.T = svd.matrixU().leftCols(M.rank) * s.head(M.rank).asDiagonal();
    const Eigen::MatrixXd C = svd.matrixV().leftCols(M.rank).transpose();
    M.Cq = C.leftCols(M.nq);
    M.Cr = C.rightCols(M.nr);
  }
  M.T_by_unit = M.T.transpose();
}

}  // namespace

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
  build_contact_basis(M);
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
  const FootprintResult exact =
      contact::solve_patch(model.tyre, contact::static_operator(model.tyre, 0.0), load);
  const FootprintResult approx =
      contact::solve_patch(truncated, contact::static_operator(truncated, 0.0), load);
  if (!exact.ok() || !approx.ok())
    throw ComputationError("truncation_error: footprint did not converge");
  e.sinking_rel = approx.sinking_m / exact.sinking_m - 1.0;
  e.length_rel = approx.contact_length_m / exact.contact_length_m - 1.0;
  return e;
}

StaticCarcass static_carcass(const TransientModel& M, const Eigen::VectorXd& f) {
  StaticCarcass s;
  s.q = M.psi.transpose() * f;
  for (int j = 0; j < M.nq; ++j) s.q(j) /= M.omega[j] * M.omega[j];
  s.r = Eigen::VectorXd::Zero(M.nr);
  if (M.nr > 0) s.r = (M.lambda.array() * (M.V.transpose() * f).array()).matrix();
  return s;
}

}  // namespace modaltyre::transient
