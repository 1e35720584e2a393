#pragma once
// The identify command's library half: its inputs, the fit of the chosen seed-000 method and
// the JSON document of `modaltyre identify --json` (and the Python module's identify). What the
// command does besides (plots, the tyre config it writes) starts from the run's data and result.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>

#include "modaltyre/rheology/bevameter.h"
#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/slope_factors.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"

namespace modaltyre::report {

/// What the command's options give; numbers < 0 are "not given".
struct IdentifyInputs {
  std::string method;  ///< load-deflection | b-factors | contact-stress | free-vibration |
                       ///< soil-rolling | bevameter | shear
  std::string file;    ///< measurement CSV (none for b-factors)
  /// Tyre config the geometry of the tyre tests comes from (tyre.outer_radius_mm,
  /// tyre.inflation_pressure_kPa, tread.contact_width_mm); "" for none (identify_geometry_config).
  std::string geometry_config;
  double r0_mm = -1, tread_width_mm = -1, mass_kg = -1, contact_length_mm = -1;
  double section_height_mm = -1, pressure_kPa = -1;
  std::string static_file;              ///< free-vibration: the static loop (E1, chi)
  int samples = 6;                      ///< b-factors: points over the range
  std::string sampling = "deflection";  ///< b-factors: deflection | angle
  bool intercept = false;               ///< b-factors: y = B x + c
  double max_h_r0 = 0.117;              ///< b-factors: upper end of h_Z/r0
};

/// The config the geometry comes from for the methods that test the tyre itself
/// (load-deflection, contact-stress, free-vibration): `config`; "" for the others (soil-rolling
/// tests a rigid wheel, whose r0 and B_tr a tyre config does not hold).
std::string identify_geometry_config(const std::string& method, const std::string& config);

struct LoadDeflectionRun {
  rheology::LoadDeflectionData data;
  rheology::LoadDeflectionResult result;
};
struct SlopeFactorRun {
  rheology::SlopeFactorResult result;
};
struct ContactStressRun {
  rheology::StressData data;
  rheology::ContactStressOptions options;
  rheology::ContactStressResult result;
};
struct FreeVibrationRun {
  rheology::DecaySignal signal;
  std::optional<rheology::StaticLoop> loop;
  rheology::ThreeElementOptions options;
  rheology::FreeVibrationResult result;
};
struct SoilRun {
  rheology::SoilData data;
  rheology::SoilResult result;
};

/// Soil parameters from plate-sinkage and shear tests (rheology/bevameter.h, docs/soil.md).
struct BevameterRun {
  rheology::PlateData data;
  rheology::BevameterResult result;
};
struct ShearRun {
  rheology::ShearData data;
  rheology::ShearResult result;
};

struct IdentifyRun {
  std::variant<LoadDeflectionRun, SlopeFactorRun, ContactStressRun, FreeVibrationRun, SoilRun,
               BevameterRun, ShearRun>
      fit;
  /// method, parameters (value, unit, std_error), residual, rows, notes, the method's extras
  /// and the file (the command adds into_config when it writes a tyre config).
  nlohmann::json document;
};

/// InputError for an unknown method or sampling, a FILE missing or given to b-factors, --static
/// with another method (checks that need no file read).
void check_identify_inputs(const IdentifyInputs& in);

/// check_identify_inputs, then reads the data and fits the method (InputError also for a
/// non-positive size and unreadable data).
IdentifyRun run_identify(const IdentifyInputs& in);

/// The JSON of a fit: method, parameters (value, unit, std_error), residual, rows, notes.
nlohmann::json fit_report_json(const rheology::FitReport& r);

}  // namespace modaltyre::report
