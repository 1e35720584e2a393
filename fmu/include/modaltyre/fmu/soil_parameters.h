#pragma once
// The soil keys of a soil FMU as its parameters (issue 46 item 3): a packed Bekker-Wong or
// Kelvin-Voigt ground (docs/soil.md section 1) exposes the keys of its `ground:` section as
// fixed Real parameters named as the keys, started at the packed values, with the ranges the
// ground reader accepts (ground/src/ground_settings.cc) as min/max. An open bound (a key that
// must be positive) is declared as min 0 and refused at 0 when set.
#include <string>
#include <vector>

#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::fmu {

struct SoilParameter {
  std::string name;         ///< the key, e.g. "ground.bekker.n"
  std::string unit;         ///< a unit model_description.h knows
  double min = 0, max = 0;  ///< the reader's range
  bool positive = false;    ///< min excluded (> 0)
  std::string description;
  double (*get)(const ground::GroundSettings&) = nullptr;
  void (*set)(ground::GroundSettings&, double) = nullptr;
};

/// The parameters of `ground` (a soil): its model's keys, Wong's unloading pair only when the
/// soil has one, and the Kelvin-Voigt rate term only where the tyre models it (not on the 3D
/// patch: `patch_3d`).
std::vector<SoilParameter> soil_parameters(const ground::GroundSettings& ground, bool patch_3d);

/// Why the settings cannot be run although every key lies in its range (k_c and k_phi both 0,
/// k0 and Au both 0), naming the keys; empty when they can.
std::string soil_combination_problem(const ground::GroundSettings& ground);

}  // namespace modaltyre::fmu
