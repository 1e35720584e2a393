#pragma once
// Compliance operators of the 3D patch (patch3d.h), internal to the contact library.
#include <Eigen/Dense>
#include <vector>

#include "modaltyre/solvers/compliance_operator.h"
#include "patch3d_cosine.h"

namespace modaltyre::contact::detail {

/// C + diag(d): a section compliance (the carcass operator, not owned) with a local compliance
/// added on the diagonal (the pattern's tread, t_i / n_i).
class DiagonalShifted final : public solvers::ComplianceOperator {
 public:
  DiagonalShifted(const solvers::ComplianceOperator& base, std::vector<double> diagonal)
      : base_(base), d_(std::move(diagonal)) {}
  int size() const override { return base_.size(); }
  double entry(int i, int j) const override { return base_.entry(i, j) + (i == j ? d_[i] : 0.0); }
  void gather(const std::vector<int>& S, Eigen::MatrixXd& A) const override;
  void apply(int r0, int nr, int c0, int nc, const Eigen::Ref<const Eigen::MatrixXd>& X,
             Eigen::Ref<Eigen::MatrixXd> Y) const override;

 private:
  const solvers::ComplianceOperator& base_;
  std::vector<double> d_;
};

/// The radial compliance of the shear-coupled tread between cells (patch3d_tread.cc):
/// cos theta_i cos theta_k T((i, j), (k, l)), T the Pasternak layer's Green's function on the
/// cell grid (unbounded along the road, free edges across it).
class CoupledTread {
 public:
  CoupledTread(double k_cell_N_m, double coupling_m, double ds_m, double dy_m, int sections,
               int columns, std::vector<double> cos_theta);
  double entry(int a, int b) const;
  /// T's lag-0 entry of column j (without the cos^2 theta weight): a cell's compliance to its
  /// own force.
  double own(int j) const { return own_[j]; }
  int columns() const { return columns_; }
  /// phi_m(j) at (j, m): the layer's modes across the tread (orthonormal).
  const Eigen::MatrixXd& modes() const { return modes_.dense(); }
  /// The same modes as a transform of blocks of cells (patch3d_cosine.h).
  const CosineModes& transform() const { return modes_; }
  /// g_m at lag d along the road (0 beyond the lags kept), and section i's cos theta.
  double lag(int m, int d) const {
    return d < static_cast<int>(lags_[m].size()) ? lags_[m][d] : 0.0;
  }
  double cos_theta(int i) const { return cos_[i]; }
  /// rho_m = g_m(1) / g_m(0): g_m(d) = g_m(0) rho_m^|d| (the lags' geometric law).
  double ratio(int m) const { return ratio_[m]; }
  /// The same layer on the columns j0 .. j0 + n - 1 alone, free at their edges.
  CoupledTread narrowed(int n) const {
    return CoupledTread(k_cell_, coupling_, ds_, dy_, sections_, n, cos_);
  }
  /// Y += (this operator)(r0 .. r0+nr-1, c0 .. c0+nc-1) X.
  void add_product(int r0, int nr, int c0, int nc, const Eigen::Ref<const Eigen::MatrixXd>& X,
                   Eigen::Ref<Eigen::MatrixXd> Y) const;

 private:
  double k_cell_, coupling_, ds_, dy_;
  int sections_, columns_;
  std::vector<double> cos_;
  CosineModes modes_;                      ///< phi_m(j), orthonormal
  std::vector<std::vector<double>> lags_;  ///< g_m at lags 0, 1, ...
  std::vector<double> ratio_;              ///< rho_m = g_m(1) / g_m(0)
  std::vector<double> own_;
};

/// The cell compliance: cells indexed i * columns + j, the carcass between the sections'
/// resultants, each cell's own tread t_i and, if given, the section's lateral belt compliance G
/// and the shear-coupled tread (then t_i is the tread's tangential part alone),
///   C_(ij)(kl) = C_carcass(i, k) + [i = k] (t_i [j = l] + G(j, l)) + T_coupled((ij), (kl)).
class CellCompliance final : public solvers::ComplianceOperator {
 public:
  CellCompliance(const solvers::ComplianceOperator& carcass, int columns, std::vector<double> t,
                 const Eigen::MatrixXd* lateral = nullptr, const CoupledTread* tread = nullptr)
      : carcass_(carcass), columns_(columns), t_(std::move(t)), G_(lateral), tread_(tread) {}
  int size() const override { return carcass_.size() * columns_; }
  double entry(int a, int b) const override {
    const int i = a / columns_, k = b / columns_;
    double c = carcass_.entry(i, k) + (a == b ? t_[i] : 0.0);
    if (G_ && i == k) c += (*G_)(a % columns_, b % columns_);
    if (tread_) c += tread_->entry(a, b);
    return c;
  }
  void apply(int r0, int nr, int c0, int nc, const Eigen::Ref<const Eigen::MatrixXd>& X,
             Eigen::Ref<Eigen::MatrixXd> Y) const override;
  /// With the coupled tread: the inverse of this operator on the rectangle of cells the set
  /// spans (the layer free at its side columns), restricted to the set
  /// (patch3d_preconditioner.cc); else null (Jacobi).
  std::unique_ptr<solvers::SetPreconditioner> preconditioner(
      const std::vector<int>& S) const override;

 private:
  const solvers::ComplianceOperator& carcass_;
  int columns_;
  std::vector<double> t_;
  const Eigen::MatrixXd* G_;   ///< not owned; null for the laterally rigid belt
  const CoupledTread* tread_;  ///< not owned; null for independent tread springs
};

}  // namespace modaltyre::contact::detail
