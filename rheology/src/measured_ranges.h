#pragma once
// The plausible range of a measured load (and a measured horizontal force) in rheology's test
// files, as the tyre config has it (loads_N): beyond it a typo or a wrong unit, and the fits
// would overflow instead of saying so. One check for every reader (load-deflection, soil).
#include <string>

#include "modaltyre/core/errors.h"

namespace modaltyre::rheology {

inline constexpr double kMaxMeasuredForce_N = 1e7;

/// InputError naming the file, the line and the column load_N unless 0 < load_N <= 1e7.
inline void require_measured_load(const std::string& path, int line, double load_N) {
  if (!(load_N > 0 && load_N <= kMaxMeasuredForce_N))
    throw InputError({path, line, "load_N"}, "load must be in (0, 1e7] N");
}

}  // namespace modaltyre::rheology
