#pragma once
// A minimal FMI 2.0 co-simulation host for the tests: packs an FMU with the built `modaltyre
// fmu`, unzips it (libzip) into a fresh folder, loads binaries/linux64/ModalTyre.so with dlopen
// and calls the fmi2 functions by name, as a host that sees nothing else of the project would.
// Value references are read from the unzipped modelDescription.xml.
#include <map>
#include <string>
#include <vector>

#include "modaltyre/fmu/fmi2.h"

namespace modaltyre::fmu::test {

/// Packs `config` (with --set overrides, on the soil file `ground` when given) into a unique
/// folder under the temp dir, unzips it and returns that folder ("" after a gtest failure).
std::string pack_and_unzip(const std::string& config, const std::vector<std::string>& sets = {},
                           const std::string& ground = "");

/// The FMU of configs/sf350_2d_table3.yaml (the 2D variant: fast), packed once per process.
class FmuFolder;
const FmuFolder& road_2d_fmu();

/// The fmi2 functions of a loaded shared library.
struct Fmi2Api {
  void* handle = nullptr;
  decltype(&fmi2Instantiate) instantiate = nullptr;
  decltype(&fmi2FreeInstance) free_instance = nullptr;
  decltype(&fmi2SetupExperiment) setup_experiment = nullptr;
  decltype(&fmi2EnterInitializationMode) enter_initialization = nullptr;
  decltype(&fmi2ExitInitializationMode) exit_initialization = nullptr;
  decltype(&fmi2DoStep) do_step = nullptr;
  decltype(&fmi2GetReal) get_real = nullptr;
  decltype(&fmi2SetReal) set_real = nullptr;
  decltype(&fmi2SetString) set_string = nullptr;
  decltype(&fmi2Terminate) terminate = nullptr;
  decltype(&fmi2Reset) reset = nullptr;
  decltype(&fmi2GetVersion) get_version = nullptr;
  decltype(&fmi2GetTypesPlatform) get_types_platform = nullptr;
  decltype(&fmi2GetString) get_string = nullptr;
  decltype(&fmi2GetBoolean) get_boolean = nullptr;
  decltype(&fmi2SetDebugLogging) set_debug_logging = nullptr;
  decltype(&fmi2GetStatus) get_status = nullptr;
  decltype(&fmi2GetRealStatus) get_real_status = nullptr;
  decltype(&fmi2GetIntegerStatus) get_integer_status = nullptr;
  decltype(&fmi2GetBooleanStatus) get_boolean_status = nullptr;
  decltype(&fmi2GetStringStatus) get_string_status = nullptr;
};

/// The standard's co-simulation function names (all must be exported).
extern const char* const kFmi2CoSimulationFunctions[];
extern const std::size_t kFmi2CoSimulationFunctionCount;

/// One loaded FMU (the library is dlopen'ed once per FmuFolder; instances share it).
class FmuFolder {
 public:
  explicit FmuFolder(const std::string& folder);
  ~FmuFolder();
  const Fmi2Api& api() const { return api_; }
  const std::string& guid() const { return guid_; }
  std::string resource_uri() const { return "file://" + folder_ + "/resources"; }
  const std::string& folder() const { return folder_; }
  /// Value reference of a variable by name (gtest failure and -1 if absent).
  unsigned vr(const std::string& name) const;
  const std::string& description() const { return xml_; }

 private:
  std::string folder_, xml_, guid_;
  std::map<std::string, unsigned> refs_;
  Fmi2Api api_;
};

/// One instance with a logger that keeps its messages.
class FmuInstance {
 public:
  /// `guid` and `type` replace the FMU's own (tests of refusals).
  explicit FmuInstance(const FmuFolder& fmu, const std::string& name = "tyre",
                       const std::string& guid = "", fmi2Type type = fmi2CoSimulation);
  ~FmuInstance();
  bool ok() const { return c_ != nullptr; }
  fmi2Component component() const { return c_; }
  /// Sets a Real by name; returns the status.
  fmi2Status set(const std::string& name, double value);
  double get(const std::string& name);
  /// The wheel upright, heading +x, at (x, z) moving at (vx, vz), spun by `angle` about its
  /// axis at `spin` [rad/s].
  void set_wheel(double x, double z, double vx, double vz, double angle, double spin);
  /// Setup (start 0, no stop), enter and exit initialization.
  fmi2Status initialize();
  fmi2Status step(double h);
  /// fmi2Reset, and the host's clock back to 0.
  fmi2Status reset();
  double time() const { return t_; }
  const std::vector<std::string>& messages() const { return log_.messages; }
  bool logged(const std::string& text) const;

  struct Log {
    std::vector<std::string> messages;
  };

 private:
  const FmuFolder& fmu_;
  Log log_;
  fmi2CallbackFunctions callbacks_;
  fmi2Component c_ = nullptr;
  double t_ = 0;
};

}  // namespace modaltyre::fmu::test
