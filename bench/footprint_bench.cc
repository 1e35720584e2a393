// Benchmarks of the static chain: fit-modes, kernel construction, one footprint solve versus the
// number of candidate units m, and the six Table 3 loads as a whole process (2D and 3D patch).
// Results compare only on the same machine: see BENCHMARKS.md.
#include <benchmark/benchmark.h>

#include <string>

#include "instruction_set_context.h"
#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/modal/carcass_kernel.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/mode_identification.h"

namespace {

const std::string kConfig = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350_2d_table3.yaml";
const std::string kHammer =
    std::string(MODALTYRE_SOURCE_DIR) + "/configs/data/sf350_hammer_12pt.csv";

using namespace modaltyre;

void BM_FitModes(benchmark::State& state) {
  for (auto _ : state) {
    auto id = modal::identify_modes(modal::read_hammer_csv(kHammer));
    benchmark::DoNotOptimize(id);
  }
}
BENCHMARK(BM_FitModes)->Unit(benchmark::kMillisecond);

// Kernels over a 360 mm window on the mesh of n units (orders up to n/2): the FFT route the
// model uses, and the direct O(terms * lags) sums for comparison.
void kernel_bench(benchmark::State& state, bool fft) {
  const double unit_mm = 1.0 / static_cast<double>(state.range(0));
  const auto cfg =
      contact::load_tyre_config(kConfig, {"contact.unit_length_mm=" + std::to_string(unit_mm)});
  const auto ident = modal::identify_modes(modal::read_hammer_csv(cfg.hammer_csv));
  const int n = modal::fft_friendly_size(
      static_cast<int>(2 * M_PI * cfg.outer_radius_m / cfg.mesh.unit_length_m));
  modal::ModalBasisOptions bo;
  bo.max_order = n / 2;
  const auto basis = modal::build_modal_basis(ident, bo);
  const int lags = static_cast<int>(cfg.mesh.window_m / cfg.mesh.unit_length_m) + 1;
  for (auto _ : state) {
    auto K = fft ? modal::build_periodic_kernels(basis, n, lags)
                 : modal::build_lag_kernels(basis, 2 * M_PI / n, lags);
    benchmark::DoNotOptimize(K);
  }
  state.counters["n"] = n;
  state.counters["lags"] = lags;
}
void BM_KernelBuildFft(benchmark::State& state) { kernel_bench(state, true); }
void BM_KernelBuildDirect(benchmark::State& state) { kernel_bench(state, false); }
BENCHMARK(BM_KernelBuildFft)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KernelBuildDirect)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

// One solve (cold start) at 5478 N with m candidate units over a 180 mm window.
void BM_FootprintSolve(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  const double unit_mm = 180.0 / m;
  const auto model = contact::build_tyre_model(contact::load_tyre_config(
      kConfig, {"contact.window_mm=180", "contact.unit_length_mm=" + std::to_string(unit_mm)}));
  int iterations = 0;
  for (auto _ : state) {
    auto r = contact::solve_footprint(model, {5478, 0});
    iterations = r.iterations;
    benchmark::DoNotOptimize(r);
  }
  state.SetLabel(modaltyre_bench::instruction_set());
  state.counters["m"] = model.candidates();
  state.counters["active_set_iterations"] = iterations;
  state.SetComplexityN(model.candidates());
}
BENCHMARK(BM_FootprintSolve)
    ->RangeMultiplier(2)
    ->Range(100, 3200)
    ->Unit(benchmark::kMillisecond)
    ->Complexity();

// The whole job of the seed's Table 3 on the 2D patch (configs/sf350_2d_table3.yaml): read
// config and hammer data, build the model at `unit` mm, solve the six loads with warm starts.
void BM_Table3Process(benchmark::State& state) {
  const double unit_mm = state.range(0) / 100.0;
  for (auto _ : state) {
    const auto model = contact::build_tyre_model(
        contact::load_tyre_config(kConfig, {"contact.unit_length_mm=" + std::to_string(unit_mm)}));
    std::vector<contact::LoadCase> loads;
    for (double F : model.config.loads_N) loads.push_back({F, 0});
    auto res = contact::solve_footprints(model, loads);
    benchmark::DoNotOptimize(res);
  }
}
BENCHMARK(BM_Table3Process)->Arg(50)->Arg(25)->Unit(benchmark::kMillisecond);

// The same job on the default tyre (configs/sf350.yaml, the 3D patch: `unit` mm x 2.5 mm cells)
// through the product's prediction path (contact::predict_all: the laterally rigid reduction,
// warm starts); the target is < 0.5 s per process at the default 0.5 mm.
void BM_Table3Process3d(benchmark::State& state) {
  const std::string config = std::string(MODALTYRE_SOURCE_DIR) + "/configs/sf350.yaml";
  const double unit_mm = state.range(0) / 100.0;
  for (auto _ : state) {
    const auto model = contact::build_tyre_model(
        contact::load_tyre_config(config, {"contact.unit_length_mm=" + std::to_string(unit_mm)}));
    std::vector<contact::OperatingConditions> cases;
    for (double F : model.config.loads_N) cases.push_back(model.config.default_conditions(F));
    auto res = contact::predict_all(model, cases);
    benchmark::DoNotOptimize(res);
  }
}
BENCHMARK(BM_Table3Process3d)->Arg(50)->Arg(25)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
