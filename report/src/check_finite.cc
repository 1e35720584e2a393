#include "modaltyre/report/check_finite.h"

#include <cmath>

#include "modaltyre/core/errors.h"

namespace modaltyre::report {

void check_finite(const nlohmann::json& j, const std::string& where) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) {
    throw ComputationError("non-finite number in " + where + "; refusing to print it");
  }
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) check_finite(it.value(), where + "." + it.key());
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) check_finite(j[i], where);
  }
}

}  // namespace modaltyre::report
