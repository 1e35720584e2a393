// A host that needs nothing but glibc (C library calls only; linked without the C++ runtime,
// which tests/fmu/clean_load.cmake checks): loads an unzipped FMU's ModalTyre.so with dlopen,
// presses the tyre 10 mm for 20 ms through the fmi2 functions, and lists every shared object
// the process then holds (dl_iterate_phdr). Exit 0 when the press gives a finite load and the
// process holds nothing but glibc's libraries and the FMU itself; otherwise a message and 1.
//   clean_host FOLDER      (FOLDER: the unzipped FMU)
#include <dlfcn.h>
#include <link.h>

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "modaltyre/fmu/fmi2.h"

namespace {

char xml[1 << 20];

/// The value reference of a variable, or the start value of wheel_state.pos.z (R0), from the
/// description's text: `<ScalarVariable name="NAME" valueReference="N"`.
bool attribute_after(const char* name, const char* attribute, double* out) {
  char key[128];
  std::snprintf(key, sizeof key, "name=\"%s\"", name);
  const char* p = std::strstr(xml, key);
  if (!p) return false;
  p = std::strstr(p, attribute);
  return p && std::sscanf(p + std::strlen(attribute), "%lf", out) == 1;
}

void logger(fmi2ComponentEnvironment, fmi2String, fmi2Status status, fmi2String, fmi2String msg,
            ...) {
  std::va_list args;
  va_start(args, msg);
  std::fprintf(stderr, "[fmu %d] ", int(status));
  std::vfprintf(stderr, msg, args);
  std::fprintf(stderr, "\n");
  va_end(args);
}

int foreign = 0;

int list_object(dl_phdr_info* info, size_t, void*) {
  const char* path = info->dlpi_name;
  if (!path || !*path) return 0;  // the executable itself
  const char* base = std::strrchr(path, '/');
  base = base ? base + 1 : path;
  static const char* allowed[] = {"libc.so.6", "libm.so.6", "ld-linux-x86-64.so.2",
                                  "linux-vdso.so.1", "ModalTyre.so"};
  bool ok = false;
  for (const char* a : allowed) ok = ok || std::strcmp(base, a) == 0;
  std::printf("loaded: %s%s\n", path, ok ? "" : "   <- not glibc's nor the FMU's");
  foreign += !ok;
  return 0;
}

template <class F>
F symbol(void* lib, const char* name) {
  F f = reinterpret_cast<F>(dlsym(lib, name));
  if (!f) {
    std::fprintf(stderr, "missing %s\n", name);
    std::exit(1);
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) return std::fprintf(stderr, "usage: clean_host FOLDER\n"), 1;
  char path[4096];
  std::snprintf(path, sizeof path, "%s/modelDescription.xml", argv[1]);
  FILE* in = std::fopen(path, "rb");
  if (!in) return std::fprintf(stderr, "cannot read %s\n", path), 1;
  xml[std::fread(xml, 1, sizeof xml - 1, in)] = '\0';
  std::fclose(in);
  char guid[128] = "";
  const char* g = std::strstr(xml, "guid=\"");
  if (!g || std::sscanf(g + 6, "%127[^\"]", guid) != 1) return std::fprintf(stderr, "no guid\n"), 1;
  double vr_z = 0, vr_fz = 0, r0 = 0;
  if (!attribute_after("wheel_state.pos.z", "valueReference=\"", &vr_z) ||
      !attribute_after("wheel_load.force.z", "valueReference=\"", &vr_fz) ||
      !attribute_after("wheel_state.pos.z", "start=\"", &r0))
    return std::fprintf(stderr, "variables not found in the description\n"), 1;

  std::snprintf(path, sizeof path, "%s/binaries/linux64/ModalTyre.so", argv[1]);
  void* lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (!lib) return std::fprintf(stderr, "dlopen: %s\n", dlerror()), 1;
  auto instantiate = symbol<decltype(&fmi2Instantiate)>(lib, "fmi2Instantiate");
  auto setup = symbol<decltype(&fmi2SetupExperiment)>(lib, "fmi2SetupExperiment");
  auto enter = symbol<decltype(&fmi2EnterInitializationMode)>(lib, "fmi2EnterInitializationMode");
  auto exit_init = symbol<decltype(&fmi2ExitInitializationMode)>(lib, "fmi2ExitInitializationMode");
  auto set_real = symbol<decltype(&fmi2SetReal)>(lib, "fmi2SetReal");
  auto get_real = symbol<decltype(&fmi2GetReal)>(lib, "fmi2GetReal");
  auto do_step = symbol<decltype(&fmi2DoStep)>(lib, "fmi2DoStep");
  auto terminate = symbol<decltype(&fmi2Terminate)>(lib, "fmi2Terminate");
  auto free_instance = symbol<decltype(&fmi2FreeInstance)>(lib, "fmi2FreeInstance");

  char uri[4200];
  std::snprintf(uri, sizeof uri, "file://%s/resources", argv[1]);
  const fmi2CallbackFunctions callbacks = {logger, nullptr, nullptr, nullptr, nullptr};
  fmi2Component c = instantiate("clean", fmi2CoSimulation, guid, uri, &callbacks, 0, 0);
  if (!c) return std::fprintf(stderr, "fmi2Instantiate failed\n"), 1;
  const fmi2ValueReference z = fmi2ValueReference(vr_z), fz = fmi2ValueReference(vr_fz);
  double force = std::nan(""), height = r0;
  bool ok = setup(c, 0, 0, 0, 0, 0) == fmi2OK && enter(c) == fmi2OK &&
            set_real(c, &z, 1, &height) == fmi2OK && exit_init(c) == fmi2OK;
  for (int k = 0; ok && k < 20; ++k) {
    height = r0 - 0.010 * std::fmin(1.0, (k + 1) / 10.0);
    ok = set_real(c, &z, 1, &height) == fmi2OK && do_step(c, k * 1e-3, 1e-3, 1) == fmi2OK;
  }
  ok = ok && get_real(c, &fz, 1, &force) == fmi2OK;
  ok = terminate(c) == fmi2OK && ok;
  free_instance(c);
  std::printf("F_z after a 10 mm press: %.3f N\n", force);
  dl_iterate_phdr(list_object, nullptr);
  if (!ok || !(force > 0) || !std::isfinite(force))
    return std::fprintf(stderr, "the press failed\n"), 1;
  if (foreign > 0)
    return std::fprintf(stderr, "%d shared objects beyond glibc's and the FMU's\n", foreign), 1;
  dlclose(lib);
  return 0;
}
