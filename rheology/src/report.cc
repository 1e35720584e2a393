#include "modaltyre/rheology/report.h"

#include "modaltyre/core/errors.h"

namespace modaltyre::rheology {

bool FitReport::has(const std::string& name) const {
  for (const auto& p : parameters)
    if (p.name == name) return true;
  return false;
}

const Parameter& FitReport::at(const std::string& name) const {
  for (const auto& p : parameters)
    if (p.name == name) return p;
  MODALTYRE_CHECK(false, "parameter '" + name + "' not in the " + method + " report");
  return parameters.front();  // unreachable
}

}  // namespace modaltyre::rheology
