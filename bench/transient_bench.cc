// Real-time factor (simulated s / wall s) of every transient scenario, reported as a counter.
// Resolution: the config's mesh unless MODALTYRE_BENCH_UNIT_MM is set (e.g. 2 for a quick run).
// Run: build/bench/transient_bench --benchmark_filter=Transient
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>

#include "modaltyre/contact/transient.h"

namespace {

using namespace modaltyre::contact;

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";

std::vector<std::string> overrides() {
  std::vector<std::string> o;
  if (const char* u = std::getenv("MODALTYRE_BENCH_UNIT_MM")) o.push_back(std::string("contact.unit_length_mm=") + u);
  if (const char* h = std::getenv("MODALTYRE_BENCH_HOLD_S")) o.push_back(std::string("transient.load_hold.hold_s=") + h);
  return o;
}

void run(benchmark::State& state, Scenario s) {
  const TransientModel model =
      build_transient_model(build_tyre_model(load_tyre_config(kConfig, overrides())));
  double rtf = 0, simulated = 0, wall = 0;
  long steps = 0;
  for (auto _ : state) {
    const TransientResult r = run_transient(model, s);
    if (!r.ok()) {
      state.SkipWithError(r.message.c_str());
      return;
    }
    simulated += r.simulated_s;
    wall += r.wall_s;
    steps += r.stats.steps;
  }
  rtf = wall > 0 ? simulated / wall : 0;
  state.counters["real_time_factor"] = rtf;
  state.counters["simulated_s"] = simulated / state.iterations();
  state.counters["steps"] = static_cast<double>(steps) / state.iterations();
  state.counters["states"] = model.state_size();
}

void TransientLoadHold(benchmark::State& st) { run(st, Scenario::load_hold); }
void TransientFreeVibration(benchmark::State& st) { run(st, Scenario::free_vibration); }
void TransientRolling60(benchmark::State& st) { run(st, Scenario::rolling); }
void TransientCleat(benchmark::State& st) { run(st, Scenario::cleat); }

}  // namespace

BENCHMARK(TransientLoadHold)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(TransientFreeVibration)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(TransientRolling60)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(TransientCleat)->Unit(benchmark::kSecond)->Iterations(1);
