#pragma once
// Matrix-free compliance of points on a uniform angular grid (seed 001 eq. 1 and 12).
//
// The carcass transfer functions depend on the angle between two points only (axisymmetry), so
// on a uniform grid the four kernels K_ab (a, b in {radial, tangential}) are Toeplitz in the
// point indices. A force f_j projected on the two directions with weights w_b(j) (cos, sin of
// the unit's angle), transmitted by the kernels and projected back gives
//   C_ij = sum_ab w_a(i) K_ab(i - j) w_b(j) + d_i delta_ij,
// d being a local (tread) compliance. A product with a block of C is then two weightings, four
// convolutions and two weightings: by FFT O(N log N) with N ~ rows + columns of the block,
// against O(rows x columns) with an assembled matrix, and no m x m array is ever stored.
#include <array>
#include <complex>
#include <cstdlib>
#include <memory>
#include <mutex>
#include <vector>

#include "modaltyre/solvers/compliance_operator.h"

namespace modaltyre::solvers {

/// u_a(i) = sum_b sum_j K_ab(i - j) v_b(j) for a, b in {0, 1}: a 2 x 2 block-Toeplitz product.
/// Not thread-safe (work arrays): one instance per thread. Copies share the kernels' spectra
/// (computed once per FFT length, under a lock), so a copy per solve or thread costs no
/// transforms of the kernels; the FFT plans are per thread and live as long as it.
class LagConvolution2x2 {
 public:
  /// kernels = {K_00, K_01, K_10, K_11}, each sampled at lags -(lags-1) .. lags-1 (lag l at
  /// index l + lags - 1).
  LagConvolution2x2(std::array<std::vector<double>, 4> kernels, int lags);

  int lags() const { return lags_; }
  /// K_ab(l), 0 for |l| >= lags.
  double kernel(int a, int b, int l) const {
    return std::abs(l) < lags_ ? k_[2 * a + b][static_cast<std::size_t>(l + lags_ - 1)] : 0.0;
  }

  /// u_a(i) for i = r0 .. r0+nr-1 from v_b(j), j = c0 .. c0+nc-1 (v and u indexed from the
  /// block's first row/column); u is overwritten. By FFT when that is cheaper than the sum.
  void apply(int r0, int nr, int c0, int nc, const double* v0, const double* v1, double* u0,
             double* u1) const;
  /// The same by the direct O(nr nc) sum.
  void apply_direct(int r0, int nr, int c0, int nc, const double* v0, const double* v1, double* u0,
                    double* u1) const;

 private:
  struct Spectra {
    int n = 0;
    std::array<std::vector<std::complex<double>>, 4> h;  ///< half spectra, scaled by 1/n
  };
  /// The spectra of every FFT length used so far, shared by the copies of one convolution.
  struct SpectraCache {
    std::mutex mutex;
    std::vector<std::shared_ptr<const Spectra>> all;
  };
  const Spectra& spectra(int n) const;
  void apply_fft(int r0, int nr, int c0, int nc, const double* v0, const double* v1, double* u0,
                 double* u1) const;

  std::array<std::vector<double>, 4> k_;
  int lags_ = 0;
  std::shared_ptr<SpectraCache> cache_;
  mutable std::vector<std::shared_ptr<const Spectra>> seen_;  ///< this copy's lock-free view
  mutable std::vector<double> real_;
  mutable std::vector<std::complex<double>> x0_, x1_, y_;
};

/// C_ij = sum_ab w_a(i) K_ab(i - j) w_b(j) + d_i delta_ij (see the top of this file).
/// Not thread-safe, like its convolution.
class WeightedToeplitzCompliance final : public ComplianceOperator {
 public:
  WeightedToeplitzCompliance(LagConvolution2x2 convolution, std::vector<double> w0,
                             std::vector<double> w1, std::vector<double> diagonal);

  int size() const override { return static_cast<int>(d_.size()); }
  double entry(int i, int j) const override;
  void gather(const std::vector<int>& S, Eigen::MatrixXd& A) const override;
  void apply(int r0, int nr, int c0, int nc, const Eigen::Ref<const Eigen::MatrixXd>& X,
             Eigen::Ref<Eigen::MatrixXd> Y) const override;
  /// The assembled matrix (for tests and small problems).
  Eigen::MatrixXd dense() const;

 private:
  LagConvolution2x2 conv_;
  std::vector<double> w0_, w1_, d_;
  mutable std::vector<double> v0_, v1_, u0_, u1_;
};

/// Smallest n' >= n that is a multiple of 4 with no prime factor above 5 (fast real FFTs).
int fast_fft_length(int n);

}  // namespace modaltyre::solvers
