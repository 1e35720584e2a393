// The discrepancy workflow on a measured test matrix of N rows (issue 16: a 1000-row matrix
// must cost less than a minute): loads x pressures x hold times, sinking and length with 1.5 %
// noise, generated on the 2 mm mesh with a creeping tread and the pressure effect hidden;
// discover names both. Above 64 rows it uses the approximations of discover/large_fit.h.
// And a 24-row set on the default 3D config with detection limits (issue 23: < 2 min), and
// the default's six Table 3 rows with every candidate (issue 45: < 60 s of CPU time).
//   build/bench/discover_bench --benchmark_repetitions=3
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <string>

#include "instruction_set_context.h"
#include "modaltyre/discover/discover.h"
#include "test_matrix.h"

namespace {

using namespace modaltyre;

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";

void BM_DiscoverTestMatrix(benchmark::State& state) {
  const int rows = static_cast<int>(state.range(0));
  const auto cfg = contact::load_tyre_config(kConfig, {"contact.unit_length_mm=2"});
  const int holds = rows >= 1000 ? 10 : 5;
  const int pressures = rows >= 1000 ? 5 : 2;
  const auto data = bench::test_matrix(cfg, rows / (holds * pressures), pressures, holds);
  discover::DiscoverReport r;
  for (auto _ : state) {
    r = discover::discover(contact::load_tyre_config(kConfig), data);
    benchmark::DoNotOptimize(r);
  }
  state.counters["rows"] = static_cast<double>(data.rows.size());
  state.counters["named"] = static_cast<double>(r.effects.size());
  state.counters["footprints"] = static_cast<double>(r.footprints);
}
BENCHMARK(BM_DiscoverTestMatrix)
    ->Arg(100)
    ->Arg(1000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// Issue 23's budget: a 24-row set on the default config (the 3D patch) with the detection
// limits of every candidate left unnamed, under 2 minutes. 6 loads x 2 pressures x 2 hold
// times, the creeping tread hidden (1.5 % noise).
void BM_Discover24RowsWithLimits(benchmark::State& state) {
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
  const auto cfg = contact::load_tyre_config(config, {"contact.unit_length_mm=2"});
  const auto data = bench::test_matrix(cfg, 6, 2, 2, false);
  discover::DiscoverReport r;
  for (auto _ : state) {
    r = discover::discover(contact::load_tyre_config(config), data);
    benchmark::DoNotOptimize(r);
  }
  int limits = 0;
  for (const auto& c : r.rounds.back()) limits += c.limit.computed() && !c.limit.effect.empty();
  state.counters["rows"] = static_cast<double>(data.rows.size());
  state.counters["named"] = static_cast<double>(r.effects.size());
  state.counters["limits"] = limits;
  state.counters["footprints"] = static_cast<double>(r.footprints);
}
BENCHMARK(BM_Discover24RowsWithLimits)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

// Issue 45's budget: discover on the default tyre (the 3D patch) with six footprint rows and
// every candidate it can test there (the nine road effects but contact_width, tread_coupling's
// coupled cell solve among them, and the four option effects), under 60 s of CPU time: seed
// 001's measured Table 3 (two rounds: belt_flattening is named, then the rest is searched on top
// of it). One thread, so that the CPU time is the wall time of an idle core.
void BM_DiscoverSixRows3dAllCandidates(benchmark::State& state) {
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
  const auto cfg = contact::load_tyre_config(config);
  const auto data = studies::read_measurements(
      std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_footprint_table3.csv", cfg);
  discover::DiscoverOptions opt;
  opt.threads = 1;
  discover::DiscoverReport r;
  for (auto _ : state) {
    r = discover::discover(cfg, data, opt);
    benchmark::DoNotOptimize(r);
  }
  int testable = 0;
  for (const auto& c : r.rounds.front()) testable += c.testable;
  state.counters["rows"] = static_cast<double>(data.rows.size());
  state.counters["candidates"] = testable;
  state.counters["rounds"] = static_cast<double>(r.rounds.size());
  state.counters["footprints"] = static_cast<double>(r.footprints);
}
BENCHMARK(BM_DiscoverSixRows3dAllCandidates)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->MeasureProcessCPUTime();

}  // namespace

int main(int argc, char** argv) {
  // As the CLI does (app/main.cc): keep freed matrices in the heap instead of page-faulting
  // them back on every footprint.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
