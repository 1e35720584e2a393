#include "modaltyre/contact/validity.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace modaltyre::contact {

Validity validity(const TyreConfig& config, double sinking_m, double contact_length_m) {
  const double R0 = config.outer_radius_m;
  std::ostringstream why;
  why.precision(3);
  if (sinking_m > kMaxSinkingOverRadius * R0) {
    why << "sinking " << sinking_m * 1e3 << " mm is " << 100 * sinking_m / R0
        << " % of the free radius R0 = " << R0 * 1e3 << " mm; the linearised model holds up to "
        << 100 * kMaxSinkingOverRadius << " % (" << kMaxSinkingOverRadius * R0 * 1e3 << " mm)";
  }
  if (0.5 * contact_length_m > kMaxHalfLengthOverRadius * R0) {
    if (why.tellp() > 0) why << "; ";
    why << "contact length " << contact_length_m * 1e3 << " mm exceeds "
        << 2 * kMaxHalfLengthOverRadius << " R0 = " << 2 * kMaxHalfLengthOverRadius * R0 * 1e3
        << " mm (a contact beyond +-30 deg of the bottom)";
  }
  return {why.tellp() == 0, why.str()};
}

Validity validity_on_soil(const TyreConfig& config, double tyre_deflection_m, double soil_sinkage_m,
                          double entry_angle_rad, double exit_angle_rad, bool rigid) {
  const double R0 = config.outer_radius_m, deg = 180 / M_PI;
  std::ostringstream why;
  why.precision(3);
  auto next = [&] {
    if (why.tellp() > 0) why << "; ";
  };
  if (!rigid && tyre_deflection_m > kMaxSinkingOverRadius * R0) {
    why << "tyre deflection " << tyre_deflection_m * 1e3 << " mm is "
        << 100 * tyre_deflection_m / R0 << " % of the free radius R0 = " << R0 * 1e3
        << " mm; the linearised model holds up to " << 100 * kMaxSinkingOverRadius << " % ("
        << kMaxSinkingOverRadius * R0 * 1e3 << " mm)";
  }
  const double widest = std::max(std::abs(entry_angle_rad), std::abs(exit_angle_rad));
  if (!rigid && widest * deg > kMaxContactAngle_deg) {
    next();
    why << "the contact reaches " << widest * deg << " deg from the bottom (entry "
        << entry_angle_rad * deg << " deg, exit " << exit_angle_rad * deg
        << " deg); the linearised model holds within +-" << kMaxContactAngle_deg << " deg";
  }
  const double soil_limit = kMaxSoilSinkageOverDiameter * 2 * R0;
  if (soil_sinkage_m > soil_limit) {
    next();
    why << "soil sinkage " << soil_sinkage_m * 1e3 << " mm exceeds D/6 = " << soil_limit * 1e3
        << " mm, the moderate sinkage of Bekker's wheel relations (Wong, Theory of Ground "
           "Vehicles, section 2.7)";
  }
  return {why.tellp() == 0, why.str()};
}

Validity validity(const TyreConfig& config, const FootprintResult& f) {
  if (!f.on_soil) return validity(config, f.sinking_m, f.contact_length_m);
  const double axle_height = config.outer_radius_m - f.sinking_m;
  return validity_on_soil(config, f.tyre_deflection_m, f.soil_sinkage_m,
                          std::atan2(f.front_edge_x_m, axle_height),
                          std::atan2(f.rear_edge_x_m, axle_height), config.rigid);
}

}  // namespace modaltyre::contact
