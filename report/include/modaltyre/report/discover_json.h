#pragma once
// The JSON document of `modaltyre discover --json` (and the Python module's discover).
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>

#include "modaltyre/discover/discover.h"

namespace modaltyre::report {

/// The gaps (config, baseline, augmented; in-sample and cross-validated), the regimes, the
/// named effects and every round's candidates, the parameters, per-row residuals, the cost and
/// the conclusion. `measured_path` and `rows` describe the measurement file.
nlohmann::json discover_json(const discover::DiscoverReport& r, const std::string& measured_path,
                             std::size_t rows);

}  // namespace modaltyre::report
