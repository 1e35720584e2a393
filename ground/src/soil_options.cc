#include "modaltyre/ground/soil_options.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace modaltyre::ground {

void WongReeceStress::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(c1 >= 0 && c1 <= 1)) bad("bekker.wong_reece.c1 must be in [0, 1]");
  if (!(c2 >= 0 && c2 <= 1)) bad("bekker.wong_reece.c2 must be in [0, 1]");
  if (!(c3 >= 0 && c3 <= 0.99)) bad("bekker.wong_reece.c3 must be in [0, 0.99]");
}

double WongReeceStress::peak_ratio(double slip) const {
  return std::clamp(c1 + c2 * slip, 0.0, 1.0);
}

}  // namespace modaltyre::ground
