// Long-CSV FRFs: read_frf_csv with tight limits, then a conversion to receptance.
#include <string>

#include "fuzz_support.h"
#include "modaltyre/ema/frf_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static modaltyre::fuzz::ScratchFile file("frf_csv");
  const std::string& path = file.write(data, size);
  modaltyre::fuzz::guarded([&] {
    modaltyre::ema::FrfLimits limits;
    limits.max_values = 1 << 16;
    const auto set =
        modaltyre::ema::read_frf_csv(path, modaltyre::ema::FrfType::accelerance, limits);
    (void)modaltyre::ema::convert_frf_type(set, modaltyre::ema::FrfType::receptance);
  });
  return 0;
}
