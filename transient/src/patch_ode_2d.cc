// The 2D patch's ODE for the run loop and the driven tyre (patch_ode.h): TransientSystem with
// ContactNewton (or ArrowLu / KLU on the sparse Jacobian), and its output samples.
#include <algorithm>
#include <cmath>

#include "modaltyre/solvers/arrow_lu.h"
#include "modaltyre/transient/contact_newton.h"
#include "modaltyre/transient/ode_system.h"
#include "modaltyre/transient/soil_contact.h"
#include "patch_ode.h"

namespace modaltyre::transient::detail {
namespace {

/// One output sample at (t, y). `f` is the caller's work vector for the forces (reused across
/// samples: no allocation and no clearing of all m units per sample); sag_min: min_i s_i.
TransientSample observe_units(const TransientModel& M, const TransientSystem& sys,
                              const ScenarioPlan& plan, double t, const double* y,
                              Eigen::VectorXd& f, double sag_min, bool forces_only = false,
                              bool accepted = false) {
  TransientSample s;
  s.t_s = t;
  // The forces k max(0, g) where units can touch (on the system's units only: tread_window.h);
  // the edge interpolation below needs g also at the first unit outside each end, computed there
  // from the contact coordinates of y that forces_into() left.
  if (!(forces_only && accepted && sys.accepted_forces(t, f))) sys.forces_into(t, y, f);
  const int u0 = sys.units().lo, u1 = sys.units().hi;
  const double z = sys.hub_z(t, y);
  const double R0 = M.tyre.config.outer_radius_m;
  s.applied_load_N = plan.load(t);
  s.hub_displacement_m = z;
  s.speed_m_s = plan.speed(t);
  s.load_N = f.segment(u0, u1 - u0 + 1).sum();
  // Sinking max_i (z + h_i - s_i): the least sag on a flat road, over the cleat's units too.
  double sink = z - sag_min, moment = 0, slope_force = 0;
  if (plan.has_road() && !forces_only) {
    Eigen::VectorXd h = Eigen::VectorXd::Zero(M.m);
    sys.add_road(t, 0, M.m - 1, h);
    sink = std::max(sink, (z + h.array() - M.tyre.sag.array()).maxCoeff());
  }
  int first = -1, last = -1, units = 0;
  const double* fp = f.data();
  const double* x = M.x_road.data();
  for (int i = u0; i <= u1; ++i) {
    if (fp[i] > 0) {
      first = first < 0 ? i : first;
      last = i;
      ++units;
      moment += fp[i] * x[i];
      if (plan.has_road()) {  // on a flat road the slope force stays 0
        double slope = 0;
        sys.road(t, i, &slope);
        slope_force += fp[i] * slope;
      }
    }
  }
  s.contact_units = units;
  s.sinking_m = sink;
  s.pressure_centre_m = s.load_N > 0 ? moment / s.load_N : 0;
  s.longitudinal_force_N = -moment / (R0 - z) - slope_force;
  if (forces_only) return s;
  const SoilContact* soil = sys.soil();
  if (soil) {
    s.soil_sinkage_m = soil->deepest_loaded_m(u0, u1, f);
    s.soil_resistance_N = soil->compaction_resistance_N(u0, u1, f);
  }
  if (first >= 0) {
    // Deformed positions of the end units (as footprint.cc): dynamic modes from the state,
    // residual orders and tread quasi-statically from the current forces.
    const Eigen::Map<const Eigen::VectorXd> q(y, M.nq);
    auto deformed_x = [&](int i) {
      double ur = M.phi_r.row(i).dot(q), ut = M.phi_t.row(i).dot(q);
      const double th = M.tyre.theta[i];
      if (M.nr > 0) {
        for (int j = first; j <= last; ++j) {
          if (f(j) <= 0) continue;
          const modal::Transfer2x2 h = M.residual_kernels.at(i - j);
          const double fr = f(j) * std::cos(M.tyre.theta[j]), ft = f(j) * std::sin(M.tyre.theta[j]);
          ur += h.r_from_r * fr + h.r_from_t * ft;
          ut += h.t_from_r * fr + h.t_from_t * ft;
        }
      }
      ur += f(i) * std::cos(th) / M.tyre.k_radial_N_m;
      ut += f(i) * std::sin(th) / M.tyre.k_tangential_N_m;
      return (R0 - ur) * std::sin(th) + ut * std::cos(th);
    };
    // Patch edges as in footprint.cc: the level function phi = f C_ii inside and -gap outside,
    // interpolated linearly to its zero between the end unit and its outside neighbour.
    auto edge = [&](int inside, int outside) {
      const double x_in = deformed_x(inside);
      if (outside < 0 || outside >= M.m) return x_in;
      double phi_in = f(inside) * M.tyre.vertical_compliance(inside, inside);
      double phi_out = sys.tip_penetration_at(t, y, outside, /*xi_of_y=*/true);
      if (soil) {
        // On a soil (as ground_patch.cc): the soil's compliance dZ/df at the unit's force joins
        // its own (the virgin curve's: soil_contact.h), and the gap outside is to the soil's
        // surface.
        phi_in += f(inside) * soil->virgin_compliance_m_N(inside);
        phi_out -= soil->rut_m(outside, t);
      }
      const double w = phi_in / (phi_in - phi_out);
      return x_in + w * (deformed_x(outside) - x_in);
    };
    s.contact_length_m = edge(last, last + 1) - edge(first, first - 1);
  }
  return s;
}

class UnitsOde final : public PatchOde {
 public:
  UnitsOde(const TransientModel& M, const ScenarioPlan& plan, const StaticContact& initial,
           UnitRange units, SoilContact* soil)
      : M_(M), plan_(plan), initial_(initial), sys_(M, plan, units), newton_(M, sys_) {
    sag_min_ = M.tyre.sag.minCoeff();
    sys_.set_soil(soil);
  }
  int size() const override { return sys_.size(); }
  int full_size() const override { return M_.state_size(); }
  int64_t nnz_hint() const override { return sys_.nnz(); }
  double newton_convergence_coefficient() const override { return kNewtonConvergenceCoefficient; }
  std::vector<double> absolute_tolerances() const override { return sys_.absolute_tolerances(); }
  std::vector<double> initial_state() const override { return sys_.state_from(initial_); }
  int update_contact_set(double t, const double* y) override {
    return sys_.update_contact_set(t, y);
  }
  void contact_switched() override { sys_.contact_switched(); }
  bool escaped() const override { return sys_.escaped(); }
  TransientSample observe(double t, const double* y, CellMap*) override {
    return observe_units(M_, sys_, plan_, t, y, f_sample_, sag_min_);
  }
  TransientSample observe_forces(double t, const double* y) override {
    return observe_units(M_, sys_, plan_, t, y, f_sample_, sag_min_, /*forces_only=*/true);
  }
  TransientSample step_forces(double t, const double* y) override {
    return observe_units(M_, sys_, plan_, t, y, f_sample_, sag_min_, /*forces_only=*/true,
                         /*accepted=*/true);
  }
  void vertical_forces(double t, const double* y, Eigen::VectorXd& F) override {
    sys_.forces_into(t, y, F);
  }
  void describe(TransientResult& res) const override {
    res.units_lo = sys_.units().lo;
    res.units_hi = sys_.units().hi;
    res.states = sys_.size();
  }
  std::vector<double> full_state(const std::vector<double>& y) const override {
    // e = 0 for the units without a tread state (they never touched).
    std::vector<double> full(M_.state_size(), 0.0);
    std::copy(y.begin(), y.begin() + M_.e_index(), full.begin());
    std::copy(y.begin() + M_.e_index(), y.end(),
              full.begin() + M_.e_index() + (M_.settings.relaxation ? sys_.units().lo : 0));
    return full;
  }
  void configure(solvers::OdeProblem& prob, const TransientRunOptions& options) override {
    prob.size = sys_.size();
    prob.rhs = [this](double t, const double* y, double* yd) {
      sys_.rhs(t, y, yd);
      return 0;
    };
    prob.jacobian = [this](double t, const double* y, const double*, solvers::CscMatrix& J) {
      sys_.jacobian(t, y, J);
      return 0;
    };
    const bool locate = options.restart_at_switches || options.locate_switches;
    prob.roots = locate ? M_.m : 0;
    prob.root_functions = [this](double t, const double* y, double* g) {
      sys_.roots(t, y, g);
      return 0;
    };
    // Newton's matrix I - gamma J has the arrow structure of solvers::ArrowLu: the carcass,
    // residual and hub states (the first e_index()) are densely coupled through the units in
    // contact; each tread state couples to its two upwind neighbours and, in contact, to that
    // dense block.
    using NewtonSolver = TransientRunOptions::NewtonSolver;
    if (options.newton_solver == NewtonSolver::schur) {
      prob.linear_setup = [this](double t, const double* y, double gamma, bool jacobian_ok) {
        // 1: CVODE retries with a smaller step.
        return newton_.setup(t, y, gamma, jacobian_ok) ? 0 : 1;
      };
      prob.linear_solve = [this](double* x) {
        newton_.solve(x);
        return 0;
      };
    } else if (options.newton_solver == NewtonSolver::arrow) {
      prob.linear_setup = [this](double t, const double* y, double gamma, bool jacobian_ok) {
        if (!jacobian_ok || jac_.n == 0) sys_.jacobian(t, y, jac_);
        return arrow_.factor(jac_, gamma, M_.e_index()) ? 0 : 1;
      };
      prob.linear_solve = [this](double* x) {
        arrow_.solve(x);
        return 0;
      };
    }
  }

 private:
  const TransientModel& M_;
  const ScenarioPlan& plan_;
  StaticContact initial_;
  TransientSystem sys_;
  ContactNewton newton_;
  solvers::ArrowLu arrow_;
  solvers::CscMatrix jac_;
  Eigen::VectorXd f_sample_;  // observe()'s work vector
  double sag_min_ = 0;
};

}  // namespace

std::unique_ptr<PatchOde> make_units_ode(const TransientModel& model, const ScenarioPlan& plan,
                                         const StaticContact& initial, UnitRange units,
                                         SoilContact* soil) {
  return std::make_unique<UnitsOde>(model, plan, initial, units, soil);
}

}  // namespace modaltyre::transient::detail
