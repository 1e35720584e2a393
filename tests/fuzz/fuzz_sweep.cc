// Sweep file YAML: parse_sweep_spec (with "#set key=value" lines as --set overrides), then,
// for small grids, plan_sweep (loads the base config with every case's overrides, checks
// every condition) and the CSV cells of each case. No footprint is solved.
//
// The sweep is named configs/sweeps/fuzz.yaml inside the source tree so that
// `base: ../sf350_2d_table3.yaml` resolves like the bundled sweeps'.
#include <string>

#include "fuzz_support.h"
#include "modaltyre/studies/sweep.h"

namespace {

// plan_sweep is allowed up to 10 million cases by design; the fuzzer plans only small grids so
// that one input stays well under the per-input timeout.
constexpr std::size_t kMaxPlannedCases = 64;
constexpr std::size_t kMaxPlannedModels = 8;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static const std::string name = modaltyre::fuzz::source_dir() + "/configs/sweeps/fuzz.yaml";
  const std::string text = modaltyre::fuzz::as_text(data, size);
  const auto overrides = modaltyre::fuzz::overrides_in(text);
  modaltyre::fuzz::guarded([&] {
    const auto spec = modaltyre::studies::parse_sweep_spec(text, name, overrides);
    std::size_t cases = 1, models = 1;
    for (const auto& axis : spec.grid) {
      cases *= axis.values.size();
      if (!axis.condition) models *= axis.values.size();
      if (cases > kMaxPlannedCases) return;
    }
    if (models > kMaxPlannedModels) return;
    const auto plan = modaltyre::studies::plan_sweep(spec);
    for (std::size_t i = 0; i < plan.cases.size(); ++i) (void)plan.cells(i);
  });
  return 0;
}
