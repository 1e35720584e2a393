#pragma once
// Every benchmark program states the instruction set it ran (issue 47 item 3): a line of the
// context Google Benchmark prints before its table (and writes into the "context" of
// --benchmark_format=json), e.g. "instruction_set: kernels avx2+fma, Eigen SSE, SSE2": the run-time
// kernels' path (solvers/instruction_set.h; MODALTYRE_ISA=portable times the portable loops) and
// the instruction sets Eigen was compiled for. The kernel benchmarks also label every row with it.
#include <benchmark/benchmark.h>

#include <string>

#include "modaltyre/solvers/instruction_set.h"

namespace modaltyre_bench {

inline const std::string& instruction_set() {
  static const std::string label = modaltyre::solvers::instruction_set_label();
  return label;
}

inline const bool kInstructionSetContext =
    (benchmark::AddCustomContext("instruction_set", instruction_set()), true);

}  // namespace modaltyre_bench
