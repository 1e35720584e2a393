#include "modaltyre/fmu/instance.h"

#include <cmath>
#include <exception>
#include <filesystem>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/fmu/resources.h"
#include "modaltyre/fmu/tyre_variables.h"
#include "modaltyre/fmu/tyre_wheel.h"

namespace modaltyre::fmu {
namespace {

/// Largest step_size [s]: the transient resolves the carcass modes (100-300 Hz) by its own
/// steps, so this bounds only the hub's carried motion; a second is already far beyond it.
constexpr double kMaxStepSize_s = 1.0;
/// Friction coefficients accepted (ground::CoulombFriction's range).
constexpr double kMaxFriction = 10;
/// Relative slack when a communication point is compared with the instance's time.
constexpr double kTimeSlack = 1e-9;

bool is_input(unsigned r) { return r <= vr::terrain_mu; }

}  // namespace

Instance::~Instance() = default;

Instance* Instance::create(fmi2String instance_name, fmi2Type type, fmi2String guid,
                           fmi2String resource_location, const fmi2CallbackFunctions* functions,
                           fmi2Boolean logging_on) {
  std::unique_ptr<Instance> inst(new Instance());
  inst->name_ = instance_name ? instance_name : "";
  if (functions) {
    inst->logger_ = functions->logger;
    inst->environment_ = functions->componentEnvironment;
  }
  inst->logging_ = logging_on == fmi2True;
  if (type != fmi2CoSimulation) {
    inst->log(fmi2Error,
              "this FMU is a co-simulation FMU only (fmi2Instantiate with "
              "fmi2ModelExchange refused)");
    return nullptr;
  }
  if (!guid || !resource_location) {
    inst->log(fmi2Error, std::string("fmi2Instantiate: ") +
                             (!guid ? "fmuGUID" : "fmuResourceLocation") + " is NULL");
    return nullptr;
  }
  try {
    inst->resource_folder_ = resource_folder_from_uri(resource_location);
    const ResourceRecord record = read_resource_record(inst->resource_folder_);
    if (record.guid != guid) {
      inst->log(fmi2Error, "fmi2Instantiate: GUID " + std::string(guid) + " is not this FMU's (" +
                               record.guid +
                               "): the modelDescription.xml and the resources differ");
      return nullptr;
    }
    const contact::TyreConfig config = contact::load_tyre_config(record.config_path);
    inst->model_ = std::make_shared<const transient::TransientModel>(
        transient::build_transient_model(contact::build_tyre_model(config)));
  } catch (const InputError& e) {
    inst->log(fmi2Error, std::string("fmi2Instantiate: ") + e.what());
    return nullptr;
  } catch (const std::exception& e) {
    inst->log(fmi2Error,
              std::string("fmi2Instantiate: the tyre model could not be built: ") + e.what());
    return nullptr;
  }
  inst->set_start_values();
  inst->log(fmi2OK, "instantiated from " + inst->resource_folder_);
  return inst.release();
}

void Instance::set_start_values() {
  TyreDescriptionInfo info;
  info.outer_radius_m = model_->tyre.config.outer_radius_m;
  const ModelDescription d = tyre_model_description(info);
  real_.assign(vr::kRealCount, 0.0);
  for (const ScalarVariable& v : d.variables) {
    if (v.type == BaseType::real && v.start) real_[v.value_reference] = *v.start;
    if (v.type == BaseType::string && v.start_string) road_profile_ = *v.start_string;
  }
  time_ = start_time_ = 0;
  stop_defined_ = false;
  wheel_.reset();
}

void Instance::log(fmi2Status status, const std::string& message) const {
  if (!logger_) return;
  if (status == fmi2OK && !logging_) return;
  const char* category = status == fmi2OK        ? "logEvents"
                         : status == fmi2Warning ? "logStatusWarning"
                                                 : "logStatusError";
  // The logger formats like printf: a '%' of the message (a path) is written '%%'. No variable
  // arguments are passed, so a host that prints the format as it is still reads the message.
  std::string escaped;
  for (char ch : message) escaped += ch == '%' ? std::string("%%") : std::string(1, ch);
  logger_(environment_, name_.c_str(), status, category, escaped.c_str());
}

fmi2Status Instance::fail(const std::string& message, fmi2Status status) {
  log(status, message);
  if (status == fmi2Error || status == fmi2Fatal) state_ = State::error;
  return status;
}

bool Instance::allowed(std::initializer_list<State> states, const char* function) {
  for (State s : states)
    if (s == state_) return true;
  static const char* names[] = {"instantiated", "initialization mode", "step complete",
                                "step failed",  "terminated",          "error"};
  log(fmi2Error,
      std::string(function) + " is not allowed in state '" + names[static_cast<int>(state_)] + "'");
  return false;
}

fmi2Status Instance::set_debug_logging(bool on) {
  logging_ = on;
  return fmi2OK;
}

fmi2Status Instance::setup_experiment(bool, double, double start_time, bool stop_defined,
                                      double stop_time) {
  if (!allowed({State::instantiated}, "fmi2SetupExperiment")) return fmi2Error;
  if (!std::isfinite(start_time) || (stop_defined && !(stop_time >= start_time)))
    return fail("fmi2SetupExperiment: startTime must be finite and stopTime >= startTime");
  start_time_ = time_ = start_time;
  stop_defined_ = stop_defined;
  stop_time_ = stop_time;
  return fmi2OK;
}

fmi2Status Instance::enter_initialization() {
  if (!allowed({State::instantiated}, "fmi2EnterInitializationMode")) return fmi2Error;
  state_ = State::initialization;
  return fmi2OK;
}

WheelInput Instance::wheel_input(bool* ok) {
  WheelState s;
  for (int k = 0; k < 3; ++k) {
    s.pos[k] = real_[vr::pos_x + k];
    s.lin_vel[k] = real_[vr::lin_vel_x + k];
    s.ang_vel[k] = real_[vr::ang_vel_x + k];
  }
  for (int k = 0; k < 4; ++k) s.rot[k] = real_[vr::rot_e0 + k];
  WheelInput in;
  const char* why = nullptr;
  *ok = plane_state(s, in.plane, &why);
  if (!*ok) log(fmi2Error, std::string("wheel state: ") + why);
  in.terrain_height_m = real_[vr::terrain_height];
  in.mu = real_[vr::terrain_mu];
  return in;
}

void Instance::refresh_outputs(const WheelInput& in) {
  const WheelOutput& o = wheel_->output();
  Vec3 force, moment;
  world_load(in.plane, o.load, force, moment);
  for (int k = 0; k < 3; ++k) {
    real_[vr::force_x + k] = force[k];
    real_[vr::moment_x + k] = moment[k];
  }
  real_[vr::deflection] = o.deflection_m;
  real_[vr::contact_length] = o.contact_length_m;
  real_[vr::slip_ratio] = o.slip_ratio;
}

fmi2Status Instance::exit_initialization() {
  if (!allowed({State::initialization}, "fmi2ExitInitializationMode")) return fmi2Error;
  const double step = real_[vr::step_size];
  if (!(step > 0 && step <= kMaxStepSize_s))
    return fail("parameter step_size = " + std::to_string(step) + " s: must be in (0, " +
                std::to_string(kMaxStepSize_s) + "] s");
  WheelSettings settings;
  settings.step_size_s = step;
  if (!road_profile_.empty()) {
    std::filesystem::path p(road_profile_);
    if (p.is_relative()) p = std::filesystem::path(resource_folder_) / p;
    try {
      settings.profile =
          std::make_shared<const ground::RoadProfile>(ground::read_road_profile_csv(p.string()));
    } catch (const std::exception& e) {
      return fail(std::string("parameter road_profile: ") + e.what());
    }
  }
  bool ok = false;
  const WheelInput in = wheel_input(&ok);
  if (!ok) return fail("fmi2ExitInitializationMode: the wheel state is not usable");
  try {
    wheel_ = std::make_unique<TyreWheel>(model_, settings);
    wheel_->start(time_, in);
  } catch (const std::exception& e) {
    return fail(std::string("fmi2ExitInitializationMode: ") + e.what());
  }
  refresh_outputs(in);
  for (int k = 0; k < 3; ++k)
    real_[vr::load_point_x + k] = real_[vr::query_x + k] = real_[vr::pos_x + k];
  state_ = State::step_complete;
  return fmi2OK;
}

fmi2Status Instance::do_step(double t, double h, bool) {
  if (!allowed({State::step_complete}, "fmi2DoStep")) return fmi2Error;
  if (!(std::isfinite(t) && std::isfinite(h) && h > 0))
    return fail("fmi2DoStep: the communication step must be finite and > 0 (got " +
                std::to_string(h) + " s)");
  if (std::abs(t - time_) > kTimeSlack * std::max(1.0, std::abs(time_)))
    return fail("fmi2DoStep: currentCommunicationPoint " + std::to_string(t) +
                " s is not the instance's time " + std::to_string(time_) + " s");
  if (stop_defined_ && t + h > stop_time_ * (1 + kTimeSlack) + kTimeSlack)
    return fail("fmi2DoStep: the step ends after the experiment's stopTime");
  bool ok = false;
  const WheelInput in = wheel_input(&ok);
  if (!ok) return fail("fmi2DoStep: the wheel state is not usable");
  if (!(in.mu >= 0 && in.mu <= kMaxFriction))
    return fail("input terrain_mu = " + std::to_string(in.mu) + ": must be in [0, 10]");
  try {
    wheel_->step(time_, h, in);
  } catch (const std::exception& e) {
    return fail(std::string("fmi2DoStep at t = ") + std::to_string(time_) + " s: " + e.what());
  }
  time_ = t + h;
  refresh_outputs(in);
  for (int k = 0; k < 3; ++k) {
    const double at_end = real_[vr::pos_x + k] + real_[vr::lin_vel_x + k] * h;
    real_[vr::load_point_x + k] = real_[vr::query_x + k] = at_end;
  }
  return fmi2OK;
}

fmi2Status Instance::terminate() {
  if (!allowed({State::step_complete, State::step_failed}, "fmi2Terminate")) return fmi2Error;
  state_ = State::terminated;
  return fmi2OK;
}

fmi2Status Instance::reset() {
  set_start_values();
  state_ = State::instantiated;
  return fmi2OK;
}

fmi2Status Instance::get_real(const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
  if (!allowed({State::initialization, State::step_complete, State::step_failed, State::terminated,
                State::error},
               "fmi2GetReal"))
    return fmi2Error;
  if (n > 0 && (!vr || !value)) return fail("fmi2GetReal: NULL array");
  if (state_ == State::initialization) {
    // Outputs in initialization mode: the tyre at rest under the current inputs.
    try {
      bool ok = false;
      const WheelInput in = wheel_input(&ok);
      if (ok) {
        WheelSettings settings;
        settings.step_size_s = real_[vr::step_size] > 0 ? real_[vr::step_size] : 1e-3;
        wheel_ = std::make_unique<TyreWheel>(model_, settings);
        wheel_->start(time_, in);
        refresh_outputs(in);
        for (int k = 0; k < 3; ++k)
          real_[vr::load_point_x + k] = real_[vr::query_x + k] = real_[vr::pos_x + k];
      }
    } catch (const std::exception& e) {
      return fail(std::string("fmi2GetReal in initialization mode: ") + e.what());
    }
  }
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] >= real_.size())
      return fail("fmi2GetReal: no Real variable has value reference " + std::to_string(vr[k]));
    value[k] = real_[vr[k]];
  }
  return fmi2OK;
}

fmi2Status Instance::set_real(const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
  if (!allowed({State::instantiated, State::initialization, State::step_complete}, "fmi2SetReal"))
    return fmi2Error;
  if (n > 0 && (!vr || !value)) return fail("fmi2SetReal: NULL array");
  for (size_t k = 0; k < n; ++k) {
    const unsigned r = vr[k];
    const bool parameter = r == vr::step_size;
    if (!(is_input(r) || parameter))
      return fail("fmi2SetReal: value reference " + std::to_string(r) +
                  " is not an input or parameter (outputs cannot be set)");
    if (parameter && state_ == State::step_complete)
      return fail(
          "fmi2SetReal: step_size is a fixed parameter (set it before "
          "fmi2ExitInitializationMode)");
    if (!std::isfinite(value[k]))
      return fail("fmi2SetReal: value reference " + std::to_string(r) + " set to " +
                  std::to_string(value[k]) + " (not finite)");
    if (parameter && !(value[k] > 0 && value[k] <= kMaxStepSize_s))
      return fail("parameter step_size = " + std::to_string(value[k]) + " s: must be in (0, " +
                  std::to_string(kMaxStepSize_s) + "] s");
    if (r == vr::terrain_mu && !(value[k] >= 0 && value[k] <= kMaxFriction))
      return fail("input terrain_mu = " + std::to_string(value[k]) + ": must be in [0, 10]");
  }
  for (size_t k = 0; k < n; ++k) real_[vr[k]] = value[k];
  return fmi2OK;
}

fmi2Status Instance::get_string(const fmi2ValueReference vr[], size_t n, fmi2String value[]) {
  if (!allowed({State::initialization, State::step_complete, State::step_failed, State::terminated,
                State::error},
               "fmi2GetString"))
    return fmi2Error;
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] != vr::road_profile)
      return fail("fmi2GetString: no String variable has value reference " + std::to_string(vr[k]));
    value[k] = road_profile_.c_str();
  }
  return fmi2OK;
}

fmi2Status Instance::set_string(const fmi2ValueReference vr[], size_t n, const fmi2String value[]) {
  if (!allowed({State::instantiated, State::initialization}, "fmi2SetString")) return fmi2Error;
  for (size_t k = 0; k < n; ++k) {
    if (vr[k] != vr::road_profile)
      return fail("fmi2SetString: no String variable has value reference " + std::to_string(vr[k]));
    road_profile_ = value[k] ? value[k] : "";
  }
  return fmi2OK;
}

fmi2Status Instance::unsupported(const char* function) {
  log(fmi2Error, std::string(function) +
                     " is not provided by this FMU (see its capability flags in "
                     "modelDescription.xml)");
  return fmi2Error;
}

fmi2Status Instance::status_real(fmi2StatusKind kind, fmi2Real* value) {
  if (kind != fmi2LastSuccessfulTime || !value) return unsupported("fmi2GetRealStatus");
  *value = time_;
  return fmi2OK;
}

fmi2Status Instance::status_boolean(fmi2StatusKind kind, fmi2Boolean* value) {
  if (kind != fmi2Terminated || !value) return unsupported("fmi2GetBooleanStatus");
  *value = fmi2False;
  return fmi2OK;
}

fmi2Status Instance::status(fmi2StatusKind kind, fmi2Status* value) {
  if (kind != fmi2DoStepStatus || !value) return unsupported("fmi2GetStatus");
  // fmi2DoStep never returns fmi2Pending (the step is computed before it returns).
  log(fmi2Warning, "fmi2GetStatus(fmi2DoStepStatus): no asynchronous step is running");
  *value = fmi2OK;
  return fmi2Discard;
}

}  // namespace modaltyre::fmu
