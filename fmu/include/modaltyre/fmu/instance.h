#pragma once
// One FMU instance: FMI 2.0's co-simulation state machine (section 4.2.4) around a TyreWheel,
// the variables' values, and the messages through the host's logger. The exported fmi2
// functions (fmi2_exports.cc) only translate calls into these member functions; nothing here
// throws out.
//
// Statuses (sections 2.1.3, 4.2.2, 4.2.3):
//  - fmi2Discard: a value outside its variable's declared [min, max] (or not finite) at
//    fmi2SetXXX, which is then not taken (section 2.2.7's recommendation for parameters, the
//    FMU's choice for inputs); a status this FMU does not provide (fmi2GetXXXStatus); a
//    communication step the FMU cannot compute from its inputs (the hub's centre at or below
//    the road, more sub-steps than one call may take), which is then not begun: the instance
//    goes to stepFailed and fmi2Terminated is true (without FMU states it cannot go back).
//  - fmi2Error: a call the standard does not allow in the instance's state, a value reference
//    that is not a variable of the call's type and causality, a failed computation; the
//    instance then refuses every call but fmi2GetXXX (for debugging), fmi2Reset and
//    fmi2FreeInstance (section 2.1.3).
//  - fmi2Warning: a step (or the start) in which the rim reached the road (tyre.rim_contact).
// Every fmi2Discard, fmi2Warning and fmi2Error comes with its reason through the logger.
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "modaltyre/fmu/fmi2.h"
#include "modaltyre/fmu/model_description.h"

// Declared only: this header is what the exported functions see, and they are compiled into the
// shared library with the fmu headers alone (fmu/CMakeLists.txt).
namespace modaltyre::transient {
struct TransientModel;
}

namespace modaltyre::fmu {

class TyreWheel;
struct WheelInput;
struct WheelSettings;

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

  fmi2Status set_debug_logging(bool on, size_t n, const fmi2String categories[]);
  fmi2Status setup_experiment(bool tolerance_defined, double tolerance, double start_time,
                              bool stop_defined, double stop_time);
  fmi2Status enter_initialization();
  fmi2Status exit_initialization();
  fmi2Status do_step(double t, double h, bool no_set_prior);
  fmi2Status terminate();
  fmi2Status reset();
  fmi2Status get_real(const fmi2ValueReference vr[], size_t n, fmi2Real value[]);
  fmi2Status set_real(const fmi2ValueReference vr[], size_t n, const fmi2Real value[]);
  fmi2Status get_boolean(const fmi2ValueReference vr[], size_t n, fmi2Boolean value[]);
  fmi2Status get_string(const fmi2ValueReference vr[], size_t n, fmi2String value[]);
  fmi2Status set_string(const fmi2ValueReference vr[], size_t n, const fmi2String value[]);
  /// A call with a value reference of a type this FMU has no variable of: fmi2OK for nvr = 0,
  /// else fmi2Error.
  fmi2Status no_variables(const char* function, size_t n);
  /// A function this FMU does not provide (its capability flag says so): fmi2Error, logged.
  fmi2Status unsupported(const char* function);
  /// fmi2GetXXXStatus: fmi2LastSuccessfulTime and fmi2Terminated are provided; every other kind
  /// (the step is never pending) is fmi2Discard, logged only with debug logging on.
  fmi2Status status_real(fmi2StatusKind kind, fmi2Real* value);
  fmi2Status status_boolean(fmi2StatusKind kind, fmi2Boolean* value);
  /// fmi2GetStatus, fmi2GetIntegerStatus, fmi2GetStringStatus: nothing this FMU provides.
  fmi2Status status_not_provided(const char* function, const void* value);

  /// Logs through the host's logger (category logStatusError, logStatusDiscard,
  /// logStatusWarning or logEvents); info messages only with logging on, and only categories
  /// the host enabled (fmi2SetDebugLogging).
  void log(fmi2Status status, const std::string& message) const;
  State state() const { return state_; }
  double time() const { return time_; }

 private:
  Instance() = default;
  /// Start values of every variable (also what fmi2Reset returns to).
  void set_start_values();
  /// Logs and returns `status`; fmi2Error and fmi2Fatal put the instance into its error state.
  fmi2Status fail(const std::string& message, fmi2Status status = fmi2Error);
  /// A communication step refused before it began (fmi2Discard, stepFailed, terminated).
  fmi2Status discard_step(const std::string& message);
  bool allowed(std::initializer_list<State> states, const char* function);
  WheelInput wheel_input(bool* ok);
  WheelSettings wheel_settings(std::string* problem) const;
  void refresh_outputs(const WheelInput& in);
  /// A warning when the rim reached the road in the last step (fmi2Warning in place of OK).
  fmi2Status rim_warning(fmi2Status status);
  /// The model to run: the packed one, or on a soil a copy with the soil's keys as the
  /// parameters set (kept while they stay); nullptr with the reason when they cannot be run.
  std::shared_ptr<const transient::TransientModel> soil_model(std::string* problem);
  /// The tyre at rest under the current inputs (initialization mode's outputs).
  fmi2Status standing_outputs(const char* function);
  /// Whether an fmi2GetXXX call may read (its state, its arrays); false after failing it.
  bool readable(const char* function, size_t n, const void* vr, const void* value);
  /// The Real variable of a value reference (nullptr if none).
  const ScalarVariable* real_variable(unsigned vr) const;
  /// Why `value` cannot be set on `v` (empty: it can).
  std::string refusal(const ScalarVariable& v, double value) const;

  std::string name_;
  fmi2CallbackLogger logger_ = nullptr;
  fmi2ComponentEnvironment environment_ = nullptr;
  bool logging_ = false;
  std::set<std::string> categories_;  ///< enabled debug categories (empty: all)
  State state_ = State::instantiated;
  bool terminated_ = false;  ///< fmi2Terminated: the slave cannot go on (after a discarded step)
  std::string resource_folder_;
  std::shared_ptr<const transient::TransientModel> model_;      ///< as packed
  std::shared_ptr<const transient::TransientModel> run_model_;  ///< with the soil as set
  ModelDescription description_;
  std::vector<const ScalarVariable*> real_vars_;  ///< by value reference
  std::unique_ptr<TyreWheel> wheel_;
  std::vector<double> real_;  ///< every Real by value reference
  std::string road_profile_;
  bool rim_contact_ = false;  ///< Boolean tyre.rim_contact
  double time_ = 0, start_time_ = 0;
  bool stop_defined_ = false;
  double stop_time_ = 0;
};

}  // namespace modaltyre::fmu
