#pragma once
// Detection limits of discover's report (issue 23): the text lines and the JSON members.
#include <nlohmann/json.hpp>

#include "modaltyre/discover/discover.h"

namespace modaltyre::app {

/// A map of relative gaps (per observable) as JSON, 6 significant digits.
nlohmann::json gaps(const std::map<std::string, double>& m);

/// "detection_limit" (null with "detection_limit_reason" where there is none) and
/// "power_at_default" of a candidate of the last round.
void put_limit(const discover::CandidateScore& c, nlohmann::json& j);

/// "tread_relaxation: not named; these data would reveal creep_ratio >= 0.21 (sinking_mm RMS
/// >= 2.1 %) with 80 % probability" for the last round's candidates left unnamed, and the rows
/// to add.
void print_limits(const discover::DiscoverReport& r);

nlohmann::json more_rows_json(const discover::MoreRows& m);

}  // namespace modaltyre::app
