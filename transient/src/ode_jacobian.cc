// The sparse Jacobian of TransientSystem for CVODE's Newton iteration (KLU or the structured
// solver of contact_newton.h): its pattern (nnz), the contact stiffness of the units that enter
// it, and its columns. The equations it differentiates are in ode_system.cc (rhs) and in
// docs/transient.md sections 1-2.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "modaltyre/core/errors.h"
#include "modaltyre/transient/ode_system.h"
#include "modaltyre/transient/soil_contact.h"

namespace modaltyre::transient {
namespace {

/// Length beyond each end of the contact patch whose units enter the Jacobian as if in contact
/// (see TransientSystem::jacobian); 4 units at the default 0.5 mm mesh (measured best of 0-10).
constexpr double kJacobianEdgeMargin_m = 2e-3;

}  // namespace

int64_t TransientSystem::nnz() const {
  const auto& M = model_;
  const int64_t N = M.nq + M.nr + 1;  // coupled columns q, r, z
  const int64_t E = ne_;
  // Room for the tread couplings of a third of the candidates (about the patch at the default
  // load); the adapter grows the matrix if more units come into contact. A larger reserve
  // costs time: CVODE zeroes the whole allocation at every Jacobian evaluation.
  return N * N + 2 * N * (E / 3) + 4 * E + 4 * M.nq + 2 + N;
}

void TransientSystem::jacobian_stiffness(double t, const double* y, Eigen::VectorXd& kd) const {
  const auto& M = model_;
  const int u0 = units_.lo, u1 = units_.hi;
  forces_into(t, y, kd);  // 0 outside units_
  for (int i = u0; i <= u1; ++i)
    kd(i) = kd(i) > 0 ? (soil_ ? soil_->stiffness(i) : M.k_contact(i)) : 0.0;
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
    for (int i = u0; i <= u1; ++i)
      if (kd(i) > 0) last = i, first = first < 0 ? i : first;
    const int margin =
        std::max(1, static_cast<int>(std::lround(kJacobianEdgeMargin_m / M.tyre.unit_length_m)));
    if (first >= 0) {
      for (int i = std::max(u0, first - margin); i < first; ++i) kd(i) = M.k_contact(i);
      for (int i = last + 1; i <= std::min(u1, last + margin); ++i) kd(i) = M.k_contact(i);
    }
  }
}

void TransientSystem::jacobian(double t, const double* y, solvers::CscMatrix& J) const {
  const auto& M = model_;
  const int nq = M.nq, nr = M.nr, m = M.m;
  const bool relax = M.settings.relaxation;
  const int Z = M.z_index(), E = M.e_index();
  const int n = size();
  Eigen::VectorXd kd;
  jacobian_stiffness(t, y, kd);
  // B = d g / d (q, r, z) = [-psi, -V, 1]; rows of W: d(v', r', w')/d f = [psi^T; lambda/tau V^T;
  // -1/m 1^T]. Dense block D = W diag(kd) B  ((nq + nr + 1) squared).
  const int N = nq + nr + 1;
  const int u0 = units_.lo, u1 = units_.hi;
  std::vector<int> active;
  for (int i = u0; i <= u1; ++i)
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
    for (int i = u0; i <= u1; ++i)
      if (in_pattern_[i]) pattern.push_back(i);
  Eigen::MatrixXd B(na, N), Wt(na, N);
  const double mh = M.settings.hub_mass_kg;
  // A prescribed hub (scenario.h): z is no state of the contact and the forces do not act on it.
  const double hub = plan_.hub_free() ? 1.0 : 0.0;
  for (int a = 0; a < na; ++a) {
    const int i = active[a];
    for (int j = 0; j < nq; ++j) B(a, j) = -M.psi(i, j), Wt(a, j) = M.psi(i, j);
    for (int l = 0; l < nr; ++l) {
      B(a, nq + l) = -M.V(i, l);
      Wt(a, nq + l) = M.lambda(l) / M.tau_residual_s * M.V(i, l);
    }
    B(a, N - 1) = hub;
    Wt(a, N - 1) = -hub / mh;
  }
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(N, N);
  // Coefficient-based product: Eigen's blocked GEMM would start OpenMP threads (the library is
  // built with OpenMP for sweeps) for a product this small, and the run is meant for one core.
  if (na > 0) D.noalias() = Wt.transpose().lazyProduct(kd(active).asDiagonal() * B);
  // Row of the coupled block k in state numbering.
  auto row_of = [&](int k) { return k < nq ? nq + k : (k < N - 1 ? 2 * nq + (k - nq) : Z + 1); };
  const double Omega = spin(t), dOmega = spin_rate(t);
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
        if (kk == j)
          v += modal_row(M, j, Omega, dOmega).dq;
        else if (kk < nq && M.partner[kk] == j)
          v += modal_row(M, kk, Omega, dOmega).dq_p;
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
          bi = hub;
        push(E + (i - u0), kd(i) * bi / M.c_kv(i));
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
    std::vector<std::pair<int, double>> rows = {{nq + j, modal_row(M, j, Omega, dOmega).dv}};
    if (p >= 0) rows.push_back({nq + p, modal_row(M, p, Omega, dOmega).dv_p});
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
  // w column: z' = w (0 under a prescribed hub).
  J.col_ptr[col] = static_cast<int64_t>(J.row.size());
  push(Z, hub);
  ++col;
  // e columns (units_ only; state E + k is unit u0 + k).
  if (relax) {
    for (int i = u0; i <= u1; ++i, ++col) {
      const int k = i - u0;
      J.col_ptr[col] = static_cast<int64_t>(J.row.size());
      const double dfde = -kd(i);
      if (in_pattern_[i]) {
        for (int j = 0; j < nq; ++j) push(nq + j, M.psi(i, j) * dfde);
        for (int l = 0; l < nr; ++l)
          push(2 * nq + l, M.lambda(l) / M.tau_residual_s * M.V(i, l) * dfde);
        push(Z + 1, -hub * dfde / mh);
      }
      // e_{i-2}' and e_{i-1}' depend on e_i (upwind from the front).
      if (k > 1) push(E + k - 2, kUpwind[2] * adv);
      if (k > 0) push(E + k - 1, kUpwind[1] * adv);
      push(E + k, kUpwind[0] * adv + (dfde - M.k_kv(i)) / M.c_kv(i));
    }
  }
  J.col_ptr[col] = static_cast<int64_t>(J.row.size());
  MODALTYRE_CHECK(col == n, "Jacobian column count");
}

}  // namespace modaltyre::transient
