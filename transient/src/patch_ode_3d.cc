// The 3D patch's ODE for the run loop and the driven tyre (patch_ode.h): CellSystem with
// CellNewton, its output samples with the width and the contact area, and the pressure maps.
#include <algorithm>
#include <cmath>

#include "cell_kernels.h"
#include "modaltyre/transient/cell_newton.h"
#include "modaltyre/transient/cell_soil.h"
#include "modaltyre/transient/cell_system.h"
#include "patch_ode.h"

namespace modaltyre::transient::detail {
namespace {

/// CVODE's own Newton convergence coefficient (CellsOde::newton_convergence_coefficient).
constexpr double kCvodeNewtonCoefficient = 0.1;

/// Observables of one state: the 2D sample's (driver.h) plus width and area, and on request the
/// pressure map. Work vectors are the caller's (reused across samples).
class CellObserver {
 public:
  CellObserver(const CellSystem& sys) : sys_(sys), cm_(sys.cell_model()), M_(cm_.M()) {
    sag_min_ = M_.tyre.sag.minCoeff();
    cos_.resize(M_.m);
    sin_.resize(M_.m);
    for (int i = 0; i < M_.m; ++i)
      cos_[i] = std::cos(M_.tyre.theta[i]), sin_[i] = std::sin(M_.tyre.theta[i]);
    stamp_.assign(M_.m, 0);
    // The shapes transposed: belt() reads one section's row, contiguous here (a row of the
    // m x nq column-major matrices strides over nq cache lines).
    phi_r_t_ = M_.phi_r.transpose();
    phi_t_t_ = M_.phi_t.transpose();
    ur_.assign(M_.m, 0.0);
    ut_.assign(M_.m, 0.0);
    // The first and the last column of each class (the lateral edge search).
    const CellClasses& C = cm_.classes;
    class_col_lo_.assign(C.size(), C.columns);
    class_col_hi_.assign(C.size(), -1);
    for (int j = 0; j < C.columns; ++j) {
      const int c = C.column_class[j];
      class_col_lo_[c] = std::min(class_col_lo_[c], j);
      class_col_hi_[c] = std::max(class_col_hi_[c], j);
    }
  }

  /// forces_only: the load, the longitudinal force and the hub (the step extremes,
  /// step_extremes.h), without the soil's, the edges' and the width's passes; `accepted`: from
  /// the forces update_contact_set() computed at this (accepted) state when it did.
  TransientSample observe(double t, const double* y, CellMap* map = nullptr,
                          bool forces_only = false, bool accepted = false) {
    const ScenarioPlan& plan = sys_.plan();
    const CellClasses& C = cm_.classes;
    TransientSample s;
    s.t_s = t;
    // f, F and (one pass) the tip penetration g and the undeformed tread's penetration at the
    // crown line P.
    const Eigen::VectorXd *fp = &f_, *Fp = &F_;
    if (forces_only && accepted && sys_.accepted_forces(t, fp, Fp)) {
      // (the forces the contact-set update computed at this state: no second pass)
    } else if (forces_only) {
      sys_.forces(t, y, f_, F_);
    } else {
      sys_.forces(t, y, f_, F_, &g_, &P_);
    }
    const double z = sys_.hub_z(t, y);
    const double R0 = M_.tyre.config.outer_radius_m;
    s.applied_load_N = plan.load(t);
    s.hub_displacement_m = z;
    s.speed_m_s = plan.speed(t);
    const Eigen::VectorXd &fv = *fp, &Fv = *Fp;
    const UnitRange span = sys_.sections();
    double load = 0, moment = 0, slope_force = 0, sink = z - sag_min_;
    int sections = 0, first = -1, last = -1;
    for (int i = span.lo; i <= span.hi; ++i) {
      if (!(Fv(i) > 0)) continue;
      load += Fv(i);
      moment += Fv(i) * M_.x_road(i);
      ++sections;
      first = first < 0 ? i : first;
      last = i;
    }
    if (plan.has_road() && span.size() > 0) {
      // The road's height and slope once per section (CellSystem::road() is the same for every
      // class it covers, 0 for the others): a cleat's cosine per slot was 5 % of its run.
      int road_class = -1;
      for (int c = 0; c < C.size() && road_class < 0; ++c)
        if (on_road(c)) road_class = c;
      road_h_.resize(span.size());
      road_s_.resize(span.size());
      // The sections where the road is raised or sloped ([lo, hi]; elsewhere h = 0 and a zero
      // slope adds nothing).
      // Forces only: the slope force needs the sections in contact only.
      int lo = span.hi + 1, hi = span.lo - 1;
      const int k0 = forces_only ? std::max(first - span.lo, 0) : 0;
      const int k1 = forces_only ? last - span.lo : span.size() - 1;
      if (road_class >= 0 && k1 >= k0)
        sys_.road_heights(t, span.lo + k0, k1 - k0 + 1, road_class, road_h_.data() + k0,
                          road_s_.data() + k0);
      for (int k = k0; road_class >= 0 && k <= k1; ++k) {
        if (road_h_[k] > 0 || road_s_[k] != 0)
          lo = std::min(lo, span.lo + k), hi = std::max(hi, span.lo + k);
      }
      for (int c = 0; c < C.size() && road_class >= 0; ++c) {
        if (!on_road(c)) continue;
        const UnitRange& r = sys_.ranges()[c];
        for (int k = std::max(0, lo - r.lo); k <= std::min(r.size() - 1, hi - r.lo); ++k) {
          const double h = road_h_[r.lo + k - span.lo], slope = road_s_[r.lo + k - span.lo];
          if (h > 0) sink = std::max(sink, z + h - M_.tyre.sag(r.lo + k) - C.drop_m[c]);
          slope_force += C.multiplicity[c] * fv(sys_.offset(c) + k) * slope;
        }
      }
    }
    s.load_N = load;
    s.contact_units = sections;
    s.pressure_centre_m = load > 0 ? moment / load : 0;
    s.longitudinal_force_N = -moment / (R0 - z) - slope_force;
    if (forces_only) return s;
    s.sinking_m = sink;
    const CellSoil* soil = sys_.soil();
    if (soil) {  // docs/soil.md section 8.3
      std::vector<int> offsets(C.size());
      for (int c = 0; c < C.size(); ++c) offsets[c] = sys_.offset(c);
      s.soil_sinkage_m = soil->deepest_loaded_m(sys_.ranges(), offsets, f_);
      s.soil_resistance_N = soil->compaction_resistance_N(sys_.ranges(), offsets, f_);
    }
    if (first < 0) return s;
    // Deformed belt positions of the sections in and around the patch (as the 2D driver: the
    // dynamic modes from the state, the residual orders quasi-statically from the forces),
    // computed only for the sections the edges and the map ask for (each a sum over the patch).
    const int x0 = std::max(0, first - 3), x1 = std::min(M_.m - 1, last + 3);
    q_ = Eigen::Map<const Eigen::VectorXd>(y, M_.nq);
    belt_first_ = first, belt_last_ = last;
    ++belt_stamp_;
    if (M_.nr > 0) {
      // The patch's radial and tangential forces in reverse order, so that each belt() sum over
      // the patch is four dot products with contiguous runs of the lag kernels.
      const int ns = last - first + 1;
      fr_rev_.resize(ns);
      ft_rev_.resize(ns);
      for (int j = first; j <= last; ++j) {
        const double Fj = F_(j) > 0 ? F_(j) : 0.0;
        fr_rev_(last - j) = Fj * cos_[j];
        ft_rev_(last - j) = Fj * sin_[j];
      }
    }
    auto cell_x = [&](int i, double f) {
      belt(i);
      const double c = cos_[i], sn = sin_[i];
      return (R0 - ur_[i] - f * c / cm_.k_radial_cell_N_m) * sn +
             (ut_[i] + f * sn / cm_.k_tangential_cell_N_m) * c;
    };
    // The level function of a cell: the undeformed tread's penetration P_i + h - drop_c (> 0
    // inside, the gap < 0 outside; at rest the 3D patch's d_i - z_j), linear to its zero.
    // On a soil: to the soil's surface (its rut outside the contact; cell_soil.h).
    // The road under section i for class c: CellSystem::road(), from the heights above where
    // they were computed (0 off the road).
    const bool heights = plan.has_road() && span.size() > 0;
    auto road_at = [&](int i, int c) {
      if (!heights || !on_road(c)) return 0.0;
      return span.contains(i) ? road_h_[i - span.lo] : sys_.road(t, i, c);
    };
    auto level = [&](int i, int c) {
      const double rut = soil ? soil->rut_m(c, i, t) : 0.0;
      return P_(i) + road_at(i, c) - C.drop_m[c] - rut;
    };
    auto force = [&](int i, int c) {
      const UnitRange& r = sys_.ranges()[c];
      return r.contains(i) ? f_(sys_.offset(c) + i - r.lo) : 0.0;
    };
    // Longitudinal extent per class (= per column of it).
    double length = 0, area = 0;
    contact_a_.assign(C.size(), 0);
    contact_b_.assign(C.size(), -1);
    contiguous_.assign(C.size(), 0);
    for (int c = 0; c < C.size(); ++c) {
      const UnitRange& r = sys_.ranges()[c];
      // The first and last cell in contact, scanned in from either end of the range.
      const double* fc = f_.data() + sys_.offset(c);
      const int ka = detail::first_positive(fc, r.size());
      if (ka == r.size()) continue;
      const int kb = detail::last_positive(fc, r.size());
      const int a = r.lo + ka, b = r.lo + kb;
      // Whether every cell between is in contact (the width below then needs only a and b).
      const int inside = detail::count_positive(fc + ka, kb - ka + 1);
      contact_a_[c] = a, contact_b_[c] = b, contiguous_[c] = inside == kb - ka + 1;
      // As the 2D driver and the 3D patch: the level function is the cell's tread compression
      // f / k_i inside (at rest d_i - z_c, patch3d.cc) and its tip penetration g < 0 outside
      // (at rest the gap d_i - z_c; behind a rolling patch the relaxed rubber's lift).
      auto edge = [&](int in, int out) {
        const double xin = cell_x(in, force(in, c));
        const UnitRange& r = sys_.ranges()[c];
        if (out < x0 || out > x1) return xin;
        double pin = force(in, c) / cm_.k_relaxed(in);
        double pout = r.contains(out) ? g_(sys_.offset(c) + out - r.lo) : level(out, c);
        if (soil) {
          // As the 3D static footprint on a soil (patch3d.cc): the compression into the
          // undisturbed surface inside (tread and soil), the gap to the soil's surface outside.
          pin += soil->depth(c, in);
          if (r.contains(out)) pout -= soil->rut_m(c, out, t);
        }
        if (!(pout < 0)) return xin;
        return xin + pin / (pin - pout) * (cell_x(out, 0.0) - xin);
      };
      const double extent = edge(b, b + 1) - edge(a, a - 1);
      length = std::max(length, extent);
      area += C.multiplicity[c] * C.dy_m * extent;
    }
    s.contact_length_m = length;
    s.contact_area_m2 = area;
    // Lateral extent per section: the outermost column in contact on each side, its zero of the
    // level function towards the next column out (the tread edge if it is the last).
    const double half = 0.5 * C.tread_width_m;
    double width = 0;
    // Per section, the outermost columns in contact: over the classes in contact there, the
    // smallest and the largest index of their columns (per class its contact run [a, b] when
    // every cell between touches, otherwise its cells one by one; not a scan of the columns per
    // section, 9 us a sample).
    const int np = last - first + 1;
    col_lo_.assign(np, C.columns);
    col_hi_.assign(np, -1);
    for (int c = 0; c < C.size(); ++c) {
      if (contact_b_[c] < contact_a_[c]) continue;
      const int jlo = class_col_lo_[c], jhi = class_col_hi_[c];
      int* lo = col_lo_.data() - first;
      int* hi = col_hi_.data() - first;
      if (contiguous_[c]) {
        const int a = contact_a_[c];
        detail::min_max_fill(lo + a, hi + a, contact_b_[c] - a + 1, jlo, jhi);
        continue;
      }
      const UnitRange& r = sys_.ranges()[c];
      const double* fc = f_.data() + sys_.offset(c) - r.lo;
      for (int i = contact_a_[c]; i <= contact_b_[c]; ++i)
        if (fc[i] > 0) lo[i] = std::min(lo[i], jlo), hi[i] = std::max(hi[i], jhi);
    }
    for (int i = first; i <= last; ++i) {
      if (!(F_(i) > 0)) continue;
      const int lo = col_lo_[i - first], hi = col_hi_[i - first];
      if (lo > hi) continue;
      auto side = [&](int in, int out) {
        const double ein = level(i, C.column_class[in]), eout = level(i, C.column_class[out]);
        if (!(ein > 0 && eout < 0)) return C.column_y_m[in];
        return C.column_y_m[in] + ein / (ein - eout) * (C.column_y_m[out] - C.column_y_m[in]);
      };
      const double right = hi == C.columns - 1 ? half : side(hi, hi + 1);
      const double left = lo == 0 ? -half : side(lo, lo - 1);
      width = std::max(width, right - left);
    }
    s.width_m = width;
    if (map) {
      map->t_s = t;
      const int m0 = std::max(0, first - 2), m1 = std::min(M_.m - 1, last + 2);
      for (int i = m0; i <= m1; ++i) {
        const double dx = M_.tyre.unit_length_m * std::cos(M_.tyre.theta[i]);
        for (int j = 0; j < C.columns; ++j) {
          map->x_mm.push_back(cell_x(i, 0.0) * 1e3);
          map->y_mm.push_back(C.column_y_m[j] * 1e3);
          map->pressure_kPa.push_back(force(i, C.column_class[j]) / (dx * C.dy_m) * 1e-3);
        }
      }
    }
    return s;
  }

 private:
  /// Whether the road input (a profile, or the cleat) reaches class c (CellSystem::road()).
  bool on_road(int c) const {
    const ScenarioPlan& plan = sys_.plan();
    return static_cast<bool>(plan.road_profile) || (plan.cleat && cm_.classes.on_cleat[c]);
  }
  /// The belt's radial and tangential displacement of section i at the state of the current
  /// observe() into ur_, ut_ (once per sample: stamp_).
  void belt(int i) {
    if (stamp_[i] == belt_stamp_) return;
    stamp_[i] = belt_stamp_;
    double modal[2], res[2] = {0, 0};
    pair_dots(M_.nq, phi_r_t_.col(i).data(), phi_t_t_.col(i).data(), q_.data(), nullptr, nullptr,
              nullptr, modal);
    if (M_.nr > 0) {
      // sum_j h(i - j) (F_j cos_j, F_j sin_j), j over the patch (fr_rev_: j = last - k, so the
      // kernel index i - j + lags - 1 runs up from i - last + lags - 1).
      const modal::LagKernels& K = M_.residual_kernels;
      const int n = static_cast<int>(fr_rev_.size());
      const std::size_t k0 = static_cast<std::size_t>(i - belt_last_ + K.lags - 1);
      pair_dots(n, K.r_from_r.data() + k0, K.t_from_r.data() + k0, fr_rev_.data(),
                K.r_from_t.data() + k0, K.t_from_t.data() + k0, ft_rev_.data(), res);
    }
    const double ur = modal[0] + res[0], ut = modal[1] + res[1];
    ur_[i] = ur, ut_[i] = ut;
  }

  const CellSystem& sys_;
  const CellModel& cm_;
  const TransientModel& M_;
  double sag_min_ = 0;
  /// Per class: its first and last column; per sample, its first and last section in contact
  /// and whether all between are (contiguous_); per section of the patch, its outermost columns
  /// in contact.
  std::vector<int> class_col_lo_, class_col_hi_, contact_a_, contact_b_, col_lo_, col_hi_;
  std::vector<char> contiguous_;
  Eigen::VectorXd f_, F_, g_, P_, q_, fr_rev_, ft_rev_;
  Eigen::MatrixXd phi_r_t_, phi_t_t_;  ///< nq x m
  std::vector<double> ur_, ut_, cos_, sin_, road_h_, road_s_;
  std::vector<long> stamp_;
  long belt_stamp_ = 0;
  int belt_first_ = 0, belt_last_ = -1;
};

class CellsOde final : public PatchOde {
 public:
  CellsOde(const CellModel& cm, const ScenarioPlan& plan, const StaticCells& initial,
           std::vector<UnitRange> ranges, CellSoil* soil)
      : cm_(cm),
        initial_(initial),
        sys_(cm, plan, std::move(ranges), soil),
        newton_(cm, sys_),
        obs_(sys_),
        // Before the first step: forces of the initial state outside the ranges.
        y0_(sys_.state_from(initial_)) {}
  int size() const override { return sys_.size(); }
  int full_size() const override {
    const TransientModel& M = cm_.M();
    return M.e_index() + (M.settings.relaxation ? cm_.classes.size() * M.m : 0);
  }
  int64_t nnz_hint() const override { return 1; }
  /// CVODE's 0.1 scaled by sqrt(2D states / 3D states) of the full models (full_size() and the
  /// 2D variant's state_size()): Newton's test is an RMS over the states, and over the ~2 10^4
  /// of 30 column classes it let single edge cells stay unconverged across the kink of
  /// k_g max(0, g) (by sqrt(N) times the per-state tolerance). A settled load-hold then kept
  /// cells chattering in and out of contact at every step, their tread states swinging by
  /// +-100 um (negative e, which the exact dynamics never reach), and stepped at 0.8 ms for ever.
  /// Scaled so, a cell is converged as tightly as a 2D unit was at CVODE's 0.1; capped at the
  /// 2D variant's own coefficient (patch_ode.h), which a flat crown (one class) takes and the
  /// default mesh's 0.021 nearly equals (docs/transient.md section 7).
  double newton_convergence_coefficient() const override {
    return std::min(kNewtonConvergenceCoefficient,
                    kCvodeNewtonCoefficient * std::sqrt(static_cast<double>(cm_.M().state_size()) /
                                                        static_cast<double>(full_size())));
  }
  std::vector<double> absolute_tolerances() const override { return sys_.absolute_tolerances(); }
  std::vector<double> initial_state() const override { return y0_; }
  int update_contact_set(double t, const double* y) override {
    return sys_.update_contact_set(t, y);
  }
  void contact_switched() override {}
  bool escaped() const override { return sys_.escaped(); }
  TransientSample observe(double t, const double* y, CellMap* map) override {
    return obs_.observe(t, y, map);
  }
  TransientSample observe_forces(double t, const double* y) override {
    return obs_.observe(t, y, nullptr, /*forces_only=*/true);
  }
  TransientSample step_forces(double t, const double* y) override {
    return obs_.observe(t, y, nullptr, /*forces_only=*/true, /*accepted=*/true);
  }
  void vertical_forces(double t, const double* y, Eigen::VectorXd& F) override {
    sys_.forces(t, y, f_forces_, F);
  }
  void describe(TransientResult& res) const override {
    res.patch_3d = true;
    res.units_lo = sys_.sections().lo;
    res.units_hi = sys_.sections().hi;
    res.states = sys_.size();
  }
  std::vector<double> full_state(const std::vector<double>& y) const override {
    // Every section of every class (CellSystem with no ranges): e = 0 outside the ranges.
    const TransientModel& M = cm_.M();
    const int E = M.e_index();
    if (sys_.tread_states() == 0) return y;
    std::vector<double> full(E + cm_.classes.size() * M.m, 0.0);
    std::copy(y.begin(), y.begin() + E, full.begin());
    for (int c = 0; c < cm_.classes.size(); ++c) {
      const UnitRange& r = sys_.ranges()[c];
      for (int k = 0; k < r.size(); ++k) full[E + c * M.m + r.lo + k] = y[E + sys_.offset(c) + k];
    }
    return full;
  }
  void configure(solvers::OdeProblem& prob, const TransientRunOptions&) override {
    prob.size = sys_.size();
    prob.rhs = [this](double t, const double* y, double* yd) {
      sys_.rhs(t, y, yd);
      return 0;
    };
    prob.linear_setup = [this](double t, const double* y, double gamma, bool jacobian_ok) {
      return newton_.setup(t, y, gamma, jacobian_ok) ? 0 : 1;
    };
    prob.linear_solve = [this](double* x) {
      newton_.solve(x);
      return 0;
    };
    prob.roots = 0;
  }

 private:
  const CellModel& cm_;
  StaticCells initial_;
  CellSystem sys_;
  CellNewton newton_;
  CellObserver obs_;
  std::vector<double> y0_;
  Eigen::VectorXd f_forces_;  // vertical_forces()' cell forces (work vector)
};

}  // namespace

std::unique_ptr<PatchOde> make_cells_ode(const CellModel& cm, const ScenarioPlan& plan,
                                         const StaticCells& initial, std::vector<UnitRange> ranges,
                                         CellSoil* soil) {
  return std::make_unique<CellsOde>(cm, plan, initial, std::move(ranges), soil);
}

}  // namespace modaltyre::transient::detail
