#pragma once
// The 2D patch on a ground other than the flat rigid road (ground/, docs/soil.md section 4):
// a road height profile (a rigid road of another shape), or a deformable soil in series with
// the tread and the carcass.
//
// Profile: the unit at theta_i (undeformed position x_i = R0 sin theta_i from the axle, the axle
// at `position_m` on the profile) starts at the gap sag_i - h(position + x_i); sinking is the
// axle's approach to the profile's reference height 0.
// Soil: each unit carries its soil's sinkage Z(p, z_max) at its pressure p = f / (b_t dx) (b_t
// the contact width, dx = ds cos theta) in series with the tyre (ground_contact.h); sinking is
// the axle's approach to the undisturbed surface, soil_sinkage the deepest unit's Z, and Bekker's
// b = min(contact width, contact length), iterated with the solution.
#include <span>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/contact/soil_rate_term.h"
#include "modaltyre/ground/ground_settings.h"

namespace modaltyre::contact {

struct GroundPatchInput {
  /// The soil's memory per candidate unit (z_max, 0 = virgin); empty: virgin everywhere.
  std::span<const double> z_max_m;
  /// Extra gap per candidate unit [m] (e.g. the carcass's vertical displacement under the
  /// contact's horizontal forces in rolling); empty: none.
  std::span<const double> gap_offset_m;
  double position_m = 0;  ///< profile: the axle's position along it
  /// Bekker's b to start from (0: the contact width).
  double bekker_width_m = 0;
  /// Fix Bekker's b at bekker_width_m (no iteration with the contact length).
  bool fixed_bekker_width = false;
  std::span<const char> warm_active;
  /// Vertical forces per candidate unit to start the soil's linearisation from (empty: none).
  std::span<const double> initial_force_N;
  /// Rolling: the slip (against the rolling radius) the soil's slip sinkage is taken at
  /// (ground/soil_options.h; 0: none).
  double slip = 0;
  /// Rolling on a viscous soil: the rate term per candidate unit (soil_rate_term.h); null: none.
  const SoilRate* rate = nullptr;
  /// Per candidate unit its own law in place of the soil's (empty or null: the soil's).
  std::span<const ground::PressureSinkage* const> unit_law;
};

/// Solves one load case on the config's ground with a given operator (its horizontal_ratio must
/// be 0; symmetric). A rigid flat ground gives solve_patch()'s result.
FootprintResult solve_ground_patch(const TyreModel& model, PatchOperator op, const LoadCase& load,
                                   const ground::GroundSettings& ground,
                                   const GroundPatchInput& input = {});

}  // namespace modaltyre::contact
