// Identification time of `modaltyre ema` (issue 19: a 12-point, 24-FRF, 1600-line data set in
// < 2 s): FRFs synthesised from planted modes with 1 % noise (tests/ema/), LSCF diagram to order
// 64, refinement, LSFD and mass normalisation.
#include <benchmark/benchmark.h>

#include "../tests/ema/planted_models.h"
#include "instruction_set_context.h"
#include "modaltyre/ema/ema.h"

namespace {

using namespace modaltyre;

ema::FrfSet frfs(const modaltyre_test::PlantedModel& model) {
  modaltyre_test::SynthOptions so;
  so.f_lo_hz = 0.25;  // 1600 lines of 0.25 Hz up to 400 Hz
  so.noise = 0.01;
  return modaltyre_test::synthesise(model, so);
}

// Ring model (6 modes in band, one below, one above), every line of the set.
void BM_EmaRing1600Lines(benchmark::State& state) {
  const auto set = frfs(modaltyre_test::ring_model());
  ema::EmaOptions o;
  for (auto _ : state) benchmark::DoNotOptimize(ema::run_ema(set, o));
  state.counters["modes"] = static_cast<double>(ema::run_ema(set, o).modes.size());
}
BENCHMARK(BM_EmaRing1600Lines)->Unit(benchmark::kMillisecond)->Iterations(5);

// The bundled SF-350 modes (16, close pairs), band 80-350 Hz (1081 of the 1600 lines).
void BM_EmaSf350Band(benchmark::State& state) {
  const auto set = frfs(modaltyre_test::bundled_model());
  ema::EmaOptions o;
  o.band_lo_hz = 80;
  o.band_hi_hz = 350;
  for (auto _ : state) benchmark::DoNotOptimize(ema::run_ema(set, o));
  state.counters["modes"] = static_cast<double>(ema::run_ema(set, o).modes.size());
}
BENCHMARK(BM_EmaSf350Band)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
