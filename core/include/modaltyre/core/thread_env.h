#pragma once
// The OpenMP thread count a user sets in the environment, bounded like --threads (issue 38:
// OMP_NUM_THREADS=100000 crashed sweep and discover while starting its threads).
#include <string>

namespace modaltyre {

/// The most threads a command takes from --threads or OMP_NUM_THREADS: far above any node's
/// cores, far below what the OpenMP runtime can start.
inline constexpr int kMaxThreads = 4096;

/// Refuses an OMP_NUM_THREADS that is set but is not a decimal list of thread counts (OpenMP's
/// "4" or "4,2" for nested levels) each in [1, kMaxThreads]: InputError naming OMP_NUM_THREADS,
/// exit 2. Unset or empty: nothing to check.
void check_omp_num_threads();

/// The same check on a given value (for tests).
void check_omp_num_threads_value(const std::string& value);

}  // namespace modaltyre
