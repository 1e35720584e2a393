// The kernels' instruction set (instruction_set.h).
#include "modaltyre/solvers/instruction_set.h"

#include <Eigen/Core>
#include <cstdlib>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::solvers {
namespace {

bool cpu_has_avx2_fma() {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

struct Choice {
  InstructionSet set = InstructionSet::portable;
  bool valid = true;
  std::string value;
};

const Choice& choice() {
  static const Choice c = [] {
    Choice r;
    const char* value = std::getenv(kInstructionSetVariable);
    const bool avx2 = cpu_has_avx2_fma();
    const std::optional<InstructionSet> set = parse_instruction_set(value, avx2);
    r.valid = set.has_value();
    r.set = set ? *set : *parse_instruction_set(nullptr, avx2);
    r.value = value ? value : "";
    return r;
  }();
  return c;
}

}  // namespace

std::optional<InstructionSet> parse_instruction_set(const char* value, bool cpu_has_avx2_fma) {
  const InstructionSet best =
      cpu_has_avx2_fma ? InstructionSet::avx2_fma : InstructionSet::portable;
  if (value == nullptr || *value == '\0') return best;
  const std::string v = value;
  if (v == "portable") return InstructionSet::portable;
  if (v == "avx2") return best;  // a cap: the portable loops on a CPU without AVX2 + FMA
  return std::nullopt;
}

InstructionSet instruction_set() { return choice().set; }

const char* instruction_set_name(InstructionSet set) {
  return set == InstructionSet::avx2_fma ? "avx2+fma" : "portable";
}

std::string instruction_set_label() {
  return std::string("kernels ") + instruction_set_name(instruction_set()) + ", Eigen " +
         Eigen::SimdInstructionSetsInUse();
}

void check_instruction_set_variable() {
  const Choice& c = choice();
  if (c.valid) return;
  throw InputError({"", 0, kInstructionSetVariable},
                   "'" + printable(c.value) +
                       "' is not an instruction set of the kernels (portable or avx2; unset: the "
                       "best this CPU runs)");
}

}  // namespace modaltyre::solvers
