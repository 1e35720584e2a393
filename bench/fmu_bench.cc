// Real-time factor of the tyre FMU through its fmi2 functions at 1 ms communication steps
// (issue 34: >= 10x on the 2D tyre, >= 1x on the 3D default). The FMU is packed from the config
// (fmu::write_fmu), unzipped, and its ModalTyre.so dlopen'ed as a host would; the host's own
// work (a quarter-car or a load-controlled hub, semi-implicit Euler) is included, the model's
// build in fmi2Instantiate is not (counted as instantiate_s). MODALTYRE_BENCH_3D=1: the default
// config (configs/sf350.yaml, 3D patch); MODALTYRE_BENCH_STEP_MS: the communication step.
// Run: build/bench/fmu_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <unistd.h>
#include <zip.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>

#include "instruction_set_context.h"
#include "modaltyre/fmu/fmi2.h"
#include "modaltyre/fmu/package.h"

namespace {
namespace fs = std::filesystem;

bool patch_3d() {
  const char* v = std::getenv("MODALTYRE_BENCH_3D");
  return v && std::string(v) == "1";
}
double step_s() {
  const char* v = std::getenv("MODALTYRE_BENCH_STEP_MS");
  return v ? std::atof(v) * 1e-3 : 1e-3;
}
double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The packed, unzipped and loaded FMU (once per process).
struct Loaded {
  std::string folder, guid;
  std::map<std::string, unsigned> vr;
  void* handle = nullptr;
  decltype(&fmi2Instantiate) instantiate;
  decltype(&fmi2FreeInstance) free_instance;
  decltype(&fmi2SetupExperiment) setup;
  decltype(&fmi2EnterInitializationMode) enter;
  decltype(&fmi2ExitInitializationMode) exit;
  decltype(&fmi2DoStep) do_step;
  decltype(&fmi2GetReal) get_real;
  decltype(&fmi2SetReal) set_real;
  decltype(&fmi2SetString) set_string;
  double R0 = 0;
};

const Loaded& loaded() {
  static const Loaded L = [] {
    Loaded l;
    const fs::path dir =
        fs::temp_directory_path() / ("modaltyre_fmu_bench_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "fmu");
    modaltyre::fmu::PackageOptions o;
    o.config_path = std::string(MODALTYRE_SOURCE_DIR) +
                    (patch_3d() ? "/configs/sf350.yaml" : "/configs/sf350_2d_table3.yaml");
    o.output_path = (dir / "tyre.fmu").string();
    o.binary_path = MODALTYRE_FMU_SO;
    modaltyre::fmu::write_fmu(o);
    int err = 0;
    zip_t* za = zip_open(o.output_path.c_str(), ZIP_RDONLY, &err);
    for (zip_int64_t i = 0; i < zip_get_num_entries(za, 0); ++i) {
      zip_stat_t st;
      zip_stat_index(za, i, 0, &st);
      std::string bytes(st.size, '\0');
      zip_file_t* f = zip_fopen_index(za, i, 0);
      zip_fread(f, bytes.data(), st.size);
      zip_fclose(f);
      const fs::path out = dir / "fmu" / st.name;
      fs::create_directories(out.parent_path());
      std::ofstream(out, std::ios::binary) << bytes;
    }
    zip_close(za);
    l.folder = (dir / "fmu").string();
    std::ifstream in(dir / "fmu/modelDescription.xml");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string xml = ss.str();
    std::smatch m;
    std::regex_search(xml, m, std::regex("guid=\"([^\"]+)\""));
    l.guid = m[1];
    const std::regex var("<ScalarVariable name=\"([^\"]+)\" valueReference=\"([0-9]+)\"");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), var); it != std::sregex_iterator();
         ++it)
      l.vr[(*it)[1]] = unsigned(std::stoul((*it)[2]));
    std::regex_search(
        xml, m,
        std::regex("name=\"wheel_state.pos.z\"[^>]*>\\s*<Real unit=\"m\" start=\"([^\"]+)\""));
    l.R0 = std::stod(m[1]);
    l.handle = dlopen((dir / "fmu/binaries/linux64/ModalTyre.so").c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!l.handle) throw std::runtime_error(dlerror());
    auto sym = [&](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(l.handle, name));
    };
    sym(l.instantiate, "fmi2Instantiate");
    sym(l.free_instance, "fmi2FreeInstance");
    sym(l.setup, "fmi2SetupExperiment");
    sym(l.enter, "fmi2EnterInitializationMode");
    sym(l.exit, "fmi2ExitInitializationMode");
    sym(l.do_step, "fmi2DoStep");
    sym(l.get_real, "fmi2GetReal");
    sym(l.set_real, "fmi2SetReal");
    sym(l.set_string, "fmi2SetString");
    return l;
  }();
  return L;
}

void logger(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String m, ...) {
  std::fprintf(stderr, "fmu: %s\n", m);
}

struct Wheel {
  const Loaded& L;
  fmi2Component c;
  void set(const char* name, double v) {
    const unsigned r = L.vr.at(name);
    L.set_real(c, &r, 1, &v);
  }
  double get(const char* name) {
    const unsigned r = L.vr.at(name);
    double v = 0;
    L.get_real(c, &r, 1, &v);
    return v;
  }
  void state(double x, double z, double vx, double vz, double angle, double spin) {
    set("wheel_state.pos.x", x);
    set("wheel_state.pos.z", z);
    set("wheel_state.lin_vel.x", vx);
    set("wheel_state.lin_vel.z", vz);
    set("wheel_state.rot.e0", std::cos(angle / 2));
    set("wheel_state.rot.e2", std::sin(angle / 2));
    set("wheel_state.ang_vel.y", spin);
  }
};

/// Quarter-car (sprung 300 kg, unsprung 35 kg, 25 kN/m, 2 kN s/m, wheel inertia 0.9 kg m^2) at
/// `speed` for `duration` s, over a raised-cosine cleat (height, length) reached at t_cleat
/// (none when height is 0). The same car as examples/fmu/quarter_car.py.
void quarter_car(benchmark::State& state, double speed, double duration, double height,
                 double length, double t_cleat) {
  const Loaded& L = loaded();
  const double h = step_s(), g = 9.81, ms = 300, mu = 35, ks = 25e3, cs = 2e3, Iw = 0.9;
  double instantiate = 0, simulated = 0, wall = 0, cpu = 0, fz_peak = 0;
  const fmi2CallbackFunctions cb{logger, nullptr, nullptr, nullptr, nullptr};
  std::string profile;
  if (height > 0) {
    profile = L.folder + "/bench_cleat.csv";
    std::ofstream out(profile);
    out << "x_m,height_m\n-1000,0\n";
    const double xc = speed * t_cleat, edge = length / 4;
    for (double x = xc - length / 2; x <= xc + length / 2 + 1e-12; x += 0.5e-3) {
      const double d = std::abs(x - xc);
      double z = d <= length / 2 - edge
                     ? height
                     : 0.5 * height * (1 - std::cos(M_PI * (length / 2 - d) / edge));
      out << x << "," << z << "\n";
    }
    out << "1000,0\n";
  }
  for (auto _ : state) {
    const auto i0 = std::chrono::steady_clock::now();
    Wheel w{
        L, L.instantiate("bench", fmi2CoSimulation, L.guid.c_str(),
                         ("file://" + L.folder + "/resources").c_str(), &cb, fmi2False, fmi2False)};
    if (!w.c) throw std::runtime_error("fmi2Instantiate failed");
    instantiate += std::chrono::duration<double>(std::chrono::steady_clock::now() - i0).count();
    w.set("step_size", h);
    if (!profile.empty()) {
      const unsigned r = L.vr.at("road_profile");
      const fmi2String p = profile.c_str();
      L.set_string(w.c, &r, 1, &p);
    }
    // Start at the static equilibrium's neighbourhood: the tyre pressed by the car's weight
    // at ~250 N/mm, rolling at speed.
    double zu = L.R0 - (ms + mu) * g / 2.5e5, wu = 0, zs = zu + 0.35 - ms * g / ks, ws = 0;
    double x = 0, angle = 0;
    double spin = speed / L.R0;
    w.state(x, zu, speed, wu, angle, spin);
    L.setup(w.c, fmi2False, 0, 0, fmi2False, 0);
    L.enter(w.c);
    if (L.exit(w.c) != fmi2OK) throw std::runtime_error("fmi2ExitInitializationMode failed");
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_s();
    const long n = std::lround(duration / h);
    for (long k = 0; k < n; ++k) {
      w.state(x, zu, speed, wu, angle, spin);
      if (L.do_step(w.c, k * h, h, fmi2True) != fmi2OK)
        throw std::runtime_error("fmi2DoStep failed");
      const double fz = w.get("wheel_load.force.z"), my = w.get("wheel_load.moment.y");
      fz_peak = std::max(fz_peak, fz);
      const double fsusp = ks * (zs - zu - 0.35) + cs * (ws - wu);
      ws += h * (-fsusp / ms - g);
      wu += h * ((fsusp + fz) / mu - g);
      zs += h * ws;
      zu += h * wu;
      spin += h * my / Iw;
      angle += h * spin;
      x += h * speed;
    }
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cpu += thread_cpu_s() - c0;
    simulated += duration;
    L.free_instance(w.c);
  }
  state.SetLabel(modaltyre_bench::instruction_set());
  state.counters["real_time_factor"] = simulated / wall;
  state.counters["cpu_real_time_factor"] = simulated / cpu;
  state.counters["instantiate_s"] = instantiate / state.iterations();
  state.counters["peak_load_N"] = fz_peak;
}

void BM_FmuQuarterCarRolling(benchmark::State& s) { quarter_car(s, 60 / 3.6, 2.0, 0, 0, 0); }
void BM_FmuQuarterCarCleat(benchmark::State& s) { quarter_car(s, 30 / 3.6, 1.5, 0.01, 0.02, 0.6); }
void BM_FmuQuarterCarStanding(benchmark::State& s) { quarter_car(s, 0, 1.0, 0, 0, 0); }

BENCHMARK(BM_FmuQuarterCarRolling)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FmuQuarterCarCleat)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FmuQuarterCarStanding)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
