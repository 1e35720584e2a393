// The preconditioner of the coupled cell solve (CellCompliance with a CoupledTread,
// patch3d_operators.h). Jacobi leaves the layer's short waves badly conditioned: their
// compliance is 1 / (k (1 + a_x lambda_x + a_y lambda_y)), ~1/150 of a long wave's at l = 11 mm
// on 2 mm sections, and the conjugate gradients took ~70 iterations per inner solve.
//
// On a rectangle of cells (sections q0..q1, columns j0..j1) of a layer free at its side edges
// the operator is block-diagonal in the layer's cosine modes across the road (patch3d_tread.cc):
// the layer is cos_i cos_k g_m(|i - k|) in mode m, each cell's own tangential tread t_i is the
// same in every mode, and the carcass moves a section's cells together, so it acts on mode 0
// alone, as w C_carcass (phi_0 = 1 / sqrt(w), w columns). Each mode is then a small dense SPD
// block over the sections, factored once per contact set. The preconditioner is that inverse on
// the rectangle the set spans, restricted to the set: R is spread over the rectangle (zero
// elsewhere), solved mode by mode and gathered. On the whole tread (j0..j1 every column) it is
// the operator's exact inverse there (test); a narrower set gets the layer cut at its outermost
// columns, free there, so that the set fills the rectangle but for the patch's rounded ends (the
// whole tread's rectangle would keep the unloaded shoulders: 138 against 116 iterations on the
// test's patch at l = 11.4 mm, 238 against 114 at 50 mm). With a lateral belt, G's
// mode-diagonal part phi_m^T G phi_m is kept (G couples the modes a little).
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
  CoupledCellPreconditioner(const std::vector<int>& S, int columns, int first_section, int sections,
                            int first_column, CoupledTread layer,
                            std::vector<Eigen::LLT<Eigen::MatrixXd>> factors)
      : S_(S),
        n_(columns),
        q0_(first_section),
        L_(sections),
        j0_(first_column),
        layer_(std::move(layer)),
        phi_t_(layer_.modes().transpose()),
        factors_(std::move(factors)) {}

  void apply(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) const override {
    const int w = layer_.columns();
    Z.resize(R.rows(), R.cols());
    Eigen::MatrixXd cells(L_, w), coef, back;
    for (Eigen::Index c = 0; c < R.cols(); ++c) {
      cells.setZero();
      for (std::size_t a = 0; a < S_.size(); ++a)
        cells(S_[a] / n_ - q0_, S_[a] % n_ - j0_) = R(a, c);
      modal_product(cells, layer_.modes(), coef);
      for (int m = 0; m < w; ++m) factors_[m].solveInPlace(coef.col(m));
      modal_product(coef, phi_t_, back);
      for (std::size_t a = 0; a < S_.size(); ++a)
        Z(a, c) = back(S_[a] / n_ - q0_, S_[a] % n_ - j0_);
    }
  }

 private:
  std::vector<int> S_;
  int n_, q0_, L_, j0_;
  CoupledTread layer_;  ///< the layer on the set's columns
  Eigen::MatrixXd phi_t_;
  std::vector<Eigen::LLT<Eigen::MatrixXd>> factors_;  ///< one per mode, sections q0..q1
};

}  // namespace

std::unique_ptr<solvers::SetPreconditioner> CellCompliance::preconditioner(
    const std::vector<int>& S) const {
  if (!tread_ || S.empty()) return nullptr;
  const int n = columns_;
  const int q0 = S.front() / n, L = S.back() / n - q0 + 1;
  int j0 = n, j1 = -1;
  for (int a : S) j0 = std::min(j0, a % n), j1 = std::max(j1, a % n);
  const int w = j1 - j0 + 1;
  if (double(L) * L * w > kMaxFactorEntries) return nullptr;
  // The layer cut at the set's outermost columns, free there: the set fills its rectangle but
  // for the patch's rounded ends (the full tread's rectangle leaves the unloaded shoulders in it).
  CoupledTread layer = w == n ? *tread_ : tread_->narrowed(w);
  const Eigen::MatrixXd& phi = layer.modes();
  std::vector<Eigen::LLT<Eigen::MatrixXd>> factors(w);
  Eigen::MatrixXd M(L, L), carcass(L, L);
  for (int i = 0; i < L; ++i)
    for (int k = 0; k < L; ++k) carcass(i, k) = carcass_.entry(q0 + i, q0 + k);
  for (int m = 0; m < w; ++m) {
    const double belt = G_ ? phi.col(m).dot(G_->block(j0, j0, w, w) * phi.col(m)) : 0.0;
    for (int i = 0; i < L; ++i) {
      for (int k = 0; k < L; ++k) {
        M(i, k) = layer.cos_theta(q0 + i) * layer.cos_theta(q0 + k) * layer.lag(m, std::abs(i - k));
      }
      M(i, i) += t_[q0 + i] + belt;
    }
    if (m == 0) M += w * carcass;
    factors[m].compute(M);
    if (factors[m].info() != Eigen::Success) return nullptr;
  }
  return std::make_unique<CoupledCellPreconditioner>(S, n, q0, L, j0, std::move(layer),
                                                     std::move(factors));
}

}  // namespace modaltyre::contact::detail
