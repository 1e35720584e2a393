#pragma once
// The validity range of the contact model. The model is linearised for displacements small
// against the free radius R0 (seed 001 eq. 11-19): the carcass deforms as the undeformed ring's
// modes, unit forces act along the undeformed normals and the sag is R0 (1 - cos theta). Its
// error grows with sinking / R0 and with the contact's half angle. A footprint outside the range
// is still computed (the solver converges), but it is not a prediction: commands flag it
// ("valid": false with the reason in JSON, a warning on stderr), never as an ordinary result.
//
// Limits (README, "Validity range"):
//  - sinking <= 0.12 R0: seed 000's tyre relations (load-deflection, slope factors eq. 6 and
//    10) are stated up to h/r0 = 0.117; at 0.12 R0 a rigid ring's contact half angle is
//    acos(0.88) = 28 deg, where sin(theta) and theta differ by 4 %. On the SF-350 (R0 = 294.8 mm)
//    it is 35.4 mm, 1.2 times the largest sinking of seed 001 Table 3 (29 mm at 8321 N).
//  - half contact length <= 0.5 R0: a contact up to +-30 deg around the bottom, where the normals
//    turn by less than cos(30 deg) = 0.87; beyond, the vertical projection of the unit forces
//    and the flat-road gap are no longer small corrections.
//
// On a soil (docs/soil.md section 5.2) the axle's approach is the tyre's deflection plus the
// soil's sinkage; each is judged against its own range:
//  - the tyre's own deflection <= 0.12 R0 (the limit above);
//  - the contact's extent: its edges, seen from the axle, within +-30 deg of the bottom (on the
//    road the same as half the contact length <= 0.5 R0), where the units' forces along their
//    undeformed normals hold;
//  - the soil's sinkage <= D/6 = R0/3: the moderate sinkage for which the rigid-wheel relations of
//    Bekker's pressure-sinkage law are stated (Wong, Theory of Ground Vehicles, 4th ed., 2008,
//    section 2.7); deeper, the soil ahead is pushed aside (bulldozing) rather than compacted.
// The rigid cylinder (tyre.rigid) does not deflect: only the soil's range applies to it.
#include <string>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::contact {

inline constexpr double kMaxSinkingOverRadius = 0.12;
inline constexpr double kMaxHalfLengthOverRadius = 0.5;
inline constexpr double kMaxContactAngle_deg = 30;              ///< asin(kMaxHalfLengthOverRadius)
inline constexpr double kMaxSoilSinkageOverDiameter = 1.0 / 6;  ///< Wong's moderate sinkage

struct Validity {
  bool valid = true;
  std::string reason;  ///< why not, with the values and the limits; empty when valid
};

/// Whether a footprint of this sinking and contact length lies in the model's validity range.
Validity validity(const TyreConfig& config, double sinking_m, double contact_length_m);

/// On a soil: the tyre's deflection, the contact's edges seen from the axle (entry ahead,
/// exit behind the bottom) and the soil's sinkage each against its range; `rigid`: the rigid
/// cylinder (only the soil's range).
Validity validity_on_soil(const TyreConfig& config, double tyre_deflection_m, double soil_sinkage_m,
                          double entry_angle_rad, double exit_angle_rad, bool rigid = false);

/// A footprint's validity: on a soil by validity_on_soil (its edges seen from the axle), on a
/// road by validity(config, sinking, contact length).
Validity validity(const TyreConfig& config, const FootprintResult& footprint);

}  // namespace modaltyre::contact
