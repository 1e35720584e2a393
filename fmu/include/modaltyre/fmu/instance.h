#pragma once
// One FMU instance: FMI 2.0's co-simulation state machine (section 4.2.4) around a TyreWheel,
// the variables' values, and the messages through the host's logger. The exported fmi2
// functions (fmi2_exports.cc) only translate calls into these member functions; nothing here
// throws out: every failure becomes fmi2Error (or fmi2Fatal) with its reason logged.
#include <memory>
#include <string>
#include <vector>

#include "modaltyre/fmu/fmi2.h"

// Declared only: this header is what the exported functions see, and they are compiled into the
// shared library with the fmu headers alone (fmu/CMakeLists.txt).
namespace modaltyre::transient {
struct TransientModel;
}

namespace modaltyre::fmu {

class TyreWheel;
struct WheelInput;

class Instance {
 public:
  enum class State { instantiated, initialization, step_complete, step_failed, terminated, error };

  /// Reads the resources (fmu.yaml, the config) and builds the model; nullptr after logging the
  /// reason when anything is wrong (the GUID, the type, the resources, the config).
  static Instance* create(fmi2String instance_name, fmi2Type type, fmi2String guid,
                          fmi2String resource_location, const fmi2CallbackFunctions* functions,
                          fmi2Boolean logging_on);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  fmi2Status set_debug_logging(bool on);
  fmi2Status setup_experiment(bool tolerance_defined, double tolerance, double start_time,
                              bool stop_defined, double stop_time);
  fmi2Status enter_initialization();
  fmi2Status exit_initialization();
  fmi2Status do_step(double t, double h, bool no_set_prior);
  fmi2Status terminate();
  fmi2Status reset();
  fmi2Status get_real(const fmi2ValueReference vr[], size_t n, fmi2Real value[]);
  fmi2Status set_real(const fmi2ValueReference vr[], size_t n, const fmi2Real value[]);
  fmi2Status get_string(const fmi2ValueReference vr[], size_t n, fmi2String value[]);
  fmi2Status set_string(const fmi2ValueReference vr[], size_t n, const fmi2String value[]);
  /// A function this FMU does not provide (its capability flag says so): fmi2Error, logged.
  fmi2Status unsupported(const char* function);
  /// fmi2GetStatus and friends: the step is never pending, so only the time and the
  /// terminated flag have meaningful values.
  fmi2Status status_real(fmi2StatusKind kind, fmi2Real* value);
  fmi2Status status_boolean(fmi2StatusKind kind, fmi2Boolean* value);
  fmi2Status status(fmi2StatusKind kind, fmi2Status* value);

  /// Logs through the host's logger (category logStatusError, logStatusWarning or logEvents);
  /// info messages only with logging on.
  void log(fmi2Status status, const std::string& message) const;
  State state() const { return state_; }
  double time() const { return time_; }

 private:
  Instance() = default;
  /// Start values of every variable (also what fmi2Reset returns to).
  void set_start_values();
  fmi2Status fail(const std::string& message, fmi2Status status = fmi2Error);
  bool allowed(std::initializer_list<State> states, const char* function);
  WheelInput wheel_input(bool* ok);
  void refresh_outputs(const WheelInput& in);

  std::string name_;
  fmi2CallbackLogger logger_ = nullptr;
  fmi2ComponentEnvironment environment_ = nullptr;
  bool logging_ = false;
  State state_ = State::instantiated;
  std::string resource_folder_;
  std::shared_ptr<const transient::TransientModel> model_;
  std::unique_ptr<TyreWheel> wheel_;
  std::vector<double> real_;  ///< every Real by value reference
  std::string road_profile_;
  double time_ = 0, start_time_ = 0;
  bool stop_defined_ = false;
  double stop_time_ = 0;
};

}  // namespace modaltyre::fmu
