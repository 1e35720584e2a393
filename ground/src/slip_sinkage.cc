#include "modaltyre/ground/slip_sinkage.h"

#include <cmath>
#include <stdexcept>

namespace modaltyre::ground {

SlipSinkageLaw::SlipSinkageLaw(std::unique_ptr<PressureSinkage> law, double factor)
    : law_(std::move(law)), f_(factor) {
  if (!law_) throw std::invalid_argument("slip sinkage: no law to stretch");
  if (!(f_ >= 1 && std::isfinite(f_)))
    throw std::invalid_argument("slip sinkage: the factor must be finite and >= 1");
}

}  // namespace modaltyre::ground
