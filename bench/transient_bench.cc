// Real-time factor (simulated s / wall s) of every transient scenario, reported as a counter,
// and the same from the thread's CPU time (cpu_real_time_factor: steadier on a shared machine).
// Resolution: the config's mesh unless MODALTYRE_BENCH_UNIT_MM is set (e.g. 2 for a quick run).
// MODALTYRE_BENCH_HOLD_S shortens the 120 s load hold; MODALTYRE_BENCH_SET adds further
// `key=value` overrides separated by ';' (e.g. "transient.rolling.duration_s=1.5").
// MODALTYRE_BENCH_3D=1 runs the same benchmarks on the 3D patch of the default config
// (configs/sf350.yaml, run_transient_3d; docs/transient.md section 7) instead of the 2D variant.
// Run: build/bench/transient_bench --benchmark_filter=Transient
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <string>

#include "instruction_set_context.h"
#include "modaltyre/transient/transient.h"

namespace {

using namespace modaltyre::contact;
using namespace modaltyre::transient;

bool patch_3d() {
  const char* v = std::getenv("MODALTYRE_BENCH_3D");
  return v && std::string(v) == "1";
}
const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) +
                            (patch_3d() ? "/configs/sf350.yaml" : "/configs/sf350_2d_table3.yaml");

std::vector<std::string> overrides() {
  std::vector<std::string> o;
  if (const char* u = std::getenv("MODALTYRE_BENCH_UNIT_MM"))
    o.push_back(std::string("contact.unit_length_mm=") + u);
  if (const char* h = std::getenv("MODALTYRE_BENCH_HOLD_S"))
    o.push_back(std::string("transient.load_hold.hold_s=") + h);
  if (const char* extra = std::getenv("MODALTYRE_BENCH_SET")) {
    std::string all = extra;
    for (std::size_t from = 0; from < all.size();) {
      const std::size_t to = std::min(all.find(';', from), all.size());
      if (to > from) o.push_back(all.substr(from, to - from));
      from = to + 1;
    }
  }
  return o;
}

double thread_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

void run(benchmark::State& state, Scenario s) {
  const TransientModel model =
      build_transient_model(build_tyre_model(load_tyre_config(kConfig, overrides())));
  double rtf = 0, simulated = 0, wall = 0, cpu = 0;
  long steps = 0;
  TransientResult last;
  for (auto _ : state) {
    const double cpu0 = thread_cpu_s();
    const TransientResult r = patch_3d() ? run_transient_3d(model, s) : run_transient(model, s);
    cpu += thread_cpu_s() - cpu0;
    if (!r.ok()) {
      state.SkipWithError(r.message.c_str());
      return;
    }
    simulated += r.simulated_s;
    wall += r.wall_s;
    steps += r.stats.steps;
    last = r;
  }
  rtf = wall > 0 ? simulated / wall : 0;
  state.SetLabel(modaltyre_bench::instruction_set());
  state.counters["real_time_factor"] = rtf;
  state.counters["cpu_real_time_factor"] = cpu > 0 ? simulated / cpu : 0;
  state.counters["simulated_s"] = simulated / state.iterations();
  state.counters["steps"] = static_cast<double>(steps) / state.iterations();
  state.counters["states"] = last.states;  // the ODE of the last run (tread_window.h)
  state.counters["nq"] = model.nq;
  state.counters["nr"] = model.nr;
  state.counters["setups"] = static_cast<double>(last.stats.lin_setups);
  state.counters["newton"] = static_cast<double>(last.stats.nonlin_iters);
  state.counters["rhs"] = static_cast<double>(last.stats.rhs_evals);
  state.counters["switches"] = last.contact_events;
  state.counters["contact_units"] = last.samples.empty() ? 0 : last.samples.back().contact_units;
}

/// Accuracy of the truncated residual (not a timing): the static footprint at 4000 N with the
/// transient model's at-rest compliance against the static kernel's, relative differences.
void TransientTruncation(benchmark::State& state) {
  const TransientModel model =
      build_transient_model(build_tyre_model(load_tyre_config(kConfig, overrides())));
  TruncationError e;
  for (auto _ : state) e = truncation_error(model, 4000);
  state.counters["sinking_rel"] = e.sinking_rel;
  state.counters["length_rel"] = e.length_rel;
  state.counters["compliance_rel"] = e.compliance_rel;
  state.counters["nr"] = model.nr;
  state.counters["candidates"] = model.m;
}

void TransientLoadHold(benchmark::State& st) { run(st, Scenario::load_hold); }
void TransientFreeVibration(benchmark::State& st) { run(st, Scenario::free_vibration); }
void TransientRolling60(benchmark::State& st) { run(st, Scenario::rolling); }
void TransientCleat(benchmark::State& st) { run(st, Scenario::cleat); }

}  // namespace

BENCHMARK(TransientTruncation)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(TransientLoadHold)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(TransientFreeVibration)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(TransientRolling60)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(TransientCleat)->Unit(benchmark::kSecond)->Iterations(1);
