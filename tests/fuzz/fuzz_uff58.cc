// UFF dataset 58 (ASCII and binary 58b): read_uff58 with tight limits, then every channel.
#include <string>

#include "fuzz_support.h"
#include "modaltyre/ema/uff58.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static modaltyre::fuzz::ScratchFile file("uff58");
  const std::string& path = file.write(data, size);
  modaltyre::fuzz::guarded([&] {
    modaltyre::ema::FrfLimits limits;
    limits.max_values = 1 << 16;  // a fuzz input is small; keep one run fast
    const auto set = modaltyre::ema::read_uff58(path, limits);
    double sum = 0;
    for (const auto& c : set.channels) sum += std::abs(c.values.front());
    (void)sum;
  });
  return 0;
}
