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

void SlipSinkage::validate() const {
  auto bad = [](const std::string& what) { throw std::invalid_argument(what); };
  if (!(k1 >= 0 && k1 <= 10)) bad("bekker.slip_sinkage.k1 must be in [0, 10]");
  if (!(k2 >= 0 && k2 <= 0.99)) bad("bekker.slip_sinkage.k2 must be in [0, 0.99]");
}

double SlipSinkage::factor(double slip) const {
  if (!enabled) return 1.0;
  const double s = std::min(std::abs(slip), 1.0);
  return (1 + k1 * s) / (1 - k2 * s);
}

}  // namespace modaltyre::ground
