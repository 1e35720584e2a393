// The exported FMI 2.0 co-simulation functions (fmi2.h): each checks its component pointer and
// hands the call to the Instance (instance.h), which never throws. Compiled into the FMU's
// shared library only (fmu/CMakeLists.txt).
//
// The component pointers handed out are kept in a registry: a call with a pointer that is not a
// live instance (freed already, never created) returns fmi2Error, and a second fmi2FreeInstance
// of the same pointer does nothing (it aborted in free() before). A pointer freed and then
// handed out again by a later fmi2Instantiate is that new instance: the registry cannot tell a
// stale copy of it.
#include <mutex>
#include <new>
#include <set>

#include "modaltyre/fmu/fmi2.h"
#include "modaltyre/fmu/instance.h"

using modaltyre::fmu::Instance;

namespace {

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}
std::set<const void*>& registry() {
  static std::set<const void*> live;
  return live;
}

Instance* as_instance(fmi2Component c) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  return registry().count(c) ? static_cast<Instance*>(c) : nullptr;
}

}  // namespace

#define MODALTYRE_INSTANCE_OR_ERROR(c) \
  Instance* inst = as_instance(c);     \
  if (!inst) return fmi2Error

extern "C" {

const char* fmi2GetTypesPlatform(void) { return "default"; }
const char* fmi2GetVersion(void) { return "2.0"; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->set_debug_logging(loggingOn == fmi2True, nCategories, categories);
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions* functions, fmi2Boolean,
                              fmi2Boolean loggingOn) {
  try {
    Instance* inst =
        Instance::create(instanceName, fmuType, fmuGUID, fmuResourceLocation, functions, loggingOn);
    if (inst) {
      std::lock_guard<std::mutex> lock(registry_mutex());
      registry().insert(inst);
    }
    return inst;
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

void fmi2FreeInstance(fmi2Component c) {
  {
    std::lock_guard<std::mutex> lock(registry_mutex());
    if (registry().erase(c) == 0) return;  // not a live instance: freed already, or never one
  }
  delete static_cast<Instance*>(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->setup_experiment(toleranceDefined == fmi2True, tolerance, startTime,
                                stopTimeDefined == fmi2True, stopTime);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->enter_initialization();
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->exit_initialization();
}

fmi2Status fmi2Terminate(fmi2Component c) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->terminate();
}

fmi2Status fmi2Reset(fmi2Component c) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->reset();
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->get_real(vr, nvr, value);
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference[], size_t nvr, fmi2Integer[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->no_variables("fmi2GetInteger", nvr);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->get_boolean(vr, nvr, value);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->get_string(vr, nvr, value);
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->set_real(vr, nvr, value);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                          const fmi2Integer[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->no_variables("fmi2SetInteger", nvr);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference[], size_t nvr,
                          const fmi2Boolean[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->no_variables("fmi2SetBoolean", nvr);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->set_string(vr, nvr, value);
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate*) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2GetFMUstate");
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2SetFMUstate");
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate*) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2FreeFMUstate");
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate, size_t*) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2SerializedFMUstateSize");
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate, fmi2Byte[], size_t) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2SerializeFMUstate");
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte[], size_t, fmi2FMUstate*) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2DeSerializeFMUstate");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2ValueReference[], size_t, const fmi2Real[],
                                        fmi2Real[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2GetDirectionalDerivative");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                       const fmi2Integer[], const fmi2Real[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2SetRealInputDerivatives (canInterpolateInputs = false)");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2GetRealOutputDerivatives (maxOutputDerivativeOrder = 0)");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize,
                      fmi2Boolean noSetFMUStatePriorToCurrentPoint) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->do_step(currentCommunicationPoint, communicationStepSize,
                       noSetFMUStatePriorToCurrentPoint == fmi2True);
}

fmi2Status fmi2CancelStep(fmi2Component c) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->unsupported("fmi2CancelStep (fmi2DoStep never returns fmi2Pending)");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status* value) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->status_not_provided("fmi2GetStatus", value);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real* value) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->status_real(s, value);
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer* value) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->status_not_provided("fmi2GetIntegerStatus", value);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean* value) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->status_boolean(s, value);
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String* value) {
  MODALTYRE_INSTANCE_OR_ERROR(c);
  return inst->status_not_provided("fmi2GetStringStatus", value);
}

}  // extern "C"
