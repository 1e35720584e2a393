#include "modaltyre/solvers/leading_eigenpairs.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "modaltyre/core/errors.h"

namespace modaltyre::solvers {
namespace {

/// Eigenvalues closer than this times |T| are one cluster (LAPACK dstein's ORTOL).
constexpr double kClusterTolerance = 1e-3;
constexpr int kMaxIterations = 8;

/// LU of the tridiagonal T - shift I with partial pivoting (LAPACK dgttrf), for repeated solves.
class ShiftedTridiagonalLu {
 public:
  ShiftedTridiagonalLu(const Eigen::VectorXd& diag, const Eigen::VectorXd& off, double shift,
                       double tiny)
      : n_(static_cast<int>(diag.size())),
        d_(diag.array() - shift),
        dl_(off),
        du_(off),
        du2_(std::max(n_ - 2, 0)),
        swapped_(std::max(n_ - 1, 0), 0) {
    for (int i = 0; i + 1 < n_; ++i) {
      if (std::abs(d_(i)) >= std::abs(dl_(i))) {  // no interchange
        if (d_(i) == 0) d_(i) = tiny;
        const double fact = dl_(i) / d_(i);
        dl_(i) = fact;
        d_(i + 1) -= fact * du_(i);
        if (i + 2 < n_) du2_(i) = 0;
      } else {  // interchange rows i and i + 1
        const double fact = d_(i) / dl_(i);
        d_(i) = dl_(i);
        dl_(i) = fact;
        const double temp = du_(i);
        du_(i) = d_(i + 1);
        d_(i + 1) = temp - fact * d_(i + 1);
        if (i + 2 < n_) {
          du2_(i) = du_(i + 1);
          du_(i + 1) = -fact * du_(i + 1);
        }
        swapped_[i] = 1;
      }
    }
    if (n_ > 0 && d_(n_ - 1) == 0) d_(n_ - 1) = tiny;
  }

  /// b <- (T - shift I)^-1 b (LAPACK dgtts2).
  void solve(Eigen::VectorXd& b) const {
    for (int i = 0; i + 1 < n_; ++i) {
      if (!swapped_[i]) {
        b(i + 1) -= dl_(i) * b(i);
      } else {
        const double temp = b(i) - dl_(i) * b(i + 1);
        b(i) = b(i + 1);
        b(i + 1) = temp;
      }
    }
    for (int i = n_ - 1; i >= 0; --i) {
      double v = b(i);
      if (i + 1 < n_) v -= du_(i) * b(i + 1);
      if (i + 2 < n_) v -= du2_(i) * b(i + 2);
      b(i) = v / d_(i);
    }
  }

 private:
  int n_;
  Eigen::VectorXd d_, dl_, du_, du2_;
  std::vector<char> swapped_;
};

/// |T x - lambda x|_2 for the tridiagonal (diag, off).
double residual(const Eigen::VectorXd& diag, const Eigen::VectorXd& off, double lambda,
                const Eigen::VectorXd& x) {
  const int n = static_cast<int>(diag.size());
  double s = 0;
  for (int i = 0; i < n; ++i) {
    double r = (diag(i) - lambda) * x(i);
    if (i > 0) r += off(i - 1) * x(i - 1);
    if (i + 1 < n) r += off(i) * x(i + 1);
    s += r * r;
  }
  return std::sqrt(s);
}

}  // namespace

EigenPairs leading_eigenpairs(const Eigen::MatrixXd& a, double fraction) {
  MODALTYRE_CHECK(a.rows() == a.cols(), "leading_eigenpairs: square matrix");
  MODALTYRE_CHECK(fraction > 0 && fraction <= 1, "leading_eigenpairs: fraction in (0, 1]");
  const int n = static_cast<int>(a.rows());
  EigenPairs out;
  if (n == 0) return out;
  const Eigen::Tridiagonalization<Eigen::MatrixXd> tri(a);
  const Eigen::VectorXd diag = tri.diagonal();
  const Eigen::VectorXd off = tri.subDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> values_only;
  values_only.computeFromTridiagonal(diag, off, Eigen::EigenvaluesOnly);
  if (values_only.info() != Eigen::Success)
    throw ComputationError("leading_eigenpairs: QL iteration on the tridiagonal failed");
  const Eigen::VectorXd& lam = values_only.eigenvalues();  // ascending
  out.largest_abs = lam.cwiseAbs().maxCoeff();
  std::vector<double> kept;
  for (int i = n - 1; i >= 0; --i)
    if (lam(i) >= fraction * out.largest_abs) kept.push_back(lam(i));
  const int p = static_cast<int>(kept.size());

  double norm = 0;  // |T|_inf
  for (int i = 0; i < n; ++i)
    norm = std::max(norm, std::abs(diag(i)) + (i > 0 ? std::abs(off(i - 1)) : 0.0) +
                              (i + 1 < n ? std::abs(off(i)) : 0.0));
  const double eps = std::numeric_limits<double>::epsilon();
  const double tiny = eps * std::max(norm, std::numeric_limits<double>::min());
  const double converged = 10.0 * std::sqrt(static_cast<double>(n)) * eps * norm;

  Eigen::MatrixXd y(n, p);  // eigenvectors of T
  unsigned seed = 12345u;
  for (int k = 0; k < p; ++k) {
    const ShiftedTridiagonalLu lu(diag, off, kept[k], tiny);
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) {  // deterministic pseudo-random start (no accidental zeros)
      seed = seed * 1664525u + 1013904223u;
      x(i) = 0.5 + static_cast<double>(seed >> 8) / static_cast<double>(1u << 24);
    }
    // Members of the same cluster computed before this one.
    int first = k;
    while (first > 0 && kept[first - 1] - kept[k] <= kClusterTolerance * norm) --first;
    bool ok = false;
    for (int it = 0; it < kMaxIterations && !ok; ++it) {
      lu.solve(x);
      for (int j = first; j < k; ++j) x -= y.col(j).dot(x) * y.col(j);
      x.normalize();
      ok = it >= 1 && residual(diag, off, kept[k], x) <= converged;
    }
    if (!ok)
      throw ComputationError(
          "leading_eigenpairs: inverse iteration did not converge for the "
          "eigenvalue " +
          std::to_string(kept[k]) + " (residual " +
          std::to_string(residual(diag, off, kept[k], x) / norm) + " of |T|)");
    y.col(k) = x;
  }
  out.values = Eigen::Map<const Eigen::VectorXd>(kept.data(), p);
  out.vectors = tri.matrixQ() * y;
  return out;
}

}  // namespace modaltyre::solvers
