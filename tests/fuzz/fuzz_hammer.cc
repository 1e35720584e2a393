// Hammer CSV: read_hammer_csv -> identify_modes (harmonic fits, aliasing, dispersion fit).
#include <string>

#include "fuzz_support.h"
#include "modaltyre/modal/hammer_data.h"
#include "modaltyre/modal/mode_identification.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static modaltyre::fuzz::ScratchFile file("hammer");
  const std::string& path = file.write(data, size);
  modaltyre::fuzz::guarded([&] {
    const auto hammer = modaltyre::modal::read_hammer_csv(path);
    const auto ident = modaltyre::modal::identify_modes(hammer);
    for (const auto& m : ident.modes) (void)m.order();
  });
  return 0;
}
