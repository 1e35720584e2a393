// The compliance operators of the 3D patch (patch3d_operators.h), the lateral belt's beam
// operator (lateral_belt_compliance, docs/footprint.md section 7) and the sections' lateral laws
// (patch3d_sections.h).
#include "patch3d_operators.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/solvers/unilateral_contact.h"
#include "patch3d_sections.h"

namespace modaltyre::contact::detail {

void DiagonalShifted::gather(const std::vector<int>& S, Eigen::MatrixXd& A) const {
  base_.gather(S, A);
  for (std::size_t a = 0; a < S.size(); ++a) A(a, a) += d_[S[a]];
}

void DiagonalShifted::apply(int r0, int nr, int c0, int nc,
                            const Eigen::Ref<const Eigen::MatrixXd>& X,
                            Eigen::Ref<Eigen::MatrixXd> Y) const {
  base_.apply(r0, nr, c0, nc, X, Y);
  for (int i = std::max(r0, c0); i < std::min(r0 + nr, c0 + nc); ++i) {
    Y.row(i - r0) += d_[i] * X.row(i - c0);
  }
}

void CellCompliance::apply(int r0, int nr, int c0, int nc,
                           const Eigen::Ref<const Eigen::MatrixXd>& X,
                           Eigen::Ref<Eigen::MatrixXd> Y) const {
  const int n = columns_;
  const Eigen::Index cols = X.cols();
  // Section resultants of the column block (its first and last sections may be partial); the
  // cells walked by section and column (no division per cell).
  const int s0 = c0 / n, s1 = (c0 + nc - 1) / n;
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(s1 - s0 + 1, cols);
  for (Eigen::Index c = 0; c < cols; ++c) {
    int s = 0, j = c0 - s0 * n;
    for (int b = 0; b < nc; ++b) {
      F(s, c) += X(b, c);
      if (++j == n) j = 0, ++s;
    }
  }
  // Carcass displacement of the row block's sections, spread to their cells.
  const int q0 = r0 / n, q1 = (r0 + nr - 1) / n;
  Eigen::MatrixXd W(q1 - q0 + 1, cols);
  carcass_.apply(q0, q1 - q0 + 1, s0, s1 - s0 + 1, F, W);
  // Each cell's own tread on the cells both blocks hold.
  const int d0 = std::max(r0, c0), d1 = std::min(r0 + nr, c0 + nc);
  for (Eigen::Index c = 0; c < cols; ++c) {
    int q = 0, j = r0 - q0 * n;
    for (int a = 0; a < nr; ++a) {
      Y(a, c) = W(q, c);
      if (++j == n) j = 0, ++q;
    }
    if (d0 >= d1) continue;
    int i = d0 / n;
    j = d0 - i * n;
    for (int a = d0; a < d1; ++a) {
      Y(a - r0, c) += t_[i] * X(a - c0, c);
      if (++j == n) j = 0, ++i;
    }
  }
  if (tread_) tread_->add_product(r0, nr, c0, nc, X, Y);
  if (!G_) return;
  // Each section's lateral belt, on the sections the row and column blocks share.
  for (int q = std::max(q0, s0); q <= std::min(q1, s1); ++q) {
    const int a0 = std::max(r0, q * n), a1 = std::min(r0 + nr, (q + 1) * n);
    const int b0 = std::max(c0, q * n), b1 = std::min(c0 + nc, (q + 1) * n);
    if (a0 >= a1 || b0 >= b1) continue;
    Y.middleRows(a0 - r0, a1 - a0) +=
        G_->block(a0 - q * n, b0 - q * n, a1 - a0, b1 - b0) * X.middleRows(b0 - c0, b1 - b0);
  }
}

}  // namespace modaltyre::contact::detail

namespace modaltyre::contact {

void LateralBelt::validate(double tread_width_m) const {
  if (!enabled) return;
  if (!(bending_stiffness_Nm > 0)) {
    throw std::invalid_argument("lateral belt: bending stiffness must be > 0");
  }
  if (!(tension_N_m >= 0) || !(foundation_Pa_m >= 0)) {
    throw std::invalid_argument("lateral belt: tension and foundation must be >= 0");
  }
  if (supports == BeltSupports::free) {
    if (!(foundation_Pa_m > 0)) {
      throw std::invalid_argument("lateral belt: free ends need a foundation > 0");
    }
    if (tension_N_m != 0) {
      throw std::invalid_argument("lateral belt: a tension needs supports (shoulders)");
    }
  } else if (support_span_m != 0 && !(support_span_m >= tread_width_m)) {
    throw std::invalid_argument("lateral belt: the support span must be >= the tread width");
  }
}

Eigen::MatrixXd lateral_belt_compliance(const LateralBelt& b, double W, int ny, double ds) {
  b.validate(W);
  // Hermite cubic beam elements (seed-independent; e.g. Przemieniecki, Theory of Matrix
  // Structural Analysis, ch. 5): the tread's columns are elements; between the tread edge and
  // a support beyond it, unloaded elements of about the same length.
  const double h = W / ny;
  int extra = 0;
  double he = 0;
  if (b.supports == BeltSupports::shoulders && b.support_span_m > W) {
    const double over = 0.5 * (b.support_span_m - W);
    extra = std::max(1, static_cast<int>(std::ceil(over / h - 1e-9)));
    he = over / extra;
  }
  const int ne = ny + 2 * extra, nd = 2 * (ne + 1);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nd, nd);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(nd, ny);  // cell force -> consistent nodal load
  Eigen::MatrixXd R(nd, 2);                           // rigid translation, rotation
  double y = -0.5 * W - extra * he;
  R.row(0) << 1, y;
  R.row(1) << 0, 1;
  for (int e = 0; e < ne; ++e) {
    const bool tread = e >= extra && e < extra + ny;
    const double L = tread ? h : he;
    const double D = b.bending_stiffness_Nm, N = b.tension_N_m, k = b.foundation_Pa_m;
    Eigen::Matrix4d Kb, Kg, Kf;
    Kb << 12, 6 * L, -12, 6 * L, 6 * L, 4 * L * L, -6 * L, 2 * L * L, -12, -6 * L, 12, -6 * L,
        6 * L, 2 * L * L, -6 * L, 4 * L * L;
    Kg << 36, 3 * L, -36, 3 * L, 3 * L, 4 * L * L, -3 * L, -L * L, -36, -3 * L, 36, -3 * L, 3 * L,
        -L * L, -3 * L, 4 * L * L;
    Kf << 156, 22 * L, 54, -13 * L, 22 * L, 4 * L * L, 13 * L, -3 * L * L, 54, 13 * L, 156, -22 * L,
        -13 * L, -3 * L * L, -22 * L, 4 * L * L;
    K.block<4, 4>(2 * e, 2 * e) += D / (L * L * L) * Kb + N / (30 * L) * Kg + k * L / 420 * Kf;
    if (tread) {
      // A cell's force f spread over its element as the line load f / ds per unit width; the
      // cell's deflection is the element mean, so G = B^T K^-1 B / ds is symmetric.
      B.block<4, 1>(2 * e, e - extra) << 0.5, L / 12, 0.5, -L / 12;
    }
    y += L;
    R.row(2 * e + 2) << 1, y;
    R.row(2 * e + 3) << 0, 1;
  }
  Eigen::MatrixXd G;
  if (b.supports == BeltSupports::shoulders) {
    // Simple supports: no deflection at the end nodes (drop those two rows and columns).
    std::vector<int> keep;
    for (int d = 0; d < nd; ++d) {
      if (d != 0 && d != nd - 2) keep.push_back(d);
    }
    const int m = static_cast<int>(keep.size());
    Eigen::MatrixXd Kr(m, m), Br(m, ny);
    for (int a = 0; a < m; ++a) {
      Br.row(a) = B.row(keep[a]);
      for (int c = 0; c < m; ++c) Kr(a, c) = K(keep[a], keep[c]);
    }
    const Eigen::LLT<Eigen::MatrixXd> llt(Kr);
    G = Br.transpose() * llt.solve(Br);
  } else {
    // Free ends on the foundation: the strip's rigid translation and rotation are the carcass's
    // (it moves the section as a whole), so only the K-orthogonal rest is the belt's own:
    // K^-1 - R (R^T K R)^-1 R^T = K^-1 P^T with P = I - R (R^T K R)^-1 R^T K, positive
    // semi-definite, zero for a rigid strip. Formed as L^T K^-1 L with the self-equilibrated
    // loads L = P^T B (no cancellation when the belt is stiff).
    const Eigen::LLT<Eigen::MatrixXd> llt(K);
    const Eigen::MatrixXd KR = K * R;
    const Eigen::MatrixXd L = B - KR * (R.transpose() * KR).ldlt().solve(R.transpose() * B);
    G = L.transpose() * llt.solve(L);
  }
  G /= ds;
  return 0.5 * (G + G.transpose());
}

}  // namespace modaltyre::contact

namespace modaltyre::contact::detail {
namespace {

/// Laterally rigid sections: every cell of a section at the same approach, so the pattern is
/// the n lowest drops (at least the tied lowest ones).
class Rigid final : public SectionLaws {
 public:
  Rigid(const std::vector<double>& t, const std::vector<double>& z) : t_(t), zs_(z) {
    std::sort(zs_.begin(), zs_.end());
    const int ny = static_cast<int>(zs_.size());
    prefix_.assign(ny + 1, 0.0);
    for (int j = 0; j < ny; ++j) prefix_[j + 1] = prefix_[j] + zs_[j];
    min_cells_ = static_cast<int>(std::count(zs_.begin(), zs_.end(), zs_[0]));
    n_.assign(t.size(), ny);  // first pattern: every cell of a loaded section
    z_ = z;
  }
  void reduced(int i, double& c, double& o) const override {
    c = t_[i] / n_[i];
    o = prefix_[n_[i]] / n_[i];
  }
  bool consistent(int i, double F, double d, double tol) const override {
    const int ny = static_cast<int>(zs_.size());
    if (!(F > 0)) return d <= zs_[0] + tol;
    return d >= zs_[n_[i] - 1] - tol && (n_[i] == ny || d <= zs_[n_[i]] + tol);
  }
  void cell_forces(int i, double d, double* f) const override {
    for (std::size_t j = 0; j < z_.size(); ++j) f[j] = std::max(d - z_[j], 0.0) / t_[i];
  }
  void start_from(int i, const double* f) override {
    // The loaded cells are the n lowest drops (the sorted-drop law).
    const int loaded =
        static_cast<int>(std::count_if(f, f + zs_.size(), [](double v) { return v > 0; }));
    n_[i] = std::max(min_cells_, loaded);
  }
  double approach(int i, double F) override {
    int n = 0;
    return pattern_at(i, F, n);
  }
  double energy(int i, double F, bool update) override {
    const double t = t_[i];
    F = std::max(F, 0.0);
    int n = 0;
    const double d = pattern_at(i, F, n);
    if (update) n_[i] = n;
    // Psi(F) = d F - sum_j (d - z_j)_+^2 / (2 t)  (integration by parts of psi dF).
    double sq = 0;
    for (int j = 0; j < n; ++j) sq += (d - zs_[j]) * (d - zs_[j]);
    return d * F - sq / (2 * t);
  }

 private:
  // psi(F): the fewest cells n whose approach d = (F t + sum of their drops) / n does not reach
  // the next drop; returns d.
  double pattern_at(int i, double F, int& n) const {
    const int ny = static_cast<int>(zs_.size());
    const double t = t_[i];
    F = std::max(F, 0.0);
    n = min_cells_;
    double d = (F * t + prefix_[n]) / n;
    while (n < ny && d > zs_[n]) {
      ++n;
      d = (F * t + prefix_[n]) / n;
    }
    return d;
  }

  std::vector<double> t_, zs_, z_, prefix_;
  int min_cells_ = 1;
  std::vector<int> n_;
};

/// Sections with a lateral belt compliance G: the pattern is any set of cells.
class Flexible final : public SectionLaws {
 public:
  Flexible(const std::vector<double>& t, const std::vector<double>& z, const Eigen::MatrixXd& G,
           int max_iterations)
      : t_(t), z_(Eigen::Map<const Eigen::VectorXd>(z.data(), Eigen::Index(z.size()))), G_(G) {
    opt_.max_iterations = max_iterations;
    zmin_ = z_.minCoeff();
    const int ny = static_cast<int>(z.size());
    sec_.resize(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) set_pattern(int(i), std::vector<char>(ny, 1));
  }
  void reduced(int i, double& c, double& o) const override {
    c = sec_[i].c;
    o = sec_[i].o;
  }
  double approach(int i, double F) override {
    if (!(F > 0)) return zmin_;
    const Section& s = sec_[i];
    const double d = s.c * F + s.o;
    if (consistent(i, F, d, 0.0)) return d;
    return solve_section(i, F).approach_m;
  }
  void start_from(int i, const double* f) override {
    std::vector<char> loaded(z_.size());
    for (std::size_t j = 0; j < loaded.size(); ++j) loaded[j] = f[j] > 0;
    set_pattern(i, loaded);
  }
  bool consistent(int i, double F, double d, double tol) const override {
    if (!(F > 0)) return d <= zmin_ + tol;
    const Section& s = sec_[i];
    const Eigen::VectorXd fA = d * s.a - s.b;
    if ((fA * t_[i]).minCoeff() < -tol) return false;
    // Gaps of the cells off the pattern: z_j + (G f)_j - d.
    for (int j = 0; j < int(z_.size()); ++j) {
      if (s.active[j]) continue;
      double g = z_(j) - d;
      for (std::size_t q = 0; q < s.cells.size(); ++q) g += G_(j, s.cells[q]) * fA(q);
      if (g < -tol) return false;
    }
    return true;
  }
  void cell_forces(int i, double d, double* f) const override {
    const Section& s = sec_[i];
    std::fill(f, f + z_.size(), 0.0);
    for (std::size_t q = 0; q < s.cells.size(); ++q) {
      f[s.cells[q]] = std::max(d * s.a(q) - s.b(q), 0.0);
    }
  }
  double energy(int i, double F, bool update) override {
    const int ny = static_cast<int>(z_.size());
    if (!(F > 0)) {
      if (update) {
        std::vector<char> lowest(ny);
        for (int j = 0; j < ny; ++j) lowest[j] = z_(j) == zmin_;
        set_pattern(i, lowest);
      }
      return 0;
    }
    // On the current pattern, when it holds at F: the section's affine law, f_A = d a - b at
    // d = c F + o, and M_AA f_A = d 1 - z_A, so 1/2 f^T M f + z^T f = (d F + z_A^T f_A) / 2
    // without a contact solve (the same KKT point the solve would find).
    const Section& s = sec_[i];
    const double d = s.c * F + s.o;
    if (consistent(i, F, d, 0.0)) {
      double zf = 0;
      for (std::size_t q = 0; q < s.cells.size(); ++q) zf += z_(s.cells[q]) * (d * s.a(q) - s.b(q));
      return 0.5 * (d * F + zf);
    }
    const solvers::ContactSolution sol = solve_section(i, F);
    if (update) set_pattern(i, sol.active);
    const Eigen::VectorXd Mf = G_ * sol.force + t_[i] * sol.force;
    return 0.5 * sol.force.dot(Mf) + z_.dot(sol.force);
  }

 private:
  // The section's small contact problem (min 1/2 f^T M f + z^T f, f >= 0, sum f = F).
  solvers::ContactSolution solve_section(int i, double F) const {
    solvers::ContactProblem p;
    p.compliance = G_;
    p.compliance.diagonal().array() += t_[i];
    p.initial_gap = z_;
    p.load_N = F;
    auto sol = solvers::solve_unilateral_contact(p, opt_, sec_[i].active);
    if (!sol.ok()) {
      throw std::runtime_error("3D patch: a section's lateral contact failed: " + sol.message);
    }
    return sol;
  }

  struct Section {
    std::vector<char> active;
    std::vector<int> cells;
    Eigen::VectorXd a, b;
    double c = 0, o = 0;
  };
  void set_pattern(int i, const std::vector<char>& active) {
    Section& s = sec_[i];
    s.active = active;
    s.cells.clear();
    for (int j = 0; j < int(active.size()); ++j) {
      if (active[j]) s.cells.push_back(j);
    }
    const int m = static_cast<int>(s.cells.size());
    Eigen::MatrixXd M(m, m);
    Eigen::VectorXd zA(m);
    for (int p = 0; p < m; ++p) {
      zA(p) = z_(s.cells[p]);
      for (int q = 0; q < m; ++q) M(p, q) = G_(s.cells[p], s.cells[q]);
      M(p, p) += t_[i];
    }
    const Eigen::LLT<Eigen::MatrixXd> llt(M);
    s.a = llt.solve(Eigen::VectorXd::Ones(m));
    s.b = llt.solve(zA);
    s.c = 1 / s.a.sum();
    s.o = s.b.sum() * s.c;
  }

  std::vector<double> t_;
  Eigen::VectorXd z_;
  const Eigen::MatrixXd& G_;
  solvers::ContactOptions opt_;
  double zmin_ = 0;
  std::vector<Section> sec_;
};

}  // namespace

std::unique_ptr<SectionLaws> rigid_sections(const std::vector<double>& t,
                                            const std::vector<double>& z) {
  return std::make_unique<Rigid>(t, z);
}

std::unique_ptr<SectionLaws> flexible_sections(const std::vector<double>& t,
                                               const std::vector<double>& z,
                                               const Eigen::MatrixXd& G, int max_iterations) {
  return std::make_unique<Flexible>(t, z, G, max_iterations);
}

}  // namespace modaltyre::contact::detail
