#pragma once
// The tyre on a wheel whose motion the host prescribes (co-simulation): the transient model
// (transient/) driven by the hub's height, forward speed and spin over each communication step,
// with the ground under it (a road flat at terrain_height, or a profile; or the config's soil,
// its undisturbed surface at terrain_height, its memory moving with the hub's travel and its
// Janosi-Hanamoto shear in place of the tread's friction), returning the in-plane wheel load. The
// hub state given at the start of a step is carried over the step at its velocity (x + V s, z + w
// s, spin constant); the transient integrates with its own steps inside, at most step_size apart.
#include <memory>
#include <string>

#include "modaltyre/fmu/wheel.h"
#include "modaltyre/ground/road_profile.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::fmu {

struct WheelSettings {
  double step_size_s = 1e-3;
  std::shared_ptr<const ground::RoadProfile> profile;  ///< null: flat at terrain_height
  /// The tyre's section height [m] (section_height_m()): the rim is on the road when the tyre's
  /// deflection at the road reaches it. 0: not known, never raised.
  double section_height_m = 0;
};

/// The section height of a config's tyre: outer radius less rim radius (tyre.rim_radius_mm),
/// else section width x aspect ratio; 0 when the config states neither.
double section_height_m(const contact::TyreConfig& config);

struct WheelInput {
  PlaneState plane;
  double terrain_height_m = 0;
  double mu = 0.8;
};

struct WheelOutput {
  PlaneLoad load;
  double deflection_m = 0, contact_length_m = 0, slip_ratio = 0;
  /// The rim on the road (the deflection at the road at least the section height) at a
  /// sub-step's end of the last step, and whether it got there in it (from off the road), first
  /// at rim_started_at_s.
  bool rim_contact = false, rim_contact_started = false;
  double rim_started_at_s = 0;
  /// On a soil: the deepest loaded point of its surface below the undisturbed one, and the
  /// compaction resistance sum f tan alpha (included in load.fx_N); 0 on a road.
  double soil_sinkage_m = 0, compaction_resistance_N = 0;
};

class TyreWheel {
 public:
  TyreWheel(std::shared_ptr<const transient::TransientModel> model, const WheelSettings& settings);
  ~TyreWheel();
  TyreWheel(const TyreWheel&) = delete;
  TyreWheel& operator=(const TyreWheel&) = delete;
  /// Why the hub state of `in`, carried over a step of h seconds, cannot be computed (empty: it
  /// can): the wheel's centre at or below the road under it at the step's start or end (a
  /// deflection of the whole outer radius; the rim reaches the road long before, raising
  /// rim_contact).
  std::string refusal(const WheelInput& in, double h) const;
  /// The tyre at rest on the road at time t under the hub state of `in` (static equilibrium at
  /// its deflection, tread unsheared). ComputationError if no equilibrium is found.
  void start(double t, const WheelInput& in);
  /// Integrates over [t, t + h] with the hub state of `in` carried at its velocity.
  /// ComputationError (with the integrator's message) on failure; the wheel is then unusable.
  void step(double t, double h, const WheelInput& in);
  const WheelOutput& output() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace modaltyre::fmu
