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
//
// Only mode 0 carries the (dense) carcass and is factored densely. A mode m >= 1 is
// M = D G D + diag(e), D = diag(cos theta), G(i, k) = g0 rho^|i - k| (the layer's geometric lags),
// e_i = t_i + belt_m. G is a Kac-Murdock-Szego matrix, whose inverse K is tridiagonal:
// K = tridiag(-rho; 1, 1 + rho^2, ..., 1 + rho^2, 1) / (g0 (1 - rho^2)). With E = diag(e / cos^2),
// M z = r is (K^-1 + E) y = r / cos with y = D z, and with y = K v, (I + E K) v = r / cos:
// a tridiagonal system, strictly diagonally dominant by rows (K is, E >= 0), solved by the
// Thomas recursion without pivoting. O(L) per mode instead of a dense L x L factor and its two
// triangular solves (which took half the coupled footprint's instructions).
#include <Eigen/Cholesky>
#include <algorithm>
#include <memory>

#include "patch3d_operators.h"

namespace modaltyre::contact::detail {
namespace {

// At most this many doubles in mode 0's factor (32 MB); beyond, Jacobi.
constexpr double kMaxFactorEntries = 4e6;

/// A mode m >= 1 of the preconditioner on L sections (see the file comment): K and the Thomas
/// factors of I + E K.
class TridiagonalMode {
 public:
  TridiagonalMode(double g0, double rho, const std::vector<double>& cos,
                  const std::vector<double>& e)
      : cos_(cos) {
    const int L = static_cast<int>(cos.size());
    const double c = 1 / (g0 * (1 - rho) * (1 + rho));
    diag_.assign(L, L == 1 ? 1 / g0 : c * (1 + rho * rho));
    if (L > 1) diag_.front() = diag_.back() = c;
    off_ = -c * rho;
    sub_.resize(L), inv_pivot_.resize(L), sup_.resize(L);
    for (int i = 0; i < L; ++i) {
      const double E = e[i] / (cos[i] * cos[i]);
      sub_[i] = i > 0 ? E * off_ : 0.0;
      const double pivot = 1 + E * diag_[i] - (i > 0 ? sub_[i] * sup_[i - 1] : 0.0);
      inv_pivot_[i] = 1 / pivot;
      sup_[i] = i + 1 < L ? E * off_ * inv_pivot_[i] : 0.0;
    }
  }

  /// r := M^-1 r (length L), in place: v over r, then y = K v (each v_i read before it is
  /// overwritten) and z = y / cos.
  void solve(double* r) const {
    const int L = static_cast<int>(cos_.size());
    for (int i = 0; i < L; ++i)
      r[i] = (r[i] / cos_[i] - (i > 0 ? sub_[i] * r[i - 1] : 0.0)) * inv_pivot_[i];
    for (int i = L - 2; i >= 0; --i) r[i] -= sup_[i] * r[i + 1];
    double previous = 0;
    for (int i = 0; i < L; ++i) {
      const double v = r[i], next = i + 1 < L ? r[i + 1] : 0.0;
      r[i] = (diag_[i] * v + off_ * (previous + next)) / cos_[i];
      previous = v;
    }
  }

 private:
  std::vector<double> cos_, diag_;
  double off_ = 0;
  std::vector<double> sub_, inv_pivot_, sup_;
};

class CoupledCellPreconditioner final : public solvers::SetPreconditioner {
 public:
  CoupledCellPreconditioner(const std::vector<int>& S, int columns, int first_section, int sections,
                            int first_column, CoupledTread layer, Eigen::LLT<Eigen::MatrixXd> mode0,
                            std::vector<TridiagonalMode> modes)
      : L_(sections), layer_(std::move(layer)), mode0_(std::move(mode0)), modes_(std::move(modes)) {
    for (int a : S) {
      row_.push_back(a / columns - first_section);
      col_.push_back(a % columns - first_column);
    }
  }

  void apply(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) const override {
    const int w = layer_.columns();
    const Eigen::Index cols = R.cols();
    Z.resize(R.rows(), cols);
    // Every right-hand side at once, stacked along the rows (c * L + section).
    Eigen::MatrixXd cells = Eigen::MatrixXd::Zero(cols * L_, w), coef, back;
    for (Eigen::Index c = 0; c < cols; ++c)
      for (std::size_t a = 0; a < row_.size(); ++a) cells(c * L_ + row_[a], col_[a]) = R(a, c);
    layer_.transform().forward(cells, coef);
    for (Eigen::Index c = 0; c < cols; ++c) {
      auto mode0 = coef.col(0).segment(c * L_, L_);
      mode0_.solveInPlace(mode0);
      for (int m = 1; m < w; ++m) modes_[m - 1].solve(&coef(c * L_, m));
    }
    layer_.transform().backward(coef, back);
    for (Eigen::Index c = 0; c < cols; ++c)
      for (std::size_t a = 0; a < row_.size(); ++a) Z(a, c) = back(c * L_ + row_[a], col_[a]);
  }

 private:
  std::vector<int> row_, col_;  ///< each set cell's section and column in the rectangle
  int L_;
  CoupledTread layer_;                  ///< the layer on the set's columns
  Eigen::LLT<Eigen::MatrixXd> mode0_;   ///< mode 0 (with the carcass), sections q0..q1
  std::vector<TridiagonalMode> modes_;  ///< modes 1 .. w - 1
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
  if (double(L) * L > kMaxFactorEntries) return nullptr;
  // The layer cut at the set's outermost columns, free there: the set fills its rectangle but
  // for the patch's rounded ends (the full tread's rectangle leaves the unloaded shoulders in it).
  CoupledTread layer = w == n ? *tread_ : tread_->narrowed(w);
  const Eigen::MatrixXd& phi = layer.modes();
  std::vector<double> cos(L), e(L);
  for (int i = 0; i < L; ++i) {
    cos[i] = layer.cos_theta(q0 + i);
    if (!(cos[i] > 0)) return nullptr;  // a section beyond a quarter turn: never in a patch
  }
  const auto belt = [&](int m) {
    return G_ ? phi.col(m).dot(G_->block(j0, j0, w, w) * phi.col(m)) : 0.0;
  };
  Eigen::MatrixXd M(L, L);
  const double belt0 = belt(0);
  for (int i = 0; i < L; ++i) {
    for (int k = 0; k < L; ++k) {
      M(i, k) =
          cos[i] * cos[k] * layer.lag(0, std::abs(i - k)) + w * carcass_.entry(q0 + i, q0 + k);
    }
    M(i, i) += t_[q0 + i] + belt0;
  }
  Eigen::LLT<Eigen::MatrixXd> mode0(M);
  if (mode0.info() != Eigen::Success) return nullptr;
  std::vector<TridiagonalMode> modes;
  modes.reserve(w - 1);
  for (int m = 1; m < w; ++m) {
    const double bm = belt(m);
    for (int i = 0; i < L; ++i) e[i] = t_[q0 + i] + bm;
    modes.emplace_back(layer.lag(m, 0), layer.ratio(m), cos, e);
  }
  return std::make_unique<CoupledCellPreconditioner>(S, n, q0, L, j0, std::move(layer),
                                                     std::move(mode0), std::move(modes));
}

}  // namespace modaltyre::contact::detail
