#pragma once
// Newton matrix M = I - gamma J of an implicit integrator for systems with an "arrow"
// structure: a few densely coupled states X (the first nx) and many states E (the rest) that
// couple to each other only through an upper band of width 2 (E_i to E_{i+1}, E_{i+2}) and to X
// through dense blocks:
//
//   M = [ M_XX  M_XE ]     M_EE upper triangular with two super-diagonals,
//       [ M_EX  M_EE ]     M_XE, M_EX nonzero on a contiguous range of E only.
//
// Factorisation by the Schur complement on X: S = M_XX - M_XE M_EE^-1 M_EX (dense, LU with
// partial pivoting), M_EE by back substitution; a solve is O(nx^2 + nx r + ne), r the coupled
// range. This is the transient tyre's Newton matrix (X = carcass and hub, E = tread units,
// transient/ode_system.h): a general sparse LU (KLU) spends most of its time on the dense
// block, at ~8 instructions per flop, and fills its triangular factors with the coupling rows.
#include <Eigen/Dense>
#include <cstdint>
#include <vector>

#include "modaltyre/solvers/cvode_klu.h"

namespace modaltyre::solvers {

class ArrowLu {
 public:
  /// Factorises I - gamma J for J in CSC form with the structure above (nx dense states
  /// first). Returns false if J has an entry outside the structure or the Schur complement is
  /// not invertible (non-finite pivots).
  bool factor(const CscMatrix& J, double gamma, int64_t nx);
  /// x <- M^-1 x (in place, n entries).
  void solve(double* x) const;

  int64_t coupled_range() const { return hi_ >= lo_ ? hi_ - lo_ + 1 : 0; }

 private:
  /// y <- M_EE^-1 y over E indices [0, ne) (back substitution from the last).
  void solve_ee(double* y) const;

  int64_t n_ = 0, nx_ = 0, ne_ = 0;
  int64_t lo_ = 0, hi_ = -1;          ///< coupled range of E indices
  std::vector<int64_t> rows_, cols_;  ///< X rows of M_XE, X columns of M_EX
  Eigen::VectorXd d_, s1_, s2_;       ///< M_EE: diagonal, first and second super-diagonal
  Eigen::MatrixXd xe_, ex_;           ///< M_XE transposed (range x |rows|), M_EX (range x |cols|)
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  mutable Eigen::VectorXd tmp_x_, tmp_e_, tmp_r_, tmp_c_;  // solve()'s work vectors
};

}  // namespace modaltyre::solvers
