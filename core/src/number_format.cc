#include "modaltyre/core/number_format.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace modaltyre {

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

double round_sig(double v, int digits) {
  if (v == 0) return 0.0;  // -0 would print as "-0" (issue 38)
  if (!std::isfinite(v)) return v;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return std::strtod(buf, nullptr);
}

}  // namespace modaltyre
