#pragma once
// FMI 2.0 co-simulation interface: the platform types, the callback structure and the functions
// an FMU exports, written from the standard (Functional Mock-up Interface for Model Exchange and
// Co-Simulation, version 2.0, Modelica Association, 2014; section 2.1 "Header files and naming
// of functions", 2.1.2 "Platform dependent definitions", 2.1.5 "Creation, destruction and
// logging", 4.2 "Co-simulation application programming interface"). The FMU is a co-simulation
// FMU only, so the model-exchange functions (fmi2EnterEventMode, fmi2SetTime, ...) are not
// declared. The names carry no prefix: the shared library exports them as they are written here.
#include <cstddef>

extern "C" {

// 2.1.2 Platform dependent definitions ("default" platform).
typedef void* fmi2Component;             ///< pointer to an FMU instance
typedef void* fmi2ComponentEnvironment;  ///< pointer to the host's environment (callbacks)
typedef void* fmi2FMUstate;              ///< pointer to a saved FMU state
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char* fmi2String;
typedef char fmi2Byte;
#define fmi2True 1
#define fmi2False 0

// 2.1.3 Status returned by the functions.
typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;

typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;

// 4.2.3 Status kinds of fmi2Get*Status.
typedef enum {
  fmi2DoStepStatus,
  fmi2PendingStatus,
  fmi2LastSuccessfulTime,
  fmi2Terminated
} fmi2StatusKind;

// 2.1.5 Callbacks the host gives fmi2Instantiate. The logger is a printf-like function: the
// message may contain format directives for the variable arguments.
typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment componentEnvironment,
                                   fmi2String instanceName, fmi2Status status, fmi2String category,
                                   fmi2String message, ...);
typedef void* (*fmi2CallbackAllocateMemory)(size_t nobj, size_t size);
typedef void (*fmi2CallbackFreeMemory)(void* obj);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment componentEnvironment, fmi2Status status);

typedef struct {
  const fmi2CallbackLogger logger;
  const fmi2CallbackAllocateMemory allocateMemory;
  const fmi2CallbackFreeMemory freeMemory;
  const fmi2StepFinished stepFinished;
  const fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

#define MODALTYRE_FMI2_EXPORT __attribute__((visibility("default")))

// 2.1.4 Inquire version numbers of header files.
MODALTYRE_FMI2_EXPORT const char* fmi2GetTypesPlatform(void);
MODALTYRE_FMI2_EXPORT const char* fmi2GetVersion(void);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn,
                                                     size_t nCategories,
                                                     const fmi2String categories[]);

// 2.1.5 Creation and destruction of FMU instances.
MODALTYRE_FMI2_EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType,
                                                    fmi2String fmuGUID,
                                                    fmi2String fmuResourceLocation,
                                                    const fmi2CallbackFunctions* functions,
                                                    fmi2Boolean visible, fmi2Boolean loggingOn);
MODALTYRE_FMI2_EXPORT void fmi2FreeInstance(fmi2Component c);

// 2.1.6 Initialization, termination and resetting an instance.
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined,
                                                     fmi2Real tolerance, fmi2Real startTime,
                                                     fmi2Boolean stopTimeDefined,
                                                     fmi2Real stopTime);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2Terminate(fmi2Component c);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2Reset(fmi2Component c);

// 2.1.7 Getting and setting variable values.
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[],
                                             size_t nvr, fmi2Real value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                                size_t nvr, fmi2Integer value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                                size_t nvr, fmi2Boolean value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[],
                                               size_t nvr, fmi2String value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[],
                                             size_t nvr, const fmi2Real value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[],
                                                size_t nvr, const fmi2Integer value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[],
                                                size_t nvr, const fmi2Boolean value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[],
                                               size_t nvr, const fmi2String value[]);

// 2.1.8 Getting and setting the complete FMU state (canGetAndSetFMUstate = false here: every
// one returns fmi2Error with the reason).
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* FMUstate);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* FMUstate);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate,
                                                            size_t* size);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate,
                                                       fmi2Byte serializedState[], size_t size);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c,
                                                         const fmi2Byte serializedState[],
                                                         size_t size, fmi2FMUstate* FMUstate);

// 2.1.9 Partial derivatives (providesDirectionalDerivative = false: fmi2Error).
MODALTYRE_FMI2_EXPORT fmi2Status
fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown_ref[],
                             size_t nUnknown, const fmi2ValueReference vKnown_ref[], size_t nKnown,
                             const fmi2Real dvKnown[], fmi2Real dvUnknown[]);

// 4.2.1 Transfer of input / output values and parameters (input derivatives: order 0 only,
// maxOutputDerivativeOrder = 0).
MODALTYRE_FMI2_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c,
                                                             const fmi2ValueReference vr[],
                                                             size_t nvr, const fmi2Integer order[],
                                                             const fmi2Real value[]);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c,
                                                              const fmi2ValueReference vr[],
                                                              size_t nvr, const fmi2Integer order[],
                                                              fmi2Real value[]);

// 4.2.2 Computation.
MODALTYRE_FMI2_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                                            fmi2Real communicationStepSize,
                                            fmi2Boolean noSetFMUStatePriorToCurrentPoint);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2CancelStep(fmi2Component c);

// 4.2.3 Retrieving the status of the slave.
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s,
                                               fmi2Status* value);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s,
                                                   fmi2Real* value);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s,
                                                      fmi2Integer* value);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s,
                                                      fmi2Boolean* value);
MODALTYRE_FMI2_EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s,
                                                     fmi2String* value);

}  // extern "C"
