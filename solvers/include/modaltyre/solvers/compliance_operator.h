#pragma once
// A compliance matrix seen only through what the contact solver needs of it: single entries and
// products with contiguous blocks. Lets the solver run on structured compliances (e.g. the
// Toeplitz one of toeplitz_compliance.h) without ever forming the m x m matrix.
#include <Eigen/Dense>
#include <memory>
#include <vector>

namespace modaltyre::solvers {

/// An approximation M^-1 of C(S, S)^-1 on one contact set S (symmetric positive definite), for
/// the conjugate gradients of the contact solve.
class SetPreconditioner {
 public:
  virtual ~SetPreconditioner() = default;
  /// Z = M^-1 R for R with |S| rows (any number of columns); Z is overwritten.
  virtual void apply(const Eigen::MatrixXd& R, Eigen::MatrixXd& Z) const = 0;
};

class ComplianceOperator {
 public:
  virtual ~ComplianceOperator() = default;
  /// m, the number of points.
  virtual int size() const = 0;
  /// C(i, j) [m/N].
  virtual double entry(int i, int j) const = 0;
  /// A = C(S, S), the restriction to the points S (for a direct factorisation). The default
  /// calls entry() k^2 times.
  virtual void gather(const std::vector<int>& S, Eigen::MatrixXd& A) const;
  /// Y = C(r0 .. r0+nr-1, c0 .. c0+nc-1) X for X with nc rows (any number of columns); Y is
  /// overwritten and must have nr rows and X's columns.
  virtual void apply(int r0, int nr, int c0, int nc, const Eigen::Ref<const Eigen::MatrixXd>& X,
                     Eigen::Ref<Eigen::MatrixXd> Y) const = 0;
  /// A preconditioner of C(S, S) for a structured operator (S sorted); null: the solver's
  /// Jacobi one (the default).
  virtual std::unique_ptr<SetPreconditioner> preconditioner(const std::vector<int>& /*S*/) const {
    return nullptr;
  }
};

/// The operator of an explicit matrix (kept by reference: it must outlive the operator).
class DenseCompliance final : public ComplianceOperator {
 public:
  explicit DenseCompliance(const Eigen::MatrixXd& C) : C_(C) {}
  int size() const override { return static_cast<int>(C_.rows()); }
  double entry(int i, int j) const override { return C_(i, j); }
  void gather(const std::vector<int>& S, Eigen::MatrixXd& A) const override;
  void apply(int r0, int nr, int c0, int nc, const Eigen::Ref<const Eigen::MatrixXd>& X,
             Eigen::Ref<Eigen::MatrixXd> Y) const override;

 private:
  const Eigen::MatrixXd& C_;
};

}  // namespace modaltyre::solvers
