#pragma once
// Compliance operators of the 3D patch (patch3d.h), internal to the contact library.
#include <vector>

#include "modaltyre/solvers/compliance_operator.h"

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

/// The cell compliance: cells indexed i * columns + j, the carcass between the sections'
/// resultants, each cell's own tread t_i and, if given, the section's lateral belt compliance G,
///   C_(ij)(kl) = C_carcass(i, k) + [i = k] (t_i [j = l] + G(j, l)).
class CellCompliance final : public solvers::ComplianceOperator {
 public:
  CellCompliance(const solvers::ComplianceOperator& carcass, int columns, std::vector<double> t,
                 const Eigen::MatrixXd* lateral = nullptr)
      : carcass_(carcass), columns_(columns), t_(std::move(t)), G_(lateral) {}
  int size() const override { return carcass_.size() * columns_; }
  double entry(int a, int b) const override {
    const int i = a / columns_, k = b / columns_;
    double c = carcass_.entry(i, k) + (a == b ? t_[i] : 0.0);
    if (G_ && i == k) c += (*G_)(a % columns_, b % columns_);
    return c;
  }
  void apply(int r0, int nr, int c0, int nc, const Eigen::Ref<const Eigen::MatrixXd>& X,
             Eigen::Ref<Eigen::MatrixXd> Y) const override;

 private:
  const solvers::ComplianceOperator& carcass_;
  int columns_;
  std::vector<double> t_;
  const Eigen::MatrixXd* G_;  ///< not owned; null for the laterally rigid belt
};

}  // namespace modaltyre::contact::detail
