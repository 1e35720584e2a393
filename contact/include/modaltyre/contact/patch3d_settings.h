#pragma once
// The settings of the 3D contact patch (patch3d.h), section `footprint_3d:` of the tyre config:
// the tread width (the shoulder limit), the lateral cell, the crown profile and the optional
// lateral belt. A config with this section is predicted on the 3D patch (predictor.h).
#include "modaltyre/contact/crown_profile.h"
#include "modaltyre/contact/sidewall_membrane.h"
#include "modaltyre/core/config_tree.h"

namespace modaltyre::contact {

/// How the belt strip of a section is held at its lateral ends.
enum class BeltSupports {
  shoulders,  ///< simply supported (no deflection, no moment) at +-span/2: the sidewalls
  free,       ///< free ends at the tread edges, on a foundation; its rigid motion is the carcass's
};

/// The belt's lateral flexibility (docs/footprint.md section 7): each section's belt strip is an
/// Euler-Bernoulli beam across the tread, loaded by its cells' forces. Disabled = laterally rigid
/// (the sections' cells move together).
struct LateralBelt {
  bool enabled = false;
  double bending_stiffness_Nm = 1.0;  ///< D, per unit circumferential length [N m], > 0
  double tension_N_m = 0;             ///< meridional membrane tension N [N/m], >= 0 (shoulders)
  double foundation_Pa_m = 0;         ///< Winkler foundation k [N/m^3], >= 0; > 0 when free
  BeltSupports supports = BeltSupports::shoulders;
  double support_span_m = 0;  ///< shoulders: distance between the supports, 0 = tread width
  /// The config states the section (enabled or, with enabled: false, its values for the
  /// lateral_belt effect of effects.h to switch on).
  bool given = false;
  /// Throws std::invalid_argument naming what is inconsistent.
  void validate(double tread_width_m) const;
};

struct Patch3dSettings {
  double tread_width_m = 0.15;     ///< shoulder to shoulder: no cell outside +-width/2
  double lateral_cell_m = 2.5e-3;  ///< target cell width; columns = round(width / cell)
  CrownProfile crown;
  LateralBelt lateral_belt;   ///< disabled: laterally rigid sections
  SidewallMembrane sidewall;  ///< disabled: the modes' linear sidewalls
  /// sidewall: fixed-point steps on the sidewalls' correction per load, and their tolerance on
  /// the correction's gap offset relative to the sinking.
  int max_sidewall_iterations = 200;
  double sidewall_tolerance = 1e-11;
  /// sidewall: Anderson mixing over this many previous steps (0: the plain iteration).
  int sidewall_anderson_depth = 3;
  int max_pattern_iterations = 200;  ///< Newton steps on the lateral pattern per load
};

/// Settings from the `footprint_3d:` section (tread_width_mm, lateral_cell_mm, crown: ...,
/// lateral_belt: ..., sidewall: ...); errors name file, line and key.
Patch3dSettings read_patch3d_settings(const ConfigSection& section);

}  // namespace modaltyre::contact
