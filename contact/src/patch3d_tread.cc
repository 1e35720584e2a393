// The 3D patch's shear-coupled tread (tread_coupling on the cells, patch3d_operators.h): a
// Pasternak layer over the cell grid, k (u - a_x D_xx u - a_y D_yy u) = f per cell with
// a_x = (l / ds)^2, a_y = (l / dy)^2 (effects.h: the same layer as the 2D patch's, sheared along
// and across the road). Along the road the layer is unbounded (as the 2D patch's); across it
// the tread ends at its edges, which carry no shear (a free edge: zero slope of u).
//
// The free edges make the discrete Laplacian across the tread the Neumann one: eigenvectors
// phi_m(j) = cos(pi m (j + 1/2) / n) (normalised), eigenvalues lambda_m = 4 sin^2(pi m / 2n).
// In mode m the layer is the 1D Pasternak layer of stiffness k (1 + a_y lambda_m) and coupling
// a_x / (1 + a_y lambda_m), whose unbounded-line Green's function is pasternak_tread_lags
// (predictor.h). So
//   T((i, j), (k, l)) = sum_m phi_m(j) phi_m(l) g_m(|i - k|),
// and a product T f is a transform across the tread, one lag convolution per mode along it, and
// the transform back. A load uniform across the tread excites mode 0 alone: the 2D patch's
// layer (test: a flat crown gives the 2D patch's coupled footprint).
#include <algorithm>
#include <cmath>

#include "modaltyre/contact/predictor.h"
#include "patch3d_operators.h"

namespace modaltyre::contact::detail {

namespace {

// One mode's convolution along the road, o[q - q0] = g0 sum_s rho^|q - s| v[s - s0] for
// q0 <= q <= q1, the forces on s0..s1 (`ahead`: s1 - s0 + 1 values). g_m is geometric,
// g_m(d) = g_m(0) rho_m^|d| (pasternak_tread_lags), so the sum is two first-order recursions,
// one running forward and one back (O(sections) instead of O(sections^2); the lags' 1e-12
// truncation is not repeated: 1e-12 of the answer). Before s0 the forward sum is 0, after s1
// the backward one.
[[gnu::noinline]] void convolve_mode(double rho, double g0, const double* v, int s0, int s1,
                                     double* o, int q0, int q1, double* ahead) {
  constexpr double kTiny = 1e-290;  // no subnormal steps once a tail has decayed
  // Forward: the sums at s0..s1 kept, then their decay onto the rows after s1.
  double f = 0;
  for (int s = s0; s <= s1; ++s) {
    f = rho * f + v[s - s0];
    if (std::abs(f) < kTiny) f = 0;
    ahead[s - s0] = f;
  }
  for (int s = s1 + 1; s <= q1; ++s) {
    f = rho * f;
    if (std::abs(f) < kTiny) f = 0;
    if (s >= q0) o[s - q0] = g0 * f;
  }
  // Backward: b = sum over s' > s of rho^(s' - s) v(s'), 0 after s1.
  double b = 0;
  for (int s = s1; s >= s0; --s) {
    if (s >= q0 && s <= q1) o[s - q0] = g0 * (ahead[s - s0] + b);
    b = rho * (b + v[s - s0]);
    if (std::abs(b) < kTiny) b = 0;
  }
  for (int s = s0 - 1; s >= q0; --s) {
    if (s <= q1) o[s - q0] = g0 * b;
    b = rho * b;
    if (std::abs(b) < kTiny) b = 0;
  }
}

}  // namespace

CoupledTread::CoupledTread(double k_cell_N_m, double coupling_m, double ds_m, double dy_m,
                           int sections, int columns, std::vector<double> cos_theta)
    : k_cell_(k_cell_N_m),
      coupling_(coupling_m),
      ds_(ds_m),
      dy_(dy_m),
      sections_(sections),
      columns_(columns),
      cos_(std::move(cos_theta)),
      modes_(columns) {
  const int n = columns;
  lags_.resize(n);
  const double ay = (coupling_m / dy_m) * (coupling_m / dy_m);
  for (int m = 0; m < n; ++m) {
    const double s = std::sin(0.5 * M_PI * m / n);
    const double stiffening = 1 + ay * 4 * s * s;  // 1 + a_y lambda_m
    lags_[m] = pasternak_tread_lags(k_cell_N_m * stiffening, coupling_m / std::sqrt(stiffening),
                                    ds_m, sections);
  }
  ratio_.resize(n);
  for (int m = 0; m < n; ++m) {
    const std::vector<double>& g = lags_[m];
    ratio_[m] = g.size() > 1 ? g[1] / g[0] : 0.0;
  }
  own_.resize(n);
  for (int j = 0; j < n; ++j) {
    double g = 0;
    for (int m = 0; m < n; ++m) g += modes()(j, m) * modes()(j, m) * lags_[m][0];
    own_[j] = g;
  }
}

double CoupledTread::entry(int a, int b) const {
  const int i = a / columns_, j = a % columns_, k = b / columns_, l = b % columns_;
  const std::size_t lag = static_cast<std::size_t>(std::abs(i - k));
  double g = 0;
  for (int m = 0; m < columns_; ++m) {
    if (lag < lags_[m].size()) g += modes()(j, m) * modes()(l, m) * lags_[m][lag];
  }
  return cos_[i] * cos_[k] * g;
}

void CoupledTread::add_product(int r0, int nr, int c0, int nc,
                               const Eigen::Ref<const Eigen::MatrixXd>& X,
                               Eigen::Ref<Eigen::MatrixXd> Y) const {
  const int n = columns_, cols = static_cast<int>(X.cols());
  // The sections the blocks touch (the first and last may be partial).
  const int s0 = c0 / n, s1 = (c0 + nc - 1) / n, q0 = r0 / n, q1 = (r0 + nr - 1) / n;
  const int span = s1 - s0 + 1, rows = q1 - q0 + 1;
  // Every right-hand side at once, stacked along the rows (c * span + s): one transform each way.
  // The column block's forces as sections x columns, cos-weighted; to modal coefficients
  // c(s, m) = sum_l phi_m(l) cos_s f(s, l) (patch3d_cosine.h).
  // The block covers its sections but for the first one's columns before c0 and the last one's
  // after c0 + nc - 1: only those are zeroed.
  Eigen::MatrixXd cells(Eigen::Index(cols) * span, n), coef;
  const int first = c0 - s0 * n, last = c0 + nc - 1 - s1 * n;
  for (int c = 0; c < cols; ++c) {
    const Eigen::Index row = Eigen::Index(c) * span;
    for (int j = 0; j < first; ++j) cells(row, j) = 0;
    for (int j = last + 1; j < n; ++j) cells(row + span - 1, j) = 0;
    int s = s0, j = first;
    for (int b = 0; b < nc; ++b) {
      cells(row + s - s0, j) = cos_[s] * X(b, c);
      if (++j == n) j = 0, ++s;
    }
  }
  modes_.forward(cells, coef);
  // Convolution along the road per mode, onto the row block's sections (convolve_mode).
  std::vector<double> ahead(span);  // sum over s' <= s of rho^(s - s') v(s'), s0 <= s <= s1
  Eigen::MatrixXd out(Eigen::Index(cols) * rows, n), back;
  for (int c = 0; c < cols; ++c) {
    for (int m = 0; m < n; ++m) {
      const double rho = ratio_[m], g0 = lags_[m][0];
      const double* v = &coef(Eigen::Index(c) * span, m);  // v[s - s0], s0 <= s <= s1
      double* o = &out(Eigen::Index(c) * rows, m);         // o[q - q0], q0 <= q <= q1
      convolve_mode(rho, g0, v, s0, s1, o, q0, q1, ahead.data());
    }
  }
  // Back across the tread, weighted by the row cells' cos theta.
  modes_.backward(out, back);
  for (int c = 0; c < cols; ++c) {
    int q = q0, j = r0 - q0 * n;
    for (int a = 0; a < nr; ++a) {
      Y(a, c) += cos_[q] * back(Eigen::Index(c) * rows + q - q0, j);
      if (++j == n) j = 0, ++q;
    }
  }
}

}  // namespace modaltyre::contact::detail
