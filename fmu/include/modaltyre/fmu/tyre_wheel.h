#pragma once
// The tyre on a wheel whose motion the host prescribes (co-simulation): the transient model
// (transient/) driven by the hub's height, forward speed and spin over each communication step,
// with the road under it (flat at terrain_height, or a profile), returning the in-plane wheel
// load. The hub state given at the start of a step is carried over the step at its velocity
// (x + V s, z + w s, spin constant); the transient integrates with its own steps inside, at
// most step_size apart.
#include <memory>
#include <string>

#include "modaltyre/fmu/wheel.h"
#include "modaltyre/ground/road_profile.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::fmu {

struct WheelSettings {
  double step_size_s = 1e-3;
  std::shared_ptr<const ground::RoadProfile> profile;  ///< null: flat at terrain_height
};

struct WheelInput {
  PlaneState plane;
  double terrain_height_m = 0;
  double mu = 0.8;
};

struct WheelOutput {
  PlaneLoad load;
  double deflection_m = 0, contact_length_m = 0, slip_ratio = 0;
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
