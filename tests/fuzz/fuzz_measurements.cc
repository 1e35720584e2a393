// Measured footprint data: read_measurements against the SF-350 config's defaults, then
// condition_value() of every condition of every row.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_support.h"
#include "modaltyre/studies/measurements.h"
#include "modaltyre/contact/tyre_config.h"

namespace {

const modaltyre::contact::TyreConfig& defaults() {
  static const modaltyre::contact::TyreConfig config = [] {
    try {
      return modaltyre::contact::load_tyre_config(modaltyre::fuzz::source_dir() +
                                                  "/configs/sf350_2d_table3.yaml");
    } catch (const std::exception& e) {
      std::fprintf(stderr, "fuzz_measurements: cannot read configs/sf350_2d_table3.yaml: %s\n", e.what());
      std::abort();  // a setup problem, not a finding
    }
  }();
  return config;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static modaltyre::fuzz::ScratchFile file("measurements");
  const auto& config = defaults();
  const std::string& path = file.write(data, size);
  modaltyre::fuzz::guarded([&] {
    const auto set = modaltyre::studies::read_measurements(path, config);
    for (const auto& row : set.rows) {
      for (const auto& c : set.conditions) {
        (void)modaltyre::studies::condition_value(row.conditions, c);
      }
    }
  });
  return 0;
}
