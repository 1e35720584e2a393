#pragma once
// The transient driver: runs a scenario on CVODE + KLU (model.h, ode_system.h), one internal
// step at a time, and samples the observables at the output step.
#include <functional>
#include <string>
#include <vector>

#include "modaltyre/solvers/cvode_klu.h"
#include "modaltyre/transient/model.h"
#include "modaltyre/transient/output_grid.h"
#include "modaltyre/transient/scenario.h"

namespace modaltyre::transient {

struct TransientSample {
  double t_s = 0;
  double load_N = 0;              ///< sum of contact forces (road reaction)
  double applied_load_N = 0;      ///< F(t) at the hub
  double hub_displacement_m = 0;  ///< z, downward
  double sinking_m = 0;           ///< max_i (z + h_i - s_i): deflection of the tyre at the road
  double contact_length_m = 0;
  double longitudinal_force_N = 0;  ///< -(sum f x)/(R0 - z) - sum f h'(x)
  double pressure_centre_m = 0;     ///< sum f x / sum f (+ forward)
  double speed_m_s = 0;
  int contact_units = 0;  ///< units (3D: sections) with a contact force
  /// On a soil (2D patch): the deepest point of the loaded soil surface below the undisturbed
  /// surface (docs/soil.md section 1); sinking_m is then the axle's approach to that surface.
  double soil_sinkage_m = 0;
  /// On a soil: the horizontal components of the normal forces on the soil surface's slope,
  /// sum f_i tan(alpha_i) (traction's motion resistance R_c, docs/soil.md section 5) [N].
  double soil_resistance_N = 0;
  /// 3D patch only (cell_model.h; 0 on the 2D patch): the widest section's lateral extent and
  /// the contact area sum_columns dy (x_front - x_rear).
  double width_m = 0;
  double contact_area_m2 = 0;
};

/// The 3D patch's pressure map at one time: every cell of the sections in contact (and two
/// either side), x the section's deformed position, y the column centre.
struct CellMap {
  double t_s = 0;
  std::vector<double> x_mm, y_mm, pressure_kPa;  ///< one entry per cell
};

/// A signal's smallest and largest value over a run and when they occurred.
struct SignalRange {
  double min = 0, max = 0, t_min_s = 0, t_max_s = 0;
};

/// The extremes of the forces over the integrator's own steps and inside them (dense output,
/// step_extremes.h), not over the output grid.
struct StepRanges {
  bool valid = false;
  SignalRange load_N;                ///< the contact load (road reaction)
  SignalRange longitudinal_force_N;  ///< F_x
  long searches = 0;                 ///< steps searched around a running extreme
};

/// The hub's displacement at the end of one integrator step.
struct HubStep {
  double t_s = 0, z_m = 0;
};

enum class TransientStatus { completed, failed };

struct TransientResult {
  Scenario scenario = Scenario::load_hold;
  TransientStatus status = TransientStatus::failed;
  std::string message;
  double simulated_s = 0;  ///< time reached
  double wall_s = 0;
  solvers::OdeStats stats;
  /// Units that entered or left the road between accepted steps (with locate_switches: root
  /// returns).
  int contact_events = 0;
  std::vector<TransientSample> samples;
  /// The output samples' times: the config's transient.output_step_ms, or chosen for the
  /// scenario (output_grid.h); finer while a cleat crosses the window.
  OutputGrid output_grid;
  /// The extremes of load and F_x over the integrator's steps (not the output grid).
  StepRanges extremes;
  /// Free vibration: the hub's displacement at t = 0 and every step's end (the bounce's peaks,
  /// decay.h).
  std::vector<HubStep> hub_steps;
  /// Mean of -longitudinal force over the last 10 % of the run (rolling resistance) [N].
  double rolling_resistance_N = 0;
  /// The state at simulated_s in the layout of all units (TransientSystem(model, plan); e = 0
  /// for the units that had no tread state), when the options asked for it.
  std::vector<double> final_state;
  /// The units that carried forces and tread states (tread_window.h), and the ODE's size.
  int units_lo = 0, units_hi = -1, states = 0;
  /// A unit outside the touchable range reached the road and the run was repeated with all
  /// units (never in the bundled scenarios).
  bool units_escaped = false;
  /// Run on the 3D patch (cell_model.h): samples carry width_m and contact_area_m2.
  bool patch_3d = false;
  /// Run on a soil (the config's ground, soil_contact.h): samples carry soil_sinkage_m.
  bool on_soil = false;
  /// On a soil, 3D patch (cell_soil.h): the deepest rut in the soil's memory at the run's end,
  /// the surface unloaded from its deepest sinkage Z(0; z_max) [m].
  double rut_depth_m = 0;
  std::vector<CellMap> maps;  ///< 3D: the pressure maps at TransientRunOptions::map_times_s
  bool ok() const { return status == TransientStatus::completed; }
  double real_time_factor() const { return wall_s > 0 ? simulated_s / wall_s : 0; }
};

struct TransientRunOptions {
  /// Called after every output sample with (t, duration); return false to stop (cancel).
  std::function<bool(double, double)> progress;
  bool keep_final_state = false;  ///< return the last state in TransientResult::final_state
  /// Locate every contact switch with CVODE's root finder (one root function per candidate
  /// unit) and return there. Off by default: the kinks of f = k max(0, g) are solved inside the
  /// implicit steps, and the contact set is compared between accepted steps instead (the root
  /// finder's passes over the m functions were half the cost of a step without relaxation).
  bool locate_switches = false;
  /// Re-initialise CVODE at every located contact switch (BDF history discarded) instead of
  /// continuing over the kink; implies locate_switches. Slower, kept for comparisons.
  bool restart_at_switches = false;
  /// Newton's linear systems: the Schur complement through the contact's low rank
  /// (contact_newton.h, the default), the dense Schur complement on the carcass and hub from the
  /// sparse Jacobian (solvers/arrow_lu.h), or KLU on the whole sparse Jacobian (the general
  /// solver); the last two kept for comparisons (docs/transient.md section 6).
  enum class NewtonSolver { schur, arrow, klu };
  NewtonSolver newton_solver = NewtonSolver::schur;
  /// Tread states for all candidate units instead of those that can touch in the scenario
  /// (tread_window.h); the same trajectory, kept for comparisons.
  bool all_tread_states = false;
  /// 3D patch: times at which to record the pressure map (TransientResult::maps; each within
  /// the scenario).
  std::vector<double> map_times_s;
  /// 3D patch: one class per column instead of merging columns of equal drop and road (the
  /// full per-cell model, for tests of the reduction).
  bool per_column_cells = false;
  /// The output samples between the first and the last with what the printed outputs read:
  /// t_s, applied_load_N, speed_m_s and hub_displacement_m (the decay on the samples) of every
  /// sample, and from 0.9 of the duration (the rolling resistance's window) also load_N,
  /// longitudinal_force_N, pressure_centre_m and contact_units, each with the bits of the whole
  /// sample; the rest not computed (0). The first and the final sample stay whole. For the JSON,
  /// the text summary and the bands, not the CSV or the plot: the width, edges and belt sums
  /// were ~3/4 of a 3D sample's work, its forces most of the rest. Ignored on a soil (its final
  /// sample reads the soil's memory at the run's end). A failed run's rolling resistance is then
  /// not a mean over its last tenth.
  bool summary_samples = false;
};

/// Runs a scenario. Failures of the integrator are reported in the result (message and time
/// reached), never thrown; ill-posed settings are InputErrors.
TransientResult run_transient(const TransientModel& model, Scenario scenario,
                              const TransientRunOptions& options = {});

/// Runs a scenario on the 3D patch of the model's config (footprint_3d:, cell_model.h,
/// docs/transient.md section 7).
TransientResult run_transient_3d(const TransientModel& model, Scenario scenario,
                                 const TransientRunOptions& options = {});

/// Runs a scenario on the patch the model's config states: the 3D patch with a footprint_3d:
/// section (run_transient_3d), else the 2D patch (run_transient). The one place that chooses
/// (`modaltyre transient` and the Python module's transient call it); map times on the 2D patch
/// are an InputError.
TransientResult run_scenario(const TransientModel& model, Scenario scenario,
                             const TransientRunOptions& options = {});

}  // namespace modaltyre::transient
