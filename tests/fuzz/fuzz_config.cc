// Tyre config YAML: ConfigTree::from_string (with "#set key=value" lines as --set overrides)
// -> read_tyre_config (every section, unknown-key rejection) -> dump().
//
// The tree is named configs/fuzz.yaml inside the source tree so that a relative hammer_csv
// (data/sf350_hammer_12pt.csv) resolves like the bundled configs'; read_tyre_config only
// resolves that path, the hammer reader has its own target.
#include <string>

#include "fuzz_support.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/core/config_tree.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  static const std::string name = modaltyre::fuzz::source_dir() + "/configs/fuzz.yaml";
  const std::string text = modaltyre::fuzz::as_text(data, size);
  const auto overrides = modaltyre::fuzz::overrides_in(text);
  modaltyre::fuzz::guarded([&] {
    const auto tree = modaltyre::ConfigTree::from_string(text, name, overrides);
    (void)tree.dump();
    const auto config = modaltyre::contact::read_tyre_config(tree);
    (void)config.default_conditions(1000.0);
  });
  return 0;
}
