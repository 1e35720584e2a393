// The instance's life cycle and steps (instance.h); its values are in instance_values.cc.
#include "modaltyre/fmu/instance.h"

#include <cmath>
#include <exception>
#include <filesystem>
#include <sstream>

#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/input_file.h"
#include "modaltyre/fmu/resources.h"
#include "modaltyre/fmu/soil_parameters.h"
#include "modaltyre/fmu/tyre_variables.h"
#include "modaltyre/fmu/tyre_wheel.h"

namespace modaltyre::fmu {
namespace {

/// Relative slack when a communication point is compared with the instance's time.
constexpr double kTimeSlack = 1e-9;
/// Sub-steps (communicationStepSize / step_size) one fmi2DoStep may take: 100 s of simulated
/// time at the default 1 ms, a minute of work on the 3D default. More is refused before the step
/// begins (fmi2DoStep(0, 1e6) never returned), the host being told to take shorter
/// communication steps.
constexpr double kMaxSubStepsPerCall = 1e5;
/// Largest road profile file read (the reader's own bound is on its rows).
constexpr std::uintmax_t kMaxProfileBytes = 64u << 20;

const char* state_name(Instance::State s) {
  static const char* names[] = {"instantiated", "initialization mode", "step complete",
                                "step failed",  "terminated",          "error"};
  return names[static_cast<int>(s)];
}

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
    contact::TyreConfig config = contact::load_tyre_config(record.config_path);
    if (!record.ground_path.empty()) config.ground = ground::load_ground_file(record.ground_path);
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
  const contact::TyreConfig& config = inst->model_->tyre.config;
  TyreDescriptionInfo info;
  info.outer_radius_m = config.outer_radius_m;
  info.friction_coefficient = config.ground.friction_coefficient;
  info.section_height_m = section_height_m(config);
  info.soil = config.ground.soil() ? &config.ground : nullptr;
  info.patch_3d = config.footprint_3d.has_value();
  inst->description_ = tyre_model_description(info);
  inst->run_model_ = inst->model_;
  for (const ScalarVariable& v : inst->description_.variables)
    if (v.type == BaseType::real) {
      if (v.value_reference >= inst->real_vars_.size())
        inst->real_vars_.resize(v.value_reference + 1, nullptr);
      inst->real_vars_[v.value_reference] = &v;
    }
  inst->set_start_values();
  inst->log(fmi2OK, "instantiated from " + inst->resource_folder_);
  return inst.release();
}

void Instance::set_start_values() {
  real_.assign(real_vars_.size(), 0.0);
  for (const ScalarVariable& v : description_.variables) {
    if (v.type == BaseType::real && v.start) real_[v.value_reference] = *v.start;
    if (v.type == BaseType::string && v.start_string) road_profile_ = *v.start_string;
  }
  time_ = start_time_ = 0;
  stop_defined_ = false;
  terminated_ = false;
  wheel_.reset();
}

void Instance::log(fmi2Status status, const std::string& message) const {
  if (!logger_) return;
  const char* category = status == fmi2OK        ? "logEvents"
                         : status == fmi2Warning ? "logStatusWarning"
                         : status == fmi2Discard ? "logStatusDiscard"
                                                 : "logStatusError";
  if (status == fmi2OK && !(logging_ && (categories_.empty() || categories_.count(category))))
    return;
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

fmi2Status Instance::discard_step(const std::string& message) {
  log(fmi2Discard, message + " (the step was not begun: fmi2LastSuccessfulTime is " +
                       std::to_string(time_) +
                       " s; without FMU states the instance cannot go on: "
                       "fmi2Terminate, fmi2Reset or fmi2FreeInstance)");
  state_ = State::step_failed;
  terminated_ = true;
  return fmi2Discard;
}

bool Instance::allowed(std::initializer_list<State> states, const char* function) {
  for (State s : states)
    if (s == state_) return true;
  std::string why = std::string(function) + " is not allowed in state '" + state_name(state_) + "'";
  if (state_ == State::error)
    why +=
        " (an earlier call returned fmi2Error: only fmi2Reset, fmi2FreeInstance and the "
        "fmi2Get functions are allowed)";
  fail(why);
  return false;
}

fmi2Status Instance::set_debug_logging(bool on, size_t n, const fmi2String categories[]) {
  if (state_ == State::error) {
    logging_ = on;  // allowed in every state (the table of section 4.2.4)
    return fmi2OK;
  }
  std::set<std::string> chosen;
  for (size_t k = 0; k < n; ++k) {
    const std::string c = categories && categories[k] ? categories[k] : "";
    bool known = false;
    for (const std::string& d : description_.log_categories) known = known || d == c;
    if (!known) return fail("fmi2SetDebugLogging: '" + c + "' is not a log category of this FMU");
    chosen.insert(c);
  }
  logging_ = on;
  categories_ = chosen;
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

WheelSettings Instance::wheel_settings(std::string* problem) const {
  WheelSettings settings;
  settings.step_size_s = real_[vr::step_size];
  settings.section_height_m = section_height_m(model_->tyre.config);
  if (!road_profile_.empty()) {
    std::filesystem::path p(road_profile_);
    if (p.is_relative()) p = std::filesystem::path(resource_folder_) / p;
    try {
      // The CSV reader takes any bytes in comments; the FMU's profile is UTF-8 text as its YAML
      // config is (core/input_file.h's check, issue 44).
      const std::string text =
          read_input_file(p.string(), "a CSV file", "road profiles", kMaxProfileBytes);
      if (const auto bad = text_problem(text))
        throw InputError(InputLocation{p.string(), bad->line, ""}, bad->message);
      settings.profile =
          std::make_shared<const ground::RoadProfile>(ground::read_road_profile_csv(p.string()));
    } catch (const std::exception& e) {
      *problem = std::string("parameter road_profile: ") + e.what();
    }
  }
  return settings;
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
  if (real_variable(vr::soil_sinkage)) {
    real_[vr::soil_sinkage] = o.soil_sinkage_m;
    real_[vr::compaction_resistance] = o.compaction_resistance_N;
  }
  rim_contact_ = o.rim_contact;
}

fmi2Status Instance::rim_warning(fmi2Status status) {
  const WheelOutput& o = wheel_->output();
  if (!o.rim_contact_started) return status;
  std::ostringstream msg;
  msg << "the rim reaches the road at t = " << o.rim_started_at_s << " s: the tyre's deflection "
      << real_[vr::deflection] * 1e3 << " mm at the step's end, its section height "
      << section_height_m(model_->tyre.config) * 1e3
      << " mm (tyre.rim_contact raised; the load is the tyre's alone, no rim contact force)";
  log(fmi2Warning, msg.str());
  return status == fmi2OK ? fmi2Warning : status;
}

std::shared_ptr<const transient::TransientModel> Instance::soil_model(std::string* problem) {
  const ground::GroundSettings& packed = model_->tyre.config.ground;
  if (!packed.soil()) return model_;
  // The soil's keys as set (parameters from first_soil_parameter on, soil_parameters' order).
  ground::GroundSettings g = packed;
  const std::vector<SoilParameter> keys =
      soil_parameters(packed, model_->tyre.config.footprint_3d.has_value());
  for (std::size_t k = 0; k < keys.size(); ++k) keys[k].set(g, real_[vr::first_soil_parameter + k]);
  const std::string why = soil_combination_problem(g);
  if (!why.empty()) {
    *problem = "soil parameters: " + why;
    return nullptr;
  }
  bool same_as_run = true;
  for (const SoilParameter& p : keys)
    same_as_run = same_as_run && p.get(g) == p.get(run_model_->tyre.config.ground);
  if (!same_as_run) {
    // The model with the soil as set (the soil enters the driven tyre through its config).
    auto m = std::make_shared<transient::TransientModel>(*model_);
    m->tyre.config.ground = g;
    run_model_ = m;
  }
  return run_model_;
}

fmi2Status Instance::standing_outputs(const char* function) {
  bool ok = false;
  const WheelInput in = wheel_input(&ok);
  if (!ok) return fail(std::string(function) + ": the wheel state is not usable");
  std::string problem;
  const WheelSettings settings = wheel_settings(&problem);
  if (!problem.empty()) return fail(problem);
  const auto model = soil_model(&problem);
  if (!model) return fail(std::string(function) + ": " + problem);
  if (settings.profile && model->tyre.config.ground.soil())
    return fail(std::string(function) +
                ": parameter road_profile: a road profile under a tyre on a soil is not "
                "modelled (the soil's undisturbed surface is at terrain_height)");
  try {
    wheel_ = std::make_unique<TyreWheel>(model, settings);
    const std::string refused = wheel_->refusal(in, 0.0);
    if (!refused.empty()) return fail(std::string(function) + ": " + refused);
    wheel_->start(time_, in);
  } catch (const std::exception& e) {
    return fail(std::string(function) + ": " + e.what());
  }
  refresh_outputs(in);
  for (int k = 0; k < 3; ++k)
    real_[vr::load_point_x + k] = real_[vr::query_x + k] = real_[vr::pos_x + k];
  return fmi2OK;
}

fmi2Status Instance::exit_initialization() {
  if (!allowed({State::initialization}, "fmi2ExitInitializationMode")) return fmi2Error;
  const fmi2Status s = standing_outputs("fmi2ExitInitializationMode");
  if (s != fmi2OK) return s;
  state_ = State::step_complete;
  return rim_warning(fmi2OK);
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
  const double substeps = h / real_[vr::step_size];
  if (substeps > kMaxSubStepsPerCall)
    return discard_step("fmi2DoStep: communicationStepSize " + std::to_string(h) + " s is " +
                        std::to_string(substeps) + " sub-steps of parameter step_size " +
                        std::to_string(real_[vr::step_size]) + " s, more than the " +
                        std::to_string(static_cast<long>(kMaxSubStepsPerCall)) +
                        " one call may take: use shorter communication steps");
  bool ok = false;
  const WheelInput in = wheel_input(&ok);
  if (!ok) return fail("fmi2DoStep: the wheel state is not usable");
  const std::string refused = wheel_->refusal(in, h);
  if (!refused.empty())
    return discard_step("fmi2DoStep at t = " + std::to_string(time_) + " s: " + refused);
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
  return rim_warning(fmi2OK);
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

fmi2Status Instance::unsupported(const char* function) {
  return fail(std::string(function) +
              " is not provided by this FMU (see its capability flags in modelDescription.xml)");
}

fmi2Status Instance::status_real(fmi2StatusKind kind, fmi2Real* value) {
  if (kind != fmi2LastSuccessfulTime) return status_not_provided("fmi2GetRealStatus", value);
  if (!value) return fail("fmi2GetRealStatus: the value pointer is NULL");
  *value = time_;
  return fmi2OK;
}

fmi2Status Instance::status_boolean(fmi2StatusKind kind, fmi2Boolean* value) {
  if (kind != fmi2Terminated) return status_not_provided("fmi2GetBooleanStatus", value);
  if (!value) return fail("fmi2GetBooleanStatus: the value pointer is NULL");
  *value = terminated_ ? fmi2True : fmi2False;
  return fmi2OK;
}

fmi2Status Instance::status_not_provided(const char* function, const void* value) {
  if (!value) return fail(std::string(function) + ": the value pointer is NULL");
  // Section 4.2.3: a status the slave cannot give is fmi2Discard. The step is never pending, so
  // fmi2DoStepStatus and fmi2PendingStatus are not provided, and no Integer status exists. A
  // legal call: nothing is logged but with debug logging on.
  log(fmi2OK, std::string(function) + ": this status kind is not provided (fmi2Discard)");
  return fmi2Discard;
}

}  // namespace modaltyre::fmu
