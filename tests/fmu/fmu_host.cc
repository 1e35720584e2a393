#include "fmu_host.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>
#include <zip.h>

#include <atomic>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

namespace modaltyre::fmu::test {
namespace fs = std::filesystem;

const char* const kFmi2CoSimulationFunctions[] = {"fmi2GetTypesPlatform",
                                                  "fmi2GetVersion",
                                                  "fmi2SetDebugLogging",
                                                  "fmi2Instantiate",
                                                  "fmi2FreeInstance",
                                                  "fmi2SetupExperiment",
                                                  "fmi2EnterInitializationMode",
                                                  "fmi2ExitInitializationMode",
                                                  "fmi2Terminate",
                                                  "fmi2Reset",
                                                  "fmi2GetReal",
                                                  "fmi2GetInteger",
                                                  "fmi2GetBoolean",
                                                  "fmi2GetString",
                                                  "fmi2SetReal",
                                                  "fmi2SetInteger",
                                                  "fmi2SetBoolean",
                                                  "fmi2SetString",
                                                  "fmi2GetFMUstate",
                                                  "fmi2SetFMUstate",
                                                  "fmi2FreeFMUstate",
                                                  "fmi2SerializedFMUstateSize",
                                                  "fmi2SerializeFMUstate",
                                                  "fmi2DeSerializeFMUstate",
                                                  "fmi2GetDirectionalDerivative",
                                                  "fmi2SetRealInputDerivatives",
                                                  "fmi2GetRealOutputDerivatives",
                                                  "fmi2DoStep",
                                                  "fmi2CancelStep",
                                                  "fmi2GetStatus",
                                                  "fmi2GetRealStatus",
                                                  "fmi2GetIntegerStatus",
                                                  "fmi2GetBooleanStatus",
                                                  "fmi2GetStringStatus"};
const std::size_t kFmi2CoSimulationFunctionCount =
    sizeof(kFmi2CoSimulationFunctions) / sizeof(kFmi2CoSimulationFunctions[0]);

namespace {

void unzip(const std::string& archive, const fs::path& into) {
  int err = 0;
  zip_t* za = zip_open(archive.c_str(), ZIP_RDONLY, &err);
  ASSERT_NE(za, nullptr) << archive;
  const zip_int64_t n = zip_get_num_entries(za, 0);
  for (zip_int64_t i = 0; i < n; ++i) {
    const std::string name = zip_get_name(za, zip_uint64_t(i), 0);
    zip_stat_t st;
    zip_stat_index(za, zip_uint64_t(i), 0, &st);
    std::string bytes(st.size, '\0');
    zip_file_t* f = zip_fopen_index(za, zip_uint64_t(i), 0);
    ASSERT_NE(f, nullptr) << name;
    ASSERT_EQ(zip_fread(f, bytes.data(), st.size), zip_int64_t(st.size)) << name;
    zip_fclose(f);
    const fs::path out = into / name;
    fs::create_directories(out.parent_path());
    std::ofstream(out, std::ios::binary) << bytes;
  }
  zip_close(za);
}

void logger(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String,
            fmi2String message, ...) {
  char buf[4096];
  va_list args;
  va_start(args, message);
  std::vsnprintf(buf, sizeof buf, message, args);
  va_end(args);
  static_cast<FmuInstance::Log*>(env)->messages.push_back(std::to_string(int(status)) + ": " + buf);
}

}  // namespace

namespace {

/// Packs with `cmd` into dir/tyre.fmu and unzips it to dir/unzipped; "" (and a gtest failure
/// with the packer's output) if `modaltyre fmu` fails.
std::string pack_into(std::string cmd, const fs::path& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir / "unzipped");
  const std::string fmu = (dir / "tyre.fmu").string();
  cmd += " --output " + fmu + " > " + (dir / "pack.log").string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  if (rc != 0) {
    std::ifstream in(dir / "pack.log");
    std::stringstream ss;
    ss << in.rdbuf();
    ADD_FAILURE() << cmd << " failed:\n" << ss.str();
    return "";
  }
  unzip(fmu, dir / "unzipped");
  return (dir / "unzipped").string();
}

/// An exclusive lock on a file for the lifetime of the object (two ctest -j processes may ask
/// for the same FMU at once: one packs, the other waits and reuses).
class FileLock {
 public:
  explicit FileLock(const fs::path& path) : fd_(::open(path.c_str(), O_RDWR | O_CREAT, 0644)) {
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~FileLock() {
    if (fd_ >= 0) ::close(fd_);  // closing releases the lock
  }
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_;
};

}  // namespace

std::string pack_and_unzip(const std::string& config, const std::vector<std::string>& sets,
                           const std::string& ground) {
  std::string cmd = std::string(MODALTYRE_CLI) + " fmu " + config;
  for (const std::string& s : sets) cmd += " --set " + s;
  if (!ground.empty()) cmd += " --ground " + ground;
  // Under ctest: one packed folder per distinct command in the run's cache (tests/CMakeLists.txt,
  // the FmuPackCache fixture empties it first, so a rebuilt modaltyre is always repacked).
  if (const char* cache = std::getenv("MODALTYRE_FMU_PACK_CACHE"); cache && *cache) {
    std::ostringstream key;
    key << std::hex << std::hash<std::string>{}(cmd);
    const fs::path dir = fs::path(cache) / key.str();
    fs::create_directories(cache);
    const FileLock lock(fs::path(cache) / (key.str() + ".lock"));
    std::ifstream done(dir / "complete");
    std::string packed;
    if (std::getline(done, packed) && packed == cmd) return (dir / "unzipped").string();
    std::string folder = pack_into(cmd, dir);
    if (!folder.empty()) std::ofstream(dir / "complete") << cmd << "\n";
    return folder;
  }
  static std::atomic<int> counter{0};
  return pack_into(
      cmd, fs::temp_directory_path() / ("modaltyre_fmu_test_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter++)));
}

const FmuFolder& road_2d_fmu() {
  static const std::string folder =
      pack_and_unzip(std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml");
  static const FmuFolder fmu(folder);
  return fmu;
}

FmuFolder::FmuFolder(const std::string& folder) : folder_(folder) {
  std::ifstream in(fs::path(folder) / "modelDescription.xml");
  std::stringstream ss;
  ss << in.rdbuf();
  xml_ = ss.str();
  std::smatch m;
  if (std::regex_search(xml_, m, std::regex("guid=\"([^\"]+)\""))) guid_ = m[1];
  const std::regex var("<ScalarVariable name=\"([^\"]+)\" valueReference=\"([0-9]+)\"");
  for (auto it = std::sregex_iterator(xml_.begin(), xml_.end(), var); it != std::sregex_iterator();
       ++it)
    refs_[(*it)[1]] = unsigned(std::stoul((*it)[2]));
  const std::string so = (fs::path(folder) / "binaries/linux64/ModalTyre.so").string();
  api_.handle = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!api_.handle) {
    ADD_FAILURE() << "dlopen " << so << ": " << dlerror();
    return;
  }
  auto sym = [&](auto& fn, const char* name) {
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(api_.handle, name));
    EXPECT_NE(fn, nullptr) << name;
  };
  sym(api_.instantiate, "fmi2Instantiate");
  sym(api_.free_instance, "fmi2FreeInstance");
  sym(api_.setup_experiment, "fmi2SetupExperiment");
  sym(api_.enter_initialization, "fmi2EnterInitializationMode");
  sym(api_.exit_initialization, "fmi2ExitInitializationMode");
  sym(api_.do_step, "fmi2DoStep");
  sym(api_.get_real, "fmi2GetReal");
  sym(api_.set_real, "fmi2SetReal");
  sym(api_.set_string, "fmi2SetString");
  sym(api_.terminate, "fmi2Terminate");
  sym(api_.reset, "fmi2Reset");
  sym(api_.get_version, "fmi2GetVersion");
  sym(api_.get_types_platform, "fmi2GetTypesPlatform");
  sym(api_.get_string, "fmi2GetString");
  sym(api_.get_boolean, "fmi2GetBoolean");
  sym(api_.set_debug_logging, "fmi2SetDebugLogging");
  sym(api_.get_status, "fmi2GetStatus");
  sym(api_.get_real_status, "fmi2GetRealStatus");
  sym(api_.get_integer_status, "fmi2GetIntegerStatus");
  sym(api_.get_boolean_status, "fmi2GetBooleanStatus");
  sym(api_.get_string_status, "fmi2GetStringStatus");
}

FmuFolder::~FmuFolder() {
  if (api_.handle) dlclose(api_.handle);
}

unsigned FmuFolder::vr(const std::string& name) const {
  auto it = refs_.find(name);
  if (it == refs_.end()) {
    ADD_FAILURE() << "no variable " << name << " in modelDescription.xml";
    return unsigned(-1);
  }
  return it->second;
}

FmuInstance::FmuInstance(const FmuFolder& fmu, const std::string& name, const std::string& guid,
                         fmi2Type type)
    : fmu_(fmu), callbacks_{logger, nullptr, nullptr, nullptr, &log_} {
  if (!fmu.api().instantiate) return;
  c_ = fmu.api().instantiate(name.c_str(), type, (guid.empty() ? fmu.guid() : guid).c_str(),
                             fmu.resource_uri().c_str(), &callbacks_, fmi2False, fmi2False);
}

FmuInstance::~FmuInstance() {
  if (c_) fmu_.api().free_instance(c_);
}

fmi2Status FmuInstance::set(const std::string& name, double value) {
  const fmi2ValueReference r = fmu_.vr(name);
  return fmu_.api().set_real(c_, &r, 1, &value);
}

double FmuInstance::get(const std::string& name) {
  const fmi2ValueReference r = fmu_.vr(name);
  double v = std::nan("");
  EXPECT_EQ(fmu_.api().get_real(c_, &r, 1, &v), fmi2OK) << name;
  return v;
}

void FmuInstance::set_wheel(double x, double z, double vx, double vz, double angle, double spin) {
  set("wheel_state.pos.x", x);
  set("wheel_state.pos.z", z);
  set("wheel_state.lin_vel.x", vx);
  set("wheel_state.lin_vel.z", vz);
  set("wheel_state.rot.e0", std::cos(angle / 2));
  set("wheel_state.rot.e2", std::sin(angle / 2));
  set("wheel_state.ang_vel.y", spin);
}

fmi2Status FmuInstance::initialize() {
  fmi2Status s = fmu_.api().setup_experiment(c_, fmi2False, 0, 0, fmi2False, 0);
  if (s != fmi2OK) return s;
  s = fmu_.api().enter_initialization(c_);
  if (s != fmi2OK) return s;
  return fmu_.api().exit_initialization(c_);
}

fmi2Status FmuInstance::step(double h) {
  const fmi2Status s = fmu_.api().do_step(c_, t_, h, fmi2True);
  if (s == fmi2OK || s == fmi2Warning) t_ += h;
  return s;
}

fmi2Status FmuInstance::reset() {
  t_ = 0;
  return fmu_.api().reset(c_);
}

bool FmuInstance::logged(const std::string& text) const {
  for (const std::string& m : log_.messages)
    if (m.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace modaltyre::fmu::test
