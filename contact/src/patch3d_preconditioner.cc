// The preconditioner of the coupled cell solve (CellCompliance with a CoupledTread,
// patch3d_operators.h). Jacobi leaves the layer's short waves badly conditioned: their
// compliance is 1 / (k (1 + a_x lambda_x + a_y lambda_y)), ~1/150 of a long wave's at l = 11 mm
// on 2 mm sections, and the conjugate gradients took ~70 iterations per inner solve.
//
// On the rectangle of cells a contact set spans (sections q0..q1, every column) the operator is
// block-diagonal in the tread's modes across the road (patch3d_tread.cc): the layer is
// cos_i cos_k g_m(|i - k|) in mode m, each cell's own tangential tread t_i is the same in every
// mode, and the carcass moves a section's cells together, so it acts on mode 0 alone, as
// n C_carcass (phi_0 = 1 / sqrt(n)). Each mode is then a small dense SPD block over the
// sections, factored once per contact set. The preconditioner is that exact inverse on the
// rectangle, restricted to the set: R is spread over the rectangle (zero elsewhere), solved mode
// by mode, and gathered. Where the set fills the rectangle it is the operator's inverse; its
// error sits on the cells of the rectangle outside the set (the patch's rounded ends). With a
// lateral belt, G's mode-diagonal part phi_m^T G phi_m is kept (G couples the modes a little).
#include <Eigen/Cholesky>
#include <algorithm>
#include <memory>

#include "patch3d_operators.h"

namespace modaltyre::contact::detail {
namespace {

// At most this many doubles in the modes' factors (32 MB); beyond, Jacobi.
constexpr double kMaxFactorEntries = 4e6;

class CoupledCellPreconditioner final : public solvers::SetPreconditioner {
 public:
  CoupledCellPreconditioner(const std::vector<int>& S, int first_section, int sections,
                            const CoupledTread& tread,
                            std::vector<Eigen::LLT<Eigen::MatrixXd>> factors)
      : S_(S),
        q0_(first_section),
        L_(sections),
        tread_(tread),
        phi_t_(tread.modes().transpose()),
        factors_(std::move(factors)) {}

  void apply(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) const override {
    const int n = tread_.columns();
    const Eigen::MatrixXd& phi = tread_.modes();
    Z.resize(R.rows(), R.cols());
    Eigen::MatrixXd cells(L_, n), coef(L_, n), back(L_, n);
    for (Eigen::Index c = 0; c < R.cols(); ++c) {
      cells.setZero();
      for (std::size_t a = 0; a < S_.size(); ++a) cells(S_[a] / n - q0_, S_[a] % n) = R(a, c);
      modal_product(cells, phi, coef);
      for (int m = 0; m < n; ++m) factors_[m].solveInPlace(coef.col(m));
      modal_product(coef, phi_t_, back);
      for (std::size_t a = 0; a < S_.size(); ++a) Z(a, c) = back(S_[a] / n - q0_, S_[a] % n);
    }
  }

 private:
  std::vector<int> S_;
  int q0_, L_;
  const CoupledTread& tread_;
  Eigen::MatrixXd phi_t_;
  std::vector<Eigen::LLT<Eigen::MatrixXd>> factors_;  ///< one per mode, sections q0..q1
};

}  // namespace

std::unique_ptr<solvers::SetPreconditioner> CellCompliance::preconditioner(
    const std::vector<int>& S) const {
  if (!tread_ || S.empty()) return nullptr;
  const int n = columns_;
  const int q0 = S.front() / n, L = S.back() / n - q0 + 1;
  if (double(L) * L * n > kMaxFactorEntries) return nullptr;
  const Eigen::MatrixXd& phi = tread_->modes();
  std::vector<Eigen::LLT<Eigen::MatrixXd>> factors(n);
  Eigen::MatrixXd M(L, L), carcass(L, L);
  for (int i = 0; i < L; ++i)
    for (int k = 0; k < L; ++k) carcass(i, k) = carcass_.entry(q0 + i, q0 + k);
  for (int m = 0; m < n; ++m) {
    const double belt = G_ ? phi.col(m).dot(*G_ * phi.col(m)) : 0.0;
    for (int i = 0; i < L; ++i) {
      for (int k = 0; k < L; ++k) {
        M(i, k) =
            tread_->cos_theta(q0 + i) * tread_->cos_theta(q0 + k) * tread_->lag(m, std::abs(i - k));
      }
      M(i, i) += t_[q0 + i] + belt;
    }
    if (m == 0) M += n * carcass;
    factors[m].compute(M);
    if (factors[m].info() != Eigen::Success) return nullptr;
  }
  return std::make_unique<CoupledCellPreconditioner>(S, q0, L, *tread_, std::move(factors));
}

}  // namespace modaltyre::contact::detail
