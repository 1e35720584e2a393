#pragma once
// Readable test parameters for the scenario suites (tests/readable_names_test.cmake): gtest
// finds PrintTo by argument-dependent lookup in the Scenario's namespace.
#include <ostream>

#include "modaltyre/transient/scenario.h"

namespace modaltyre::transient {

inline void PrintTo(Scenario s, std::ostream* os) { *os << to_string(s); }

}  // namespace modaltyre::transient
