#pragma once
// The 2D SF-350 of Table 3 as configured, read once per test process.
#include "data_paths.h"
#include "modaltyre/contact/tyre_config.h"

namespace modaltyre_test {

inline const modaltyre::contact::TyreConfig& table3_tyre() {
  static const modaltyre::contact::TyreConfig c = modaltyre::contact::load_tyre_config(kConfig2d);
  return c;
}

}  // namespace modaltyre_test
