#include "modaltyre/fmu/tyre_wheel.h"

#include "modaltyre/core/errors.h"

namespace modaltyre::fmu {

// Step 1 of issue 34: the FMU's interface, description and packaging. Driving the transient by
// the hub's prescribed motion comes with transient/'s prescribed-hub API (branch t3d2); until
// then the wheel refuses to start, and fmi2ExitInitializationMode reports it as an fmi2Error.
struct TyreWheel::Impl {
  std::shared_ptr<const transient::TransientModel> model;
  WheelSettings settings;
  WheelOutput output;
};

TyreWheel::TyreWheel(std::shared_ptr<const transient::TransientModel> model,
                     const WheelSettings& settings)
    : impl_(std::make_unique<Impl>()) {
  impl_->model = std::move(model);
  impl_->settings = settings;
}

TyreWheel::~TyreWheel() = default;

void TyreWheel::start(double, const WheelInput&) {
  throw ComputationError("the hub-driven transient is not in this build yet");
}

void TyreWheel::step(double, double, const WheelInput&) {
  throw ComputationError("the hub-driven transient is not in this build yet");
}

const WheelOutput& TyreWheel::output() const { return impl_->output; }

}  // namespace modaltyre::fmu
