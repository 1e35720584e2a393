#pragma once
// The tyre driven by its hub (docs/transient.md section 8): the hub's deflection, forward speed
// and wheel spin prescribed (hub_motion.h) instead of a scenario's load control, on the 2D or
// the 3D patch, integrated by the transient's CVODE machinery (BDF + the contact's low-rank
// Newton solver); the wheel load (F_z, F_x, M_y) read back at any time reached. Step by step
// (DrivenTyre::advance, a co-simulation's communication steps) or over a whole motion given as
// a function of time (run_prescribed, sampled like a scenario).
//
// Frames and signs (ISO 8855: x forward, y left, z up; the wheel spins about y, forward
// rolling > 0): F_z the road's vertical force on the tyre (> 0 in contact); F_x the road's
// longitudinal force on the tyre at the contact, here the free-rolling drag -M/(R0 - z) of the
// pressure distribution's moment M = sum f_i x_i (< 0 rolling forward: the rolling resistance;
// the model has no tangential contact, so no drive or brake force); M_y = -M the moment of the
// vertical contact forces about the wheel axis through the hub. The hub's own mass takes no part
// (the host carries the wheel), nor does the carcass's base excitation (model.h).
//
// On a soil (the model's config has a Bekker-Wong or Kelvin-Voigt ground: docs/soil.md section
// 8) the units (2D) or cells (3D) carry their contact springs in series with the soil and its
// memory, as the transient's soil runs do (soil_contact.h, cell_soil.h); deflection_m is then the
// hub's approach to the undisturbed surface. Bekker's b is the static footprint's on the soil at
// the config's transient.rolling.load_N (iterated with its contact length, as `footprint` does),
// fixed for the tyre's life; the memory moves with DrivenTyreOptions::distance_m.
//
// Instances are independent (each owns its integrator and work vectors; the TransientModel is
// shared read-only and must outlive them); reset() starts over.
#include <functional>
#include <memory>
#include <string>

#include "modaltyre/solvers/cvode_klu.h"
#include "modaltyre/transient/driver.h"
#include "modaltyre/transient/hub_motion.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::transient {

/// The wheel load and the patch at one time.
struct WheelLoad {
  double t_s = 0;
  double fz_N = 0;   ///< vertical force of the road on the tyre (upward)
  double fx_N = 0;   ///< longitudinal force at the road (ISO x; free-rolling drag, see above)
  double my_Nm = 0;  ///< moment of the vertical contact forces about the wheel axis (ISO y)
  double deflection_m = 0;             ///< the hub's (HubState::deflection_m)
  double sinking_m = 0;                ///< deflection of the tyre at the road
  double contact_length_m = 0;         ///< longest column's (2D: the patch's) extent along x
  double width_m = 0;                  ///< 3D patch only (0 on the 2D patch)
  double contact_area_m2 = 0;          ///< 3D patch only
  double pressure_centre_m = 0;        ///< sum f x / sum f (+ forward)
  double soil_sinkage_m = 0;           ///< on a soil: the deepest loaded point of its surface
  double compaction_resistance_N = 0;  ///< on a soil: sum f tan(alpha) (TransientSample)
};

/// A wheel load from an output sample of the transient (driver.h).
WheelLoad wheel_load(const TransientSample& s);

struct DrivenTyreOptions {
  /// The 2D patch even if the config has a footprint_3d: section (the fast variant); otherwise
  /// the patch the config states, as `modaltyre transient` does.
  bool force_2d = false;
  /// Largest internal step [s]; 0: the integrator's own choice (its error test).
  double max_step_s = 0;
  /// The largest deflection the hub will reach [m]: tread states are kept only for the units
  /// (sections) that can touch up to it (tread_window.h's bound), the cheaper the smaller.
  /// 0: every unit. Should a unit beyond it reach the road, the step is redone with every unit
  /// (never a wrong result, only a slower one).
  double max_deflection_m = 0;
  /// A road under the tyre instead of the flat one (ScenarioPlan::road_profile: height above
  /// the flat road at ground position x relative to the hub, at time t; the caller keeps the
  /// hub's position along the road), with a bound of its heights. The static start (reset())
  /// is on the flat road: start where the profile is flat under the patch.
  std::function<double(double t, double x_m, double* slope)> road_profile;
  double road_max_height_m = 0;
  /// On a soil: the distance the hub has rolled along the ground at t [m] (the soil's memory
  /// moves backward under the tyre with it; soil_contact.h); empty: the ground at rest.
  std::function<double(double t)> distance_m;
};

/// How one advance() ended.
struct DriveStatus {
  bool ok = true;
  double t_s = 0;       ///< time reached
  std::string message;  ///< the reason when !ok
};

class DrivenTyre {
 public:
  /// The tyre of `model` (which must outlive this object), reset() at t = 0 with the hub at
  /// rest touching the road (deflection 0).
  explicit DrivenTyre(const TransientModel& model, const DrivenTyreOptions& options = {});
  ~DrivenTyre();
  DrivenTyre(DrivenTyre&&) noexcept;
  DrivenTyre& operator=(DrivenTyre&&) noexcept;

  /// Starts over at t0 from the static equilibrium of the standing tyre at the hub's deflection
  /// (the static footprint whose sinking is initial.deflection_m; the undeformed tyre at 0 or
  /// less). ComputationError if no static footprint reaches that deflection in the window.
  void reset(const HubState& initial, double t0 = 0);
  /// Integrates from time() to t_next (> time()) with the hub moving linearly from its state
  /// at time() to `hub` at t_next, or held at `hub` over the step (the integrator restarts when
  /// a held state jumps). Internal steps of at most max_step_s.
  DriveStatus advance(double t_next, const HubState& hub,
                      HubInterpolation how = HubInterpolation::linear);
  /// The hub follows `motion` from time() on (a function of time; not beyond what the motion
  /// defines); advance(t_next) then integrates with it.
  void follow(std::function<HubState(double)> motion);
  DriveStatus advance(double t_next);

  double time() const;
  /// The hub's state at time() (spin resolved).
  HubState hub() const;
  /// The wheel load at time().
  WheelLoad load() const;
  /// The vertical contact force of every unit (2D) or section (3D, summed over its cells) at
  /// time() into F (m entries, indexed as the model's candidate units; 0 where nothing
  /// touches) [N]: the pressure distribution along x that a tangential contact needs.
  void vertical_forces(Eigen::VectorXd& F) const;
  /// Runs on the 3D patch.
  bool patch_3d() const;
  /// Integrator counters since reset().
  solvers::OdeStats stats() const;
  /// Tread states in the ODE and whether a step had to be redone with every unit.
  int states() const;
  bool widened() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The tyre under a hub motion given as a function of time over [0, duration_s], from the
/// static equilibrium at motion(0)'s deflection, with output samples every output step (the
/// config's transient.output_step_ms) as a scenario run (driver.h; applied_load_N is 0: there
/// is no load control). map_times_s and the 3D options of `options` apply.
TransientResult run_prescribed(const TransientModel& model,
                               const std::function<HubState(double)>& motion, double duration_s,
                               const TransientRunOptions& options = {}, bool force_2d = false);

}  // namespace modaltyre::transient
