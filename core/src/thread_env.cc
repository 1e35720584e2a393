// OMP_NUM_THREADS bounded like --threads (thread_env.h).
#include "modaltyre/core/thread_env.h"

#include <cstdlib>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre {

void check_omp_num_threads_value(const std::string& value) {
  const std::string range = "[1, " + std::to_string(kMaxThreads) + "]";
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = value.find(',', start);
    const std::string item =
        value.substr(start, comma == std::string::npos ? comma : comma - start);
    const auto v = parse_finite_double(item);
    bool digits = !item.empty();
    for (char c : item) digits = digits && ((c >= '0' && c <= '9') || c == ' ');
    if (!v || !digits) {
      throw InputError({"", 0, "OMP_NUM_THREADS"},
                       "'" + printable(value) + "' is not a thread count (a whole number in " +
                           range + ", or a comma-separated list of them)");
    }
    if (*v < 1 || *v > kMaxThreads) {
      throw InputError({"", 0, "OMP_NUM_THREADS"},
                       printable(item) + " threads is outside " + range +
                           ", the range of --threads (unset it to use every core)");
    }
    if (comma == std::string::npos) return;
    start = comma + 1;
  }
}

void check_omp_num_threads() {
  const char* value = std::getenv("OMP_NUM_THREADS");
  if (value == nullptr || *value == '\0') return;
  check_omp_num_threads_value(value);
}

}  // namespace modaltyre
