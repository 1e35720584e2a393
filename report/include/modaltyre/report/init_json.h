#pragma once
// The JSON document of `modaltyre init --json` and of the Python module's init(): the orders
// used and their alternatives, the modal mass and hoop tension the ring gives, the ring fit,
// every decision with its source, the warnings, and the config text when it is not written.
#include <nlohmann/json.hpp>
#include <string>

#include "modaltyre/init/init_tyre.h"

namespace modaltyre::report {

/// `output`: the path the config is written to ("" = not written: the text goes in "config").
nlohmann::json init_json(const init::InitResult& result, const std::string& output);

}  // namespace modaltyre::report
