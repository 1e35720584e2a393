#pragma once
// What `modaltyre identify` prints and draws: the parameter table or JSON, the standalone
// 'rheology:' record of --write-config, and one figure per method (the fitted law over the data).
#include <nlohmann/json.hpp>
#include <string>

#include "modaltyre/rheology/contact_stress.h"
#include "modaltyre/rheology/load_deflection.h"
#include "modaltyre/rheology/slope_factors.h"
#include "modaltyre/rheology/soil.h"
#include "modaltyre/rheology/three_element.h"

namespace modaltyre::app {

/// The table of `out` (report::run_identify's document plus the command's additions) as
/// `identify` prints it.
void print_report(const nlohmann::json& out, const std::string& source);

/// The 'rheology:' YAML record of the parameters in `out`, written atomically to `path`.
struct RecordSource {
  std::string method, data_file, tyre_config;
};
void write_rheology_record(const std::string& path, const RecordSource& source,
                           const nlohmann::json& out);

void plot_load_deflection(const rheology::LoadDeflectionData& data,
                          const rheology::LoadDeflectionResult& res, const std::string& path);
void plot_b_factors(const rheology::SlopeFactorResult& res, const std::string& path);
void plot_contact_stress(const rheology::StressData& data, const rheology::ContactStressResult& res,
                         double r0_m, const std::string& path);
/// `loop` is drawn with the static fit when the result has one.
void plot_free_vibration(const rheology::DecaySignal& signal, const rheology::StaticLoop* loop,
                         const rheology::FreeVibrationResult& res,
                         const rheology::ThreeElementOptions& o, const std::string& path);
void plot_soil(const rheology::SoilData& data, const rheology::SoilResult& res,
               const std::string& path);

}  // namespace modaltyre::app
