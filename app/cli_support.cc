#include "cli_support.h"

#include <cmath>
#include <cstdio>
#include <iostream>

#include "modaltyre/core/errors.h"

namespace modaltyre::app {

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

void print_json(const nlohmann::json& j) {
  check_finite(j);
  std::cout << j.dump(2) << std::endl;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace modaltyre::app
