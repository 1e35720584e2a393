#pragma once
// One patch's ODE under a plan, with its Newton solver and its observables (internal to the
// transient library): the 2D units (ode_system.h, contact_newton.h) or the 3D cells
// (cell_system.h, cell_newton.h). The scenario runner (run_plan) and the driven tyre
// (driven_tyre.h) integrate either through this interface.
#include <memory>
#include <vector>

#include "modaltyre/solvers/cvode_klu.h"
#include "modaltyre/transient/cell_model.h"
#include "modaltyre/transient/cell_soil.h"
#include "modaltyre/transient/cell_system.h"
#include "modaltyre/transient/driver.h"
#include "modaltyre/transient/scenario.h"
#include "modaltyre/transient/soil_contact.h"
#include "modaltyre/transient/tread_window.h"

namespace modaltyre::transient::detail {

/// Newton's convergence coefficient of the units' and the cells' ODEs, a fifth of CVODE's 0.1.
/// Newton's test is an RMS over the states: at 0.1 single edge units stayed unconverged across
/// the kink of the contact law k max(0, g), and a settled load-hold could chatter in and out of
/// contact at every step for the whole hold (configs/sf350_init.yaml: 107 315 steps at net
/// tension share 0.55, 1276 with 0.02; 0.05 and 0.03 still 13 738 and 1554; docs/transient.md
/// section 7). It also takes the 2D default's rolling from 180 steps to 63 at the same answers.
constexpr double kNewtonConvergenceCoefficient = 0.02;

class PatchOde {
 public:
  virtual ~PatchOde() = default;
  virtual int size() const = 0;
  /// States of the model with a tread state for every unit (every section of every class): the
  /// RMS error test's reference count (ode_options()).
  virtual int full_size() const = 0;
  /// The right-hand side, Newton's linear solver (and root functions if the options ask for
  /// them) into `prob`; the callbacks refer to this object.
  virtual void configure(solvers::OdeProblem& prob, const TransientRunOptions& options) = 0;
  virtual int64_t nnz_hint() const = 0;
  /// Newton's convergence coefficient (solvers::OdeOptions; 0: CVODE's 0.1).
  virtual double newton_convergence_coefficient() const = 0;
  virtual std::vector<double> absolute_tolerances() const = 0;
  /// The initial state (the plan's static contact).
  virtual std::vector<double> initial_state() const = 0;
  /// Units (cells, with their multiplicity) that entered or left since the last accepted step.
  virtual int update_contact_set(double t, const double* y) = 0;
  /// A root function reported a switch (2D with located switches).
  virtual void contact_switched() = 0;
  /// A unit outside the touchable range reached the road: the run must be repeated with all.
  virtual bool escaped() const = 0;
  /// One output sample (and the pressure map on the 3D patch when `map` is given).
  virtual TransientSample observe(double t, const double* y, CellMap* map = nullptr) = 0;
  /// The sample's load_N, longitudinal_force_N, pressure_centre_m and hub_displacement_m only
  /// (the rest not computed): a pass over the forces, without the edges, width and soil.
  virtual TransientSample observe_forces(double t, const double* y) = 0;
  /// observe_forces() at the state update_contact_set() just accepted at t, from the forces it
  /// computed there (no second pass over the contact; a pass when it accepted no state at t).
  virtual TransientSample step_forces(double t, const double* y) = 0;
  /// The vertical contact force of every unit (2D) or section (3D: summed over its cells) at
  /// (t, y) into F (m entries; 0 where nothing touches) [N].
  virtual void vertical_forces(double t, const double* y, Eigen::VectorXd& F) = 0;
  /// units_lo/hi, states and patch_3d of a result.
  virtual void describe(TransientResult& res) const = 0;
  /// The state in the layout of every unit (2D: e = 0 for units without a tread state).
  virtual std::vector<double> full_state(const std::vector<double>& y) const = 0;
};

/// The 2D units `units` of `model` under `plan`, starting from `initial`; on `soil` when given
/// (soil_contact.h; not owned, its memory that of `initial`).
std::unique_ptr<PatchOde> make_units_ode(const TransientModel& model, const ScenarioPlan& plan,
                                         const StaticContact& initial, UnitRange units,
                                         SoilContact* soil = nullptr);
/// The 3D cells of `cm` under `plan` with tread states on `ranges` (empty: every section),
/// starting from `initial`; on `soil` when given (cell_soil.h; not owned, its memory that of
/// `initial`).
std::unique_ptr<PatchOde> make_cells_ode(const CellModel& cm, const ScenarioPlan& plan,
                                         const StaticCells& initial, std::vector<UnitRange> ranges,
                                         CellSoil* soil = nullptr);

/// The integrator settings of every transient run: BDF orders 1-2, the Newton and setup
/// settings of docs/transient.md section 2, the tolerances scaled by sqrt(full / states) so that
/// the RMS error test is that of the full state.
solvers::OdeOptions ode_options(const PatchOde& ode, const TransientModel& model);

/// Runs the plan on `ode` with output samples every output step (TransientResult); sets
/// `escaped` (and returns at once) if a unit outside the touchable range reached the road.
TransientResult run_plan(PatchOde& ode, const TransientModel& model, const ScenarioPlan& plan,
                         const TransientRunOptions& options, bool& escaped);

}  // namespace modaltyre::transient::detail
