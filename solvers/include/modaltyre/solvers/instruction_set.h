#pragma once
// The instruction set of the vector kernels chosen at run time: CVODE's vector operations
// (serial_vector_ops.cc), the dense contact solve's products (dense_product.cc) and the
// transient's cell and column kernels (transient/src/cell_kernels.cc, column_product.cc). Each
// kernel has an AVX2 path (with FMA where it fuses) and a portable one in the same order of
// operations: both give the same bits, so a run's answers do not depend on the CPU. Everything else
// (Eigen included) is compiled for the compiler's baseline, x86-64's SSE2.
//
// The environment variable MODALTYRE_ISA, read once per process, caps the choice: `portable`
// forces the portable loops, `avx2` allows AVX2 + FMA where the CPU runs them (the default: no
// kernel has an AVX-512 path). It lets one machine run every path through the same tests and a
// benchmark time either (docs/transient.md section 7, issue 47).
#include <optional>
#include <string>

namespace modaltyre::solvers {

enum class InstructionSet { portable, avx2_fma };

/// The name of the environment variable.
inline constexpr const char* kInstructionSetVariable = "MODALTYRE_ISA";

/// The path the kernels take in this process (MODALTYRE_ISA and the CPU, decided at the first
/// call). An invalid value leaves the default and is reported by check_instruction_set_variable().
InstructionSet instruction_set();

/// "portable" or "avx2+fma".
const char* instruction_set_name(InstructionSet set);

/// The kernels' path and the compiled baseline in one label for benchmarks, e.g.
/// "kernels avx2+fma, Eigen SSE, SSE2".
std::string instruction_set_label();

/// The choice for a value of MODALTYRE_ISA (null or empty: unset) on a CPU that does or does not
/// run AVX2 + FMA; nullopt for a value that is not an instruction set.
std::optional<InstructionSet> parse_instruction_set(const char* value, bool cpu_has_avx2_fma);

/// InputError naming MODALTYRE_ISA when its value is not `portable` or `avx2` (called before an
/// integration starts: the kernels themselves never throw).
void check_instruction_set_variable();

}  // namespace modaltyre::solvers
