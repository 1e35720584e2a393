#include "modaltyre/contact/validity.h"

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

}  // namespace modaltyre::contact
