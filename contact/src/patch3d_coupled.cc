// The 3D patch with a shear-coupled tread (tread_coupling, patch3d.h): every cell an unknown of
// one load-controlled contact problem, the cell compliance C_carcass (between the sections'
// resultants) + the coupled tread (patch3d_tread.cc) + each cell's tangential tread part (+ the
// lateral belt), by the active-set solver (conjugate gradients on the contact cells). It starts
// from the cells in contact of the uncoupled reduction at the same load (the exact solution
// without the layer's shear, one cheap solve).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "modaltyre/contact/patch3d.h"
#include "modaltyre/solvers/unilateral_contact.h"
#include "patch3d_operators.h"

namespace modaltyre::contact {

void Patch3d::coupled_compression(const std::vector<double>& f, std::vector<double>& u,
                                  std::vector<double>& own, std::vector<double>& radial) const {
  const int S = sections(), ny = columns(), n = S * ny;
  Eigen::MatrixXd F = Eigen::Map<const Eigen::VectorXd>(f.data(), n);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, 1);
  tread_->add_product(0, n, 0, n, F, T);
  u.resize(n), own.resize(n), radial.resize(n);
  for (int i = 0; i < S; ++i) {
    const double c = std::cos(model_.theta[i]);
    for (int j = 0; j < ny; ++j) {
      const std::size_t a = std::size_t(i) * ny + j;
      u[a] = T(a, 0) + t_tangential_[i] * f[a];
      own[a] = c * c * tread_->own(j) + t_tangential_[i];
      radial[a] = c != 0 ? T(a, 0) / c : 0.0;
    }
  }
}

Patch3dResult Patch3d::solve_coupled(double load_N, std::span<const char> warm,
                                     const Eigen::VectorXd& extra, detail::SectionLaws* laws,
                                     bool sections_only) const {
  const int S = sections(), ny = columns();
  // The uncoupled reduction: its cells in contact start the coupled solve.
  const Patch3dResult start = solve_reduced(load_N, warm, extra, laws, true);
  if (!start.ok()) return start;
  // The coupled set predicted from it: a cell stays in contact if its penetration at the
  // uncoupled approach exceeds what its neighbours' forces compress it by through the layer
  // (one product; the set the solver then corrects is closer than the uncoupled one).
  std::vector<double> u, own, radial;
  coupled_compression(start.cell_force_N, u, own, radial);
  std::vector<char> active(std::size_t(S) * ny);
  for (int i = 0; i < S; ++i) {
    for (int j = 0; j < ny; ++j) {
      const std::size_t a = std::size_t(i) * ny + j;
      const double neighbours = u[a] - own[a] * start.cell_force_N[a];
      active[a] =
          start.cell_force_N[a] > 0 && start.section_approach_m[i] - z_m_[j] - neighbours > 0;
    }
  }

  const solvers::WeightedToeplitzCompliance carcass = *carcass_;
  const detail::CellCompliance op(carcass, ny, t_tangential_, G_.size() ? &G_ : nullptr,
                                  tread_.get());
  solvers::ContactProblem p;
  p.compliance_operator = &op;
  p.initial_gap.resize(std::size_t(S) * ny);
  const bool loaded = extra.size() > 0;
  Eigen::VectorXd offset = Eigen::VectorXd::Zero(S);
  if (loaded) {  // the sidewalls' lost loads move the sections: a gap offset C extra
    Eigen::MatrixXd out(S, 1);
    carcass.apply(0, S, 0, S, extra, out);
    offset = out.col(0);
  }
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < ny; ++j)
      p.initial_gap(std::size_t(i) * ny + j) = model_.sag(i) + z_m_[j] + offset(i);
  p.load_N = load_N;
  solvers::ContactOptions opt;
  opt.max_iterations = model_.config.solver.max_iterations;
  opt.gap_tolerance = model_.config.solver.gap_tolerance;
  const solvers::ContactSolution s = solvers::solve_unilateral_contact(p, opt, active);
  Patch3dResult r;
  r.load_N = load_N;
  r.contact_iterations = start.contact_iterations + s.iterations;
  r.pattern_iterations = start.pattern_iterations;
  if (!s.ok()) {
    r.status = s.status;
    r.message = "coupled tread: " + s.message;
    return r;
  }
  std::ostringstream msg;
  msg << "coupled tread: converged in " << s.iterations << " active-set iterations over the cells";
  r.message = msg.str();
  std::vector<double> f(s.force.data(), s.force.data() + s.force.size());
  for (double& v : f) v = std::max(v, 0.0);
  return finish(load_N, f, s.approach_m, extra, std::move(r), sections_only);
}

}  // namespace modaltyre::contact
