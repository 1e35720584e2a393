#include "modaltyre/ema/lscf.h"

#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/Polynomials>

#include "lsfd_basis.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::ema {
namespace {

using detail::kTwoPi;  // lsfd_basis.h

struct OrderPoles {
  std::vector<DiagramPole> poles;
  std::vector<Eigen::VectorXcd> shapes;  // numerator values at the root, per channel
};

double mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  const double den = a.squaredNorm() * b.squaredNorm();
  return den > 0 ? std::norm(a.dot(b)) / den : 0.0;
}

}  // namespace

void StabilityCriteria::validate() const {
  if (!(freq_tol > 0 && freq_tol < 0.5) || !(damping_tol > 0 && damping_tol < 5) ||
      !(mac_min > 0 && mac_min <= 1)) {
    throw InputError(
        "stability criteria: need 0 < freq_tol < 0.5, 0 < damping_tol < 5, "
        "0 < mac_min <= 1");
  }
}

void PoleSelection::validate() const {
  if (!(min_recurrence > 0 && min_recurrence <= 1) || !(match_tol > 0 && match_tol < 0.1) ||
      !(max_damping > 0 && max_damping < 1)) {
    throw InputError(
        "pole selection: need 0 < min_recurrence <= 1, 0 < match_tol < 0.1, "
        "0 < max_damping < 1");
  }
}

std::complex<double> SelectedPole::lambda() const {
  const double w = kTwoPi * freq_hz;
  return {-damping_ratio * w, w * std::sqrt(1 - damping_ratio * damping_ratio)};
}

StabilisationDiagram lscf_diagram(const std::vector<double>& freq_hz, const Eigen::MatrixXcd& frf,
                                  int max_order, const StabilityCriteria& criteria) {
  criteria.validate();
  const int nf = static_cast<int>(freq_hz.size());
  const int no = static_cast<int>(frf.cols());
  MODALTYRE_CHECK(frf.rows() == nf && nf > max_order + 1 && max_order >= 2 && no > 0,
                  "lscf_diagram: sizes");
  StabilisationDiagram diagram;
  diagram.band_lo_hz = freq_hz.front();
  diagram.band_hi_hz = freq_hz.back();
  const double ts = 1.0 / (2.0 * freq_hz.back());

  // Omega_f^k for k = -n ... n (column k + n).
  const int n = max_order;
  Eigen::MatrixXcd omega_pow(nf, 2 * n + 1);
  for (int f = 0; f < nf; ++f) {
    const double theta = kTwoPi * freq_hz[f] * ts;
    for (int k = -n; k <= n; ++k) omega_pow(f, k + n) = std::polar(1.0, -k * theta);
  }
  // T[a][b] = sum_o Re sum_f |H_o|^2 Omega^(b-a) (Toeplitz).
  const Eigen::VectorXcd t =
      omega_pow.transpose() * frf.cwiseAbs2().rowwise().sum().cast<std::complex<double>>();

  // The numerator basis X (lines x orders, real and imaginary parts stacked) is far from
  // orthogonal when the band is a part of 0 ... f_hi (its Gram matrix can be singular to
  // machine precision): the numerators are eliminated through an orthonormal basis Q of X
  // instead of the normal equations. QR is nested: the first n+1 columns of Q serve order n.
  const Eigen::MatrixXcd x = omega_pow.rightCols(n + 1);
  Eigen::MatrixXd xs(2 * nf, n + 1);
  xs << x.real(), x.imag();
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(xs);
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(2 * nf, n + 1);
  const Eigen::MatrixXd rx = qr.matrixQR().topRows(n + 1).triangularView<Eigen::Upper>();
  std::vector<Eigen::MatrixXd> b(no);  // Q^T Y_o, Y_o = -H_o X (stacked)
  for (int o = 0; o < no; ++o) {
    const Eigen::MatrixXcd y = -(frf.col(o).asDiagonal() * x);
    Eigen::MatrixXd ys(2 * nf, n + 1);
    ys << y.real(), y.imag();
    b[o] = q.transpose() * ys;
  }

  const auto at = [n](int k) { return k + n; };
  std::vector<OrderPoles> all;
  for (int order = 2; order <= max_order; ++order) {
    const int m = order + 1;
    Eigen::MatrixXd M(m, m);
    for (int a = 0; a < m; ++a) {
      for (int c = 0; c < m; ++c) M(a, c) = t(at(c - a)).real();
    }
    for (int o = 0; o < no; ++o) {
      const auto bo = b[o].topLeftCorner(m, m);
      M.noalias() -= bo.transpose() * bo;
    }
    // alpha_order = 1; the others from the first `order` reduced normal equations.
    Eigen::VectorXd alpha(m);
    alpha.head(order) = M.topLeftCorner(order, order).ldlt().solve(-M.col(order).head(order));
    alpha(order) = 1.0;
    if (!alpha.allFinite()) {  // a singular order: no poles, the next order starts afresh
      diagram.orders.push_back({order, {}});
      all.emplace_back();
      continue;
    }
    Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(alpha);
    OrderPoles op;
    for (const auto& z : solver.roots()) {
      if (std::abs(z) == 0) continue;
      const std::complex<double> lambda = -std::log(z) / ts;
      if (lambda.imag() <= 0) continue;  // one of each conjugate pair
      const double w = std::abs(lambda);
      const double zeta = -lambda.real() / w;
      const double fhz = w / kTwoPi;
      if (!(zeta > 0 && zeta < 1) || fhz < diagram.band_lo_hz || fhz > diagram.band_hi_hz) continue;
      // The numerator N_o = -Rx^-1 Q^T Y_o alpha at the root is proportional to the residue.
      Eigen::VectorXcd shape(no);
      Eigen::VectorXcd zp(m);
      zp(0) = 1;
      for (int a = 1; a < m; ++a) zp(a) = zp(a - 1) * z;
      for (int o = 0; o < no; ++o) {
        const Eigen::VectorXd beta = -rx.topLeftCorner(m, m).triangularView<Eigen::Upper>().solve(
            b[o].topLeftCorner(m, m) * alpha);
        shape(o) = (beta.cast<std::complex<double>>().array() * zp.array()).sum();
      }
      op.poles.push_back({fhz, zeta, 'o'});
      op.shapes.push_back(shape);
    }
    // Stability against the previous order.
    if (!all.empty()) {
      const OrderPoles& prev = all.back();
      for (std::size_t i = 0; i < op.poles.size(); ++i) {
        auto& p = op.poles[i];
        std::size_t best = prev.poles.size();
        double best_df = 1e300;
        for (std::size_t j = 0; j < prev.poles.size(); ++j) {
          const double df = std::abs(prev.poles[j].freq_hz - p.freq_hz);
          if (df < best_df) best_df = df, best = j;
        }
        if (best == prev.poles.size() || best_df > criteria.freq_tol * p.freq_hz) continue;
        p.status = 'f';
        const auto& q = prev.poles[best];
        if (std::abs(q.damping_ratio - p.damping_ratio) > criteria.damping_tol * p.damping_ratio)
          continue;
        p.status = 'd';
        if (mac(op.shapes[i], prev.shapes[best]) >= criteria.mac_min) p.status = 's';
      }
    }
    diagram.orders.push_back({order, op.poles});
    all.push_back(std::move(op));
  }
  return diagram;
}

std::vector<SelectedPole> select_poles(const StabilisationDiagram& diagram,
                                       const PoleSelection& selection) {
  selection.validate();
  std::vector<SelectedPole> out;
  if (diagram.orders.empty()) return out;
  const DiagramOrder& top = diagram.orders.back();
  std::vector<const DiagramOrder*> upper;
  for (const auto& o : diagram.orders) {
    if (o.order >= top.order / 2 && o.order < top.order) upper.push_back(&o);
  }
  for (const auto& p : top.poles) {
    if (p.damping_ratio > selection.max_damping) continue;
    int hits = 0;
    for (const DiagramOrder* o : upper) {
      for (const auto& q : o->poles) {
        if (std::abs(q.freq_hz - p.freq_hz) <= selection.match_tol * p.freq_hz &&
            q.damping_ratio <= selection.max_damping) {
          ++hits;
          break;
        }
      }
    }
    const double rec = upper.empty() ? 0.0 : double(hits) / double(upper.size());
    if (rec >= selection.min_recurrence) out.push_back({p.freq_hz, p.damping_ratio, rec});
  }
  std::sort(out.begin(), out.end(),
            [](const SelectedPole& a, const SelectedPole& b) { return a.freq_hz < b.freq_hz; });
  return out;
}

}  // namespace modaltyre::ema
