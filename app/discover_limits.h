#pragma once
// Detection limits of discover's report (issue 23): the text lines (the JSON members are in
// report/discover_json.cc).

#include "modaltyre/discover/discover.h"

namespace modaltyre::app {

/// "tread_relaxation: not named; these data would reveal creep_ratio >= 0.21 (sinking_mm RMS
/// >= 2.1 %) with 80 % probability" for the last round's candidates left unnamed, and the rows
/// to add.
void print_limits(const discover::DiscoverReport& r);

}  // namespace modaltyre::app
