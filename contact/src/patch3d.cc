#include "modaltyre/contact/patch3d.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/solvers/unilateral_contact.h"
#include "patch3d_operators.h"
#include "patch3d_sections.h"

namespace modaltyre::contact {
namespace {

/// C F over every section.
Eigen::VectorXd carcass_product(const solvers::ComplianceOperator& C, const Eigen::VectorXd& F) {
  const int S = C.size();
  Eigen::MatrixXd out(S, 1);
  C.apply(0, S, 0, S, F, out);
  return out.col(0);
}

solvers::ContactOptions contact_options(const TyreModel& m) {
  solvers::ContactOptions o;
  o.max_iterations = m.config.solver.max_iterations;
  o.gap_tolerance = m.config.solver.gap_tolerance;
  return o;
}

}  // namespace

Patch3d::Patch3d(const TyreModel& model, Patch3dSettings settings, const Patch3dPhysics& physics)
    : model_(model),
      settings_(std::move(settings)),
      kernels_(physics.kernels ? *physics.kernels : model.kernels) {
  if (!(physics.carcass_scale > 0) || !(physics.tread_creep > 0) || !(physics.soil_m_per_Pa >= 0)) {
    throw std::invalid_argument("3D patch: carcass scale and tread creep must be > 0, soil >= 0");
  }
  if (physics.carcass_scale != 1.0) {
    for (auto* k : {&kernels_.r_from_r, &kernels_.r_from_t, &kernels_.t_from_r, &kernels_.t_from_t})
      for (double& v : *k) v *= physics.carcass_scale;
  }
  // The carcass-only vertical compliance of the sections (the 2D model's with the tread springs
  // rigid); on the model's own kernels the model's operator, whose spectra every load shares.
  const bool own = physics.kernels == nullptr && physics.carcass_scale == 1.0;
  carcass_ = std::make_shared<const solvers::WeightedToeplitzCompliance>(
      carcass_compliance_operator(model_, own ? nullptr : &kernels_, physics.rolling));
  const auto& s = settings_;
  if (!(s.tread_width_m > 0) || !(s.lateral_cell_m > 0)) {
    throw std::invalid_argument("3D patch: tread width and lateral cell must be > 0");
  }
  const double columns = std::round(s.tread_width_m / s.lateral_cell_m);
  if (columns > 2000) throw std::invalid_argument("3D patch: more than 2000 columns");
  s.crown.validate();
  const int n = std::max(1, static_cast<int>(columns));
  const double dy = s.tread_width_m / n;
  const double half = 0.5 * s.tread_width_m;
  if (half >= s.crown.reach_m()) {
    throw std::invalid_argument("3D patch: the crown profile turns vertical inside the tread");
  }
  for (int j = 0; j < n; ++j) {
    y_m_.push_back(-half + (j + 0.5) * dy);
    z_m_.push_back(s.crown.drop_m(y_m_.back()));
  }
  const TreadParams& T = physics.tread ? *physics.tread : model_.config.tread;
  // Seed 001 eq. (6)-(9) for a cell of dy x ds; creeping by the given factor
  // (seed 001 eq. 10, tread_relaxation).
  const double ds = model_.unit_length_m;
  const TreadSprings k = tread_springs(T, dy, ds);
  k_radial_cell_ = k.radial_N_m / physics.tread_creep;
  k_tangential_cell_ = k.tangential_N_m / physics.tread_creep;
  for (double th : model_.theta) {
    const double c = std::cos(th), sn = std::sin(th);
    double t = c * c / k_radial_cell_ + sn * sn / k_tangential_cell_;
    // Winkler soil under the cell (road area dy ds cos theta), in series with the tread.
    if (physics.soil_m_per_Pa > 0) t += physics.soil_m_per_Pa / (dy * ds * c);
    t_.push_back(t);
  }
  if (s.sidewall.enabled) {
    s.sidewall.validate();
    pressure_Pa_ = physics.inflation_pressure_Pa >= 0 ? physics.inflation_pressure_Pa
                                                      : model_.config.inflation_pressure_Pa;
  }
  if (physics.soil) {
    if (s.lateral_belt.enabled)
      throw std::invalid_argument("3D patch: a soil with a lateral belt is not built");
    soil_ = physics.soil;
    for (double th : model_.theta) cell_area_m2_.push_back(dy * ds * std::cos(th));
  }
  symmetric_ = !physics.rolling;
  if (physics.tread_coupling_m > 0) {
    if (physics.soil)
      throw std::invalid_argument("3D patch: a soil under a coupled tread is not built");
    if (physics.rolling) {
      // The non-symmetric cell problem would need a dense LU of every cell in contact.
      throw std::invalid_argument(
          "3D patch: a coupled tread on a rolling carcass is not built (every cell in contact "
          "would be one non-symmetric dense system)");
    }
    std::vector<double> cos_theta;
    for (double th : model_.theta) {
      cos_theta.push_back(std::cos(th));
      t_tangential_.push_back(std::sin(th) * std::sin(th) / k_tangential_cell_);
    }
    tread_ = std::make_shared<const detail::CoupledTread>(k_radial_cell_, physics.tread_coupling_m,
                                                          ds, dy, sections(), n, cos_theta);
  }
  if (s.lateral_belt.enabled) {
    if (n > kMaxLateralBeltColumns) {
      throw std::invalid_argument("3D patch: a lateral belt supports at most " +
                                  std::to_string(kMaxLateralBeltColumns) + " columns");
    }
    G_ = lateral_belt_compliance(s.lateral_belt, s.tread_width_m, n, model_.unit_length_m);
  }
}

Patch3dResult Patch3d::solve(double load_N, std::span<const char> warm,
                             std::span<const double> warm_cells) const {
  const SidewallMembrane& wall = settings_.sidewall;
  if (!wall.enabled || pressure_Pa_ == 0) {
    if (warm_cells.empty()) return solve_loaded(load_N, warm, {});
    const std::unique_ptr<detail::SectionLaws> laws = section_laws(warm_cells);
    return solve_loaded(load_N, warm, {}, laws.get());
  }
  // Fixed point x = G(x) on the sections' lost sidewall loads x = e ds (sidewall_membrane.h):
  // G solves the contact with x fixed and returns e(u) ds from the sections' carcass
  // displacement u_i = delta - sag_i - d_i = (C (F + x))_i. Converged when the gap offset moves
  // by C (G(x) - x) <= tolerance x sinking. Anderson mixing over the last few steps
  // (settings.sidewall_anderson_depth; 0 = the plain iteration x <- G(x)) takes the next x as
  // the combination of the recent G(x_j) whose residuals G(x_j) - x_j cancel best.
  const int S = sections();
  const double ds = model_.unit_length_m;
  const solvers::WeightedToeplitzCompliance carcass = *carcass_;
  const int depth = std::max(0, settings_.sidewall_anderson_depth);
  const SidewallLostForce lost(wall, pressure_Pa_);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(S), g(S);
  std::vector<Eigen::VectorXd> xs, gs;  // recent iterates and their images, oldest first
  std::vector<char> active(warm.begin(), warm.end());
  // One set of section laws for every step: each starts from the lateral patterns the last one
  // ended with (the steps' solutions differ little), not from every cell.
  const std::unique_ptr<detail::SectionLaws> laws = section_laws(warm_cells);
  bool mixed = false;  // x came from Anderson mixing, not from a plain step
  for (int it = 1; it <= settings_.max_sidewall_iterations; ++it) {
    Patch3dResult r = solve_loaded(load_N, active, x, laws.get(), true);
    r.sidewall_iterations = it;
    if (!r.ok()) return r;
    active = r.section_active;
    for (int i = 0; i < S; ++i) {
      const double u = r.sinking_m - model_.sag(i) - r.section_approach_m[i];
      g(i) = lost(u) * ds;
    }
    if (!g.allFinite()) {
      if (mixed) {  // a mixed step left the meridian's range: restart from the plain step
        x = gs.back();
        xs.clear();
        gs.clear();
        mixed = false;
        continue;
      }
      r.status = SolveStatus::failed;
      r.message = "sidewall softening: a section's displacement leaves the meridian's range";
      return r;
    }
    const double change = carcass_product(carcass, g - x).cwiseAbs().maxCoeff();
    if (change <= settings_.sidewall_tolerance * std::abs(r.sinking_m)) {
      r.message += "; sidewall softening converged in " + std::to_string(it) + " steps";
      const std::vector<double> f = r.cell_force_N;
      const double delta = r.sinking_m;
      return finish(load_N, f, delta, x, std::move(r));  // the whole result of this step
    }
    xs.push_back(x);
    gs.push_back(g);
    if (static_cast<int>(xs.size()) > depth + 1) {
      xs.erase(xs.begin());
      gs.erase(gs.begin());
    }
    x = g;
    const int n = static_cast<int>(xs.size()) - 1;
    if (n > 0) {
      // min |f_k - dF gamma|, f_j = G(x_j) - x_j, dF's columns f_{j+1} - f_j; then
      // x = G(x_k) - dG gamma with dG's columns G(x_{j+1}) - G(x_j).
      Eigen::MatrixXd dF(S, n), dG(S, n);
      for (int j = 0; j < n; ++j) {
        dF.col(j) = (gs[j + 1] - xs[j + 1]) - (gs[j] - xs[j]);
        dG.col(j) = gs[j + 1] - gs[j];
      }
      const Eigen::VectorXd gamma = dF.colPivHouseholderQr().solve(gs[n] - xs[n]);
      mixed = gamma.allFinite();
      if (mixed) x -= dG * gamma;
    }
  }
  Patch3dResult r;
  r.load_N = load_N;
  r.status = SolveStatus::max_iterations;
  r.message = "sidewall softening did not converge in " +
              std::to_string(settings_.max_sidewall_iterations) + " steps";
  return r;
}

std::unique_ptr<detail::SectionLaws> Patch3d::section_laws(
    std::span<const double> warm_cells) const {
  auto laws = soil_ ? detail::soil_sections(t_, z_m_, *soil_, cell_area_m2_)
              : G_.size()
                  ? detail::flexible_sections(t_, z_m_, G_, contact_options(model_).max_iterations)
                  : detail::rigid_sections(t_, z_m_);
  const int S = sections(), ny = columns();
  if (static_cast<int>(warm_cells.size()) == S * ny) {
    for (int i = 0; i < S; ++i) {
      const double* f = warm_cells.data() + std::size_t(i) * ny;
      if (std::any_of(f, f + ny, [](double v) { return v > 0; })) laws->start_from(i, f);
    }
  }
  return laws;
}

Patch3dResult Patch3d::solve_loaded(double load_N, std::span<const char> warm,
                                    const Eigen::VectorXd& extra, detail::SectionLaws* laws,
                                    bool sections_only) const {
  return tread_ ? solve_coupled(load_N, warm, extra, laws, sections_only)
                : solve_reduced(load_N, warm, extra, laws, sections_only);
}

Patch3dResult Patch3d::solve_reduced(double load_N, std::span<const char> warm,
                                     const Eigen::VectorXd& extra, detail::SectionLaws* given_laws,
                                     bool sections_only) const {
  MODALTYRE_CHECK(load_N > 0, "load must be positive");
  const int S = sections(), ny = columns();
  const solvers::WeightedToeplitzCompliance carcass = *carcass_;
  const auto opt = contact_options(model_);
  std::unique_ptr<detail::SectionLaws> own_laws;
  if (!given_laws) own_laws = section_laws();
  detail::SectionLaws* const laws = given_laws ? given_laws : own_laws.get();
  Patch3dResult r;
  r.load_N = load_N;
  // The extra carcass loads' gap offset C extra (sidewall softening; empty: none).
  const bool loaded = extra.size() > 0;
  const Eigen::VectorXd offset = loaded ? carcass_product(carcass, extra) : Eigen::VectorXd();

  // The objective J(F) of the reduction; `update` moves the lateral patterns to F's.
  auto energies = [&](const Eigen::VectorXd& F, bool update) {
    double e = 0;
    for (int i = 0; i < S; ++i) e += laws->energy(i, std::max(F(i), 0.0), update);
    return e;
  };
  auto objective = [&](const Eigen::VectorXd& F) {
    const double linear = loaded ? (model_.sag + offset).dot(F) : model_.sag.dot(F);
    return 0.5 * F.dot(carcass_product(carcass, F)) + linear + energies(F, false);
  };

  // The rolling carcass's merit: sum_i min(c_i F_i, w_i)^2, w_i the section's gap at F and the
  // approach delta (the load equation holds along every step).
  auto natural_residual = [&](const Eigen::VectorXd& F, double delta) {
    const Eigen::VectorXd CF = carcass_product(carcass, F);
    double sum = 0;
    for (int i = 0; i < S; ++i) {
      const double Fi = std::max(F(i), 0.0);
      double w = model_.sag(i) + CF(i) + laws->approach(i, Fi) - delta;
      if (loaded) w += offset(i);
      const double r = std::min(t_[i] / ny * Fi, w);
      sum += r * r;
    }
    return sum;
  };

  Eigen::VectorXd F;  // current iterate (empty before the first step)
  double delta = 0;   // its approach (the rolling carcass's iteration)
  std::vector<char> active(warm.begin(), warm.end());
  const double gtol_rel = model_.config.solver.gap_tolerance;
  for (int it = 1; it <= settings_.max_pattern_iterations; ++it) {
    r.pattern_iterations = it;
    std::vector<double> diag(S);
    Eigen::VectorXd gap0(S);
    for (int i = 0; i < S; ++i) {
      double drop = 0;
      laws->reduced(i, diag[i], drop);
      gap0(i) = model_.sag(i) + drop;
      if (loaded) gap0(i) += offset(i);
    }
    const detail::DiagonalShifted op(carcass, std::move(diag));
    solvers::ContactProblem p;
    p.compliance_operator = &op;
    p.initial_gap = gap0;
    p.load_N = load_N;
    p.symmetric = symmetric_;
    const solvers::ContactSolution s = solvers::solve_unilateral_contact(p, opt, active);
    r.contact_iterations += s.iterations;
    if (!s.ok()) {
      r.status = s.status;
      r.message = s.message;
      return r;
    }
    active = s.active;
    // Consistency of the pattern with the step's approaches d_i = delta - sag_i - (C F)_i.
    const Eigen::VectorXd& Fh = s.force;
    const Eigen::VectorXd CF = carcass_product(carcass, Fh);
    Eigen::VectorXd d(S);
    for (int i = 0; i < S; ++i) d(i) = s.approach_m - model_.sag(i) - CF(i);
    if (loaded) d -= offset;
    const double tol = gtol_rel * std::max(std::abs(s.approach_m), 1e-12);
    bool consistent = true;
    for (int i = 0; i < S && consistent; ++i) consistent = laws->consistent(i, Fh(i), d(i), tol);
    if (consistent) {
      std::vector<double> f(std::size_t(S) * ny, 0.0);
      for (int i = 0; i < S; ++i) {
        if (Fh(i) > 0) laws->cell_forces(i, d(i), &f[std::size_t(i) * ny]);
      }
      std::ostringstream msg;
      msg << "converged in " << it << " lateral-pattern steps (" << r.contact_iterations
          << " active-set iterations)";
      r.message = msg.str();
      return finish(load_N, f, s.approach_m, extra, std::move(r), sections_only);
    }
    // Newton step on J towards the step's forces, backtracked while J does not decrease (the
    // rolling carcass: while the natural residual does not).
    if (F.size() == 0) {
      F = Fh;
      delta = s.approach_m;
    } else if (symmetric_) {
      const Eigen::VectorXd dF = Fh - F;
      const double j0 = objective(F);
      double alpha = 1;
      for (int k = 0; k < 40 && objective(F + alpha * dF) > j0; ++k) alpha *= 0.5;
      F += alpha * dF;
    } else {
      const Eigen::VectorXd dF = Fh - F;
      const double dd = s.approach_m - delta, m0 = natural_residual(F, delta);
      double alpha = 1;
      for (int k = 0;
           k < 40 && natural_residual(F + alpha * dF, delta + alpha * dd) > (1 - 1e-4 * alpha) * m0;
           ++k)
        alpha *= 0.5;
      F += alpha * dF;
      delta += alpha * dd;
    }
    energies(F, true);
  }
  r.status = SolveStatus::max_iterations;
  r.message = "lateral contact pattern did not settle in " +
              std::to_string(settings_.max_pattern_iterations) + " steps";
  return r;
}

Patch3dResult Patch3d::solve_cells(double load_N) const {
  MODALTYRE_CHECK(load_N > 0, "load must be positive");
  if (soil_) {
    Patch3dResult r;
    r.load_N = load_N;
    r.message = "solve_cells (the reduction's reference) takes no soil";
    return r;
  }
  const int S = sections(), ny = columns();
  const solvers::WeightedToeplitzCompliance carcass = *carcass_;
  const detail::CellCompliance op(carcass, ny, t_, G_.size() ? &G_ : nullptr);
  solvers::ContactProblem p;
  p.compliance_operator = &op;
  p.initial_gap.resize(std::size_t(S) * ny);
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < ny; ++j) p.initial_gap(std::size_t(i) * ny + j) = model_.sag(i) + z_m_[j];
  p.load_N = load_N;
  const solvers::ContactSolution s = solvers::solve_unilateral_contact(p, contact_options(model_));
  Patch3dResult r;
  r.load_N = load_N;
  r.contact_iterations = s.iterations;
  r.message = s.message;
  if (!s.ok()) {
    r.status = s.status;
    return r;
  }
  std::vector<double> f(s.force.data(), s.force.data() + s.force.size());
  return finish(load_N, f, s.approach_m, {}, std::move(r));
}

std::vector<Patch3dResult> Patch3d::solve_all(const std::vector<double>& loads_N) const {
  std::vector<Patch3dResult> out;
  for (double F : loads_N) {
    const bool warm = !out.empty() && out.back().ok();
    out.push_back(solve(
        F, warm ? std::span<const char>(out.back().section_active) : std::span<const char>()));
  }
  return out;
}

double Patch3d::lateral_half_width(const Patch3dResult& r, int i,
                                   const std::vector<double>& shift) const {
  // The level function e_j = d_i - z_j - v_ij across the section (tread compression inside,
  // minus the gap outside; v the shift), linear between the column centres: its outermost zero
  // on each side; the tread edge if the outermost column is in contact.
  const int ny = columns();
  const double half = 0.5 * settings_.tread_width_m;
  auto level = [&](int j) {
    return r.section_approach_m[i] - z_m_[j] - shift[std::size_t(i) * ny + j];
  };
  auto in_contact = [&](int j) { return r.cell_force(i, j) > 0; };
  int lo = 0, hi = ny - 1;
  while (lo < ny && !in_contact(lo)) ++lo;
  while (hi >= 0 && !in_contact(hi)) --hi;
  if (lo > hi) return 0;
  auto edge = [&](int in, int out) {
    const double ein = level(in), eout = level(out);
    return y_m_[in] + ein / (ein - eout) * (y_m_[out] - y_m_[in]);
  };
  if (!G_.size()) {
    // A laterally rigid belt (the coupled tread): the crown itself between the column centres,
    // the shift linear, so that without a shift the edge is the reduction's crown inverse.
    const double d = r.section_approach_m[i];
    auto shift_at = [&](int j) { return shift[std::size_t(i) * ny + j]; };
    auto crown_edge = [&](int in, int out) {
      const double y0 = std::abs(y_m_[in]), y1 = std::abs(y_m_[out]);
      auto phi = [&](double y) {
        const double s = shift_at(in) + (y - y0) / (y1 - y0) * (shift_at(out) - shift_at(in));
        return d - settings_.crown.drop_m(y) - s;
      };
      double a = y0, b = y1;
      for (int k = 0; k < 100 && b - a > 1e-15; ++k)
        (phi(0.5 * (a + b)) > 0 ? a : b) = 0.5 * (a + b);
      return 0.5 * (a + b);
    };
    auto outer = [&](int j) {  // the outermost column in contact: up to the tread edge
      return std::min(settings_.crown.half_width_m(d - shift_at(j)), half);
    };
    const double right = hi == ny - 1 ? outer(hi) : crown_edge(hi, hi + 1);
    const double left = lo == 0 ? outer(lo) : crown_edge(lo, lo - 1);
    return 0.5 * (right + left);
  }
  const double right = hi == ny - 1 ? half : edge(hi, hi + 1);
  const double left = lo == 0 ? -half : edge(lo, lo - 1);
  return 0.5 * (right - left);
}

Patch3dResult Patch3d::finish(double load_N, const std::vector<double>& f, double delta,
                              const Eigen::VectorXd& extra, Patch3dResult r,
                              bool sections_only) const {
  const int S = sections(), ny = columns();
  const TyreModel& m = model_;
  r.sections = S;
  r.columns = ny;
  r.dy_m = settings_.tread_width_m / ny;
  r.y_m = y_m_;
  r.column_drop_m = z_m_;
  r.cell_force_N = f;
  r.sinking_m = delta;
  Eigen::VectorXd F = Eigen::VectorXd::Zero(S);
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < ny; ++j) F(i) += f[std::size_t(i) * ny + j];
  if (F(0) > 0 || F(S - 1) > 0) {
    std::ostringstream msg;
    msg << "contact reached the edge of the candidate window (+-" << 0.5e3 * m.config.mesh.window_m
        << " mm): increase contact.window_mm (e.g. to " << suggested_window_mm(m.config) << ")";
    r.message = msg.str();
    r.status = SolveStatus::failed;
    return r;
  }
  const solvers::WeightedToeplitzCompliance carcass = *carcass_;
  // The carcass carries the contact forces and the extra loads (sidewall softening).
  const bool loaded = extra.size() > 0;
  const Eigen::VectorXd CF = carcass_product(carcass, loaded ? Eigen::VectorXd(F + extra) : F);
  r.section_force_N.assign(F.data(), F.data() + S);
  if (loaded) r.sidewall_force_N.assign(extra.data(), extra.data() + S);
  r.section_approach_m.resize(S);
  r.section_active.resize(S);
  if (sections_only) {  // a fixed-point step: the sections' approaches are all it reads
    for (int i = 0; i < S; ++i) {
      r.section_approach_m[i] = delta - m.sag(i) - CF(i);
      r.section_active[i] = F(i) > 0;
    }
    r.status = std::isfinite(r.sinking_m) ? SolveStatus::converged : SolveStatus::failed;
    return r;
  }
  // The belt's lateral deflection of each cell, G f_i (zero for the laterally rigid belt).
  r.belt_deflection_m.assign(std::size_t(S) * ny, 0.0);
  if (G_.size()) {
    for (int i = 0; i < S; ++i) {
      if (!(F(i) > 0)) continue;
      const Eigen::Map<const Eigen::VectorXd> fi(&f[std::size_t(i) * ny], ny);
      Eigen::Map<Eigen::VectorXd>(&r.belt_deflection_m[std::size_t(i) * ny], ny) = G_ * fi;
    }
  }
  // What else separates a cell from the road at its section's approach: the belt's deflection
  // and, for the coupled tread, the compression its neighbours' forces cause (u - own f).
  std::vector<double> shift = r.belt_deflection_m, u, own, radial;
  if (tread_) {
    coupled_compression(f, u, own, radial);
    for (std::size_t k = 0; k < shift.size(); ++k) shift[k] += u[k] - own[k] * f[k];
  }
  double total = 0, comp = 0, pen = 0;
  if (soil_) r.soil_depth_m.assign(std::size_t(S) * ny, 0.0);
  for (int i = 0; i < S; ++i) {
    r.section_approach_m[i] = delta - m.sag(i) - CF(i);
    r.section_active[i] = F(i) > 0;
    for (int j = 0; j < ny; ++j) {
      const double fij = f[std::size_t(i) * ny + j];
      double soil = 0;  // the soil's sinkage under the cell, in series with its tread
      if (soil_) {
        soil = soil_->sinkage_m(fij / cell_area_m2_[i], 0.0);
        r.soil_depth_m[std::size_t(i) * ny + j] = soil;
        if (fij > 0) r.soil_sinkage_m = std::max(r.soil_sinkage_m, soil);
      }
      const double tread = tread_ ? u[std::size_t(i) * ny + j] : t_[i] * fij;
      const double g = m.sag(i) + z_m_[j] + CF(i) + r.belt_deflection_m[std::size_t(i) * ny + j] +
                       tread + soil - delta;
      total += fij;
      comp = std::max(comp, std::abs(fij * g));
      pen = std::max(pen, -g);
    }
  }
  r.equilibrium_residual = std::abs(total - load_N) / load_N;
  r.complementarity_residual = comp / (load_N * std::max(std::abs(delta), 1e-12));
  r.max_penetration_m = std::max(pen, 0.0);

  // Deformed positions (seed 001 eq. 1, 6, 12): the belt section moved by the carcass, each
  // cell's surface further by its own tread.
  const auto& K = kernels_;
  const solvers::LagConvolution2x2 H({K.r_from_r, K.r_from_t, K.t_from_r, K.t_from_t}, K.lags);
  std::vector<double> fr(S), ft(S), ur(S), ut(S);
  for (int i = 0; i < S; ++i) {
    const double Fi = loaded ? F(i) + extra(i) : F(i);
    fr[i] = Fi * std::cos(m.theta[i]), ft[i] = Fi * std::sin(m.theta[i]);
  }
  H.apply(0, S, 0, S, fr.data(), ft.data(), ur.data(), ut.data());
  const double R0 = m.config.outer_radius_m;
  // A cell's surface: its radial tread compression (the coupled tread's, with the neighbours'
  // share, or its own spring's) and its tangential shear.
  auto cell_x = [&](int i, double fij, std::size_t cell) {
    const double c = std::cos(m.theta[i]), sn = std::sin(m.theta[i]);
    const double radial_compression = tread_ ? radial[cell] : fij * c / k_radial_cell_;
    return (R0 - ur[i] - radial_compression) * sn + (ut[i] + fij * sn / k_tangential_cell_) * c;
  };
  r.x_m.resize(S);
  r.dx_m.resize(S);
  r.half_width_m.assign(S, 0.0);
  for (int i = 0; i < S; ++i) {
    for (int j = 0; j < ny && F(i) > 0; ++j) {
      const std::size_t a = std::size_t(i) * ny + j;
      if (f[a] > 0) r.force_moment_Nm += f[a] * cell_x(i, f[a], a);
    }
  }
  const double half = 0.5 * settings_.tread_width_m;
  for (int i = 0; i < S; ++i) {
    // The belt's position (the cell's without its tread).
    r.x_m[i] = (R0 - ur[i]) * std::sin(m.theta[i]) + ut[i] * std::cos(m.theta[i]);
    r.dx_m[i] = m.unit_length_m * std::cos(m.theta[i]);
    if (!(F(i) > 0)) continue;
    if (G_.size() || tread_) {
      r.half_width_m[i] = lateral_half_width(r, i, shift);
    } else {
      r.half_width_m[i] = std::min(settings_.crown.half_width_m(r.section_approach_m[i]), half);
    }
    r.width_m = std::max(r.width_m, 2 * r.half_width_m[i]);
  }
  // Longitudinal edges per column: the level function d_i - z_j - v_ij (the cell's tread
  // compression inside, minus its gap outside; v the belt's lateral deflection) interpolated
  // linearly to zero between the sections.
  r.column_edges.assign(ny, {});
  for (int j = 0; j < ny; ++j) {
    int first = -1, last = -1;
    for (int i = 0; i < S; ++i) {
      if (f[std::size_t(i) * ny + j] > 0) {
        if (first < 0) first = i;
        last = i;
      }
    }
    if (first < 0) continue;
    auto edge = [&](int in, int out) {
      const std::size_t a = std::size_t(in) * ny + j, b = std::size_t(out) * ny + j;
      const double pin = r.section_approach_m[in] - z_m_[j] - shift[a];
      const double pout = r.section_approach_m[out] - z_m_[j] - shift[b];
      const double xin = cell_x(in, f[a], a), xout = cell_x(out, 0.0, b);
      return xin + pin / (pin - pout) * (xout - xin);
    };
    ColumnEdges& e = r.column_edges[j];
    e.contact = true;
    e.rear_x_m = edge(first, first - 1);
    e.front_x_m = edge(last, last + 1);
    r.length_m = std::max(r.length_m, e.front_x_m - e.rear_x_m);
  }
  r.status = std::isfinite(r.sinking_m) && std::isfinite(r.length_m) ? SolveStatus::converged
                                                                     : SolveStatus::failed;
  if (!r.ok()) r.message = "3D patch result is not finite";
  return r;
}

}  // namespace modaltyre::contact
