#include "cli_support.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "modaltyre/core/errors.h"
#include "modaltyre/report/check_finite.h"

namespace modaltyre::app {

void print_json(const nlohmann::json& j) {
  check_finite(j);
  std::cout << j.dump(2) << std::endl;
}

CLI::Validator physical_range(double lo, double hi, const std::string& unit, const std::string& why,
                              bool lo_inclusive) {
  auto number = [](double v) {  // 1e+07 -> 1e7
    std::ostringstream s;
    s << v;
    std::string t = s.str();
    for (const char* from : {"e+0", "e+", "e-0"}) {
      const auto at = t.find(from);
      if (at != std::string::npos)
        t.replace(at, std::string(from).size(), from[1] == '-' ? "e-" : "e");
    }
    return t;
  };
  const std::string text =
      std::string(lo_inclusive ? "[" : "(") + number(lo) + ", " + number(hi) + "] " + unit;
  return CLI::Validator(
      [=](std::string& input) -> std::string {
        char* end = nullptr;
        const double v = std::strtod(input.c_str(), &end);
        if (end == input.c_str() || *end != '\0' || !std::isfinite(v)) {
          return "'" + input.substr(0, 40) + "' is not a finite number (range " + text + ")";
        }
        if (!(lo_inclusive ? v >= lo : v > lo) || !(v <= hi)) {
          return input.substr(0, 40) + " is outside " + text + ": " + why;
        }
        return "";
      },
      text);
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace modaltyre::app
