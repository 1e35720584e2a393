// .tir property files: parse_tir -> interpret_tir (units, model identification, vertical and
// contact-patch laws), then every law at a few deflections and loads.
#include <cmath>
#include <string>

#include "fuzz_support.h"
#include "modaltyre/tir/mf_tyre.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  modaltyre::fuzz::guarded([&] {
    modaltyre::tir::TirLimits limits;
    limits.max_entries = 4096;  // a fuzz input is small; keep one run fast
    limits.max_table_rows = 4096;
    const auto file =
        modaltyre::tir::parse_tir(modaltyre::fuzz::as_text(data, size), "fuzz.tir", limits);
    const auto tyre = modaltyre::tir::interpret_tir(file);
    double sum = tyre.vertical_stiffness_N_m();
    for (double rho : {0.0, 1e-3, 0.01, 0.05}) {
      if (const auto f = tyre.load_N(rho * tyre.unloaded_radius_m)) {
        sum += *f;
        sum += tyre.length_m(*f).value_or(0) + tyre.width_at_m(*f).value_or(0);
      }
    }
    (void)sum;
  });
  return 0;
}
