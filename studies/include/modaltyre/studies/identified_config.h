#pragma once
// The identify -> tyre-config link (docs/rheology.md section 6): rheological parameters
// identified from simple tyre and soil tests (seed 000, modaltyre::rheology) mapped into a tyre
// config the footprint model runs, as effects and as the carcass level modal.compliance_scale.
//
// It lives in studies/ because it needs both sides: the rheology results (rheology/ depends on
// core only and must not learn about the tyre model) and the static tyre with its carcass-level
// calibration (contact/ and studies/stiffness_calibration.h). Inputs are plain values: the
// method's results, the file names for the notes, the tyre config; nothing of the command line.
//
// Use: read TYRE (contact::load_tyre_config) into a ConfigTarget before fitting, fit with
// rheology::identify_*, call the method's map_* function (it also notes every identified
// parameter), then write compose_identified_config(...).text to OUT.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_config.h"
#include "modaltyre/rheology/bevameter.h"
#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"
#include "modaltyre/studies/stiffness_calibration.h"

namespace modaltyre::studies {

/// What an identification determines in the tyre config.
struct ConfigMapping {
  std::vector<std::string> enabled;                    ///< effect names switched on
  std::vector<std::pair<std::string, double>> values;  ///< dotted key, value in the key's unit
  std::vector<std::pair<std::string, std::string>> words;  ///< dotted key, a word (ground.model)
  std::vector<std::string> notes;                      ///< how each value was obtained, why
};

/// The identification: the method's name (as `modaltyre identify` spells it, e.g.
/// "load-deflection") and its measurement file ("" when none), named in notes and messages.
struct IdentifiedSource {
  std::string method;
  std::string data_file;
};

/// The tyre config the identified values go into and the mapping so far.
struct ConfigTarget {
  std::string tyre_path;     ///< TYRE, the config the values go into
  std::string out_path;      ///< OUT, where the result is written (paths are re-anchored to it)
  contact::TyreConfig tyre;  ///< TYRE as the tyre config reader read it
  ConfigMapping mapping;
};

/// Why the footprint model has no place for what `method` identifies; empty when it has one
/// (docs/rheology.md 6.4). `static_loop`: free-vibration was given a static loop.
std::string unmapped_reason(const std::string& method, bool static_loop);

/// Saint-Venant force of the three-element model, the third term of seed 000 eq. (14) with
/// sgn dh/dt = +-1 (eq. 18 solved for P_Zv): P_Zv = 2 B_tr chi E1 r0 phi1 cos phi1 [N].
double dry_friction_force_N(double chi, double E1_Pa, double tread_width_m, double r0_m,
                            double phi1_rad);

/// Three-element model (static loop + free decay; `result.static_fit` must be set) ->
/// effects.dry_friction.friction_force_N at the test's contact length.
void map_three_element(const rheology::FreeVibrationResult& result,
                       const rheology::StaticLoop& loop, const rheology::ThreeElementOptions& o,
                       ConfigTarget& target);

/// Kelvin-Voigt soil (rolling tests) -> effects.soil_compliance (modulus E2, layer depth A).
void map_soil(const rheology::SoilData& data, const rheology::SoilResult& result,
              ConfigTarget& target);

/// Plate-sinkage tests -> the ground: section, ground.model = bekker with n, k_c, k_phi (and
/// unloading k0, Au when the file has cycles), in Wong's units (docs/soil.md section 6).
void map_bevameter(const rheology::BevameterResult& result, ConfigTarget& target);

/// Shear tests -> the soil's Janosi-Hanamoto keys of TYRE's ground (bekker or kelvin_voigt);
/// InputError when TYRE's ground is not a soil (identify bevameter first).
void map_shear(const rheology::ShearResult& result, ConfigTarget& target);

/// Load-deflection (eq. 3) -> the load and pressure laws the data span, then the carcass level
/// at which the footprint model sinks eq. (3)'s h_Z at the mean test load (docs/rheology.md 6.5).
void map_load_deflection(const IdentifiedSource& source, const rheology::LoadDeflectionData& data,
                         const rheology::LoadDeflectionResult& result, ConfigTarget& target);

/// Contact-stress profile (eq. 8-12) -> the carcass level at which the footprint model sinks the
/// profile's h_Z under its load P_Z (docs/rheology.md 6.6); `r0_m` is the radius of the fit.
void map_contact_stress(const IdentifiedSource& source, const rheology::ContactStressResult& result,
                        double r0_m, ConfigTarget& target);

/// OUT: a header of notes, then TYRE's text with the mapping's keys set in place (its comments
/// kept; re-emitted without them, said in the header, when a key cannot be set in place),
/// modal.hammer_csv re-anchored to OUT's folder, and every key the mapping sets removed from
/// validation.calibrate (`validate` would overwrite the identified value; noted); and OUT as the
/// tyre config reader reads it (InputError naming the key otherwise).
struct IdentifiedConfig {
  std::string text;
  contact::TyreConfig config;
  std::vector<std::string> notes;  ///< the mapping's notes and what composing changed besides
};
IdentifiedConfig compose_identified_config(const IdentifiedSource& source,
                                           const ConfigTarget& target);

/// The carcass level modal.compliance_scale at which OUT's footprint model (the mapping so far
/// applied, so the effects it switched on act) sinks `target_mm` under `load_N` at the tyre's
/// pressure. ComputationError when the calibration fails; InputError when no scale reaches it.
struct CarcassLevel {
  contact::TyreConfig fed;                          ///< OUT with the calibrated scale
  std::unique_ptr<const contact::TyreModel> model;  ///< OUT's model (before the calibration)
  ScaleCalibration cal;
};
CarcassLevel calibrate_carcass_level(const IdentifiedSource& source, const ConfigTarget& target,
                                     double load_N, double target_mm);

}  // namespace modaltyre::studies
