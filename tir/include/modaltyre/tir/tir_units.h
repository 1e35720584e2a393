#pragma once
// The [UNITS] section of a .tir file: what one unit of each base quantity is in SI, and the SI
// value of the keys the bridge reads. A file without [UNITS] is in SI (meter, newton, second,
// kg, radian), as MF-Tool writes it. Pressure is the PRESSURE unit when [UNITS] gives one
// (MF 6.x files do), else force / length^2.
#include <string>

#include "modaltyre/tir/tir_file.h"

namespace modaltyre::tir {

/// Physical dimension of a .tir quantity.
enum class Dimension {
  none,
  length,
  force,
  stiffness,
  pressure,
  damping,
  mass,
  time,
  angle,
  speed
};

struct TirUnits {
  double length_m = 1;  ///< one file length unit in metres
  double force_N = 1;
  double time_s = 1;
  double mass_kg = 1;
  double angle_rad = 1;
  double pressure_Pa = 1;  ///< one file pressure unit in pascal
  bool stated = false;     ///< false: no [UNITS] section (SI assumed)

  /// Factor that turns a value of `d` in file units into SI.
  double to_si(Dimension d) const;
};

/// Reads [UNITS]; an unknown unit name is an InputError naming file, line and UNITS.KEY.
TirUnits read_units(const TirFile& file);

}  // namespace modaltyre::tir
