#include "validate_bands.h"

#include <cmath>

#include "modaltyre/contact/carcass_source.h"
#include "modaltyre/report/uncertainty_json.h"
#include "modaltyre/uncertainty/inputs.h"

namespace modaltyre::app {
namespace {
constexpr double kBandZ975 = 1.959963984540054;  // the 97.5 % point of the standard normal
}  // namespace

const std::vector<BandObservable>& band_observables() {
  static const std::vector<BandObservable> list = {
      {"sinking_mm", 0}, {"length_mm", 1}, {"width_mm", 2}};
  return list;
}

bool outside_band(const uncertainty::Band& b, double measured, double measured_std) {
  const double noise = kBandZ975 * measured_std;
  const double lo = b.value - std::hypot(b.value - b.p025, noise);
  const double hi = b.value + std::hypot(b.p975 - b.value, noise);
  return measured < lo || measured > hi;
}

ValidationBands validation_bands(const studies::ValidationReport& rep,
                                 const uncertainty::PropagationOptions& options) {
  const auto& config = rep.model.config;  // calibrated values set
  const auto& c = rep.calibration;
  uncertainty::PropagationOptions o = options;
  if (!c.std_errors.empty()) {
    o.extra_inputs = uncertainty::calibration_inputs(c.keys, c.values, c.std_errors, c.correlation);
  }
  std::vector<contact::OperatingConditions> cases;
  for (const auto& r : rep.rows) cases.push_back(r.measured.conditions);
  ValidationBands out;
  out.rows = rep.rows.size();
  out.result = uncertainty::propagate(config, contact::config_modes(config), cases, o);
  for (std::size_t i = 0; i < rep.rows.size(); ++i) {
    const auto& row = rep.rows[i].measured;
    std::vector<std::string> off;
    for (const auto& b : band_observables()) {
      const auto v = row.value(b.observable);
      if (!v) continue;
      const auto s = row.observed_std.find(b.observable);
      const double sd = s == row.observed_std.end() ? 0.0 : s->second;
      if (outside_band(out.result.cases[i].bands[b.output], *v, sd)) off.push_back(b.observable);
    }
    out.outside.push_back(off);
  }
  return out;
}

void add_validation_bands_json(nlohmann::json& document, const ValidationBands& bands) {
  // The footprint's layout, per row: {sinking_mm: {value, std, p025, p975}, ...}.
  nlohmann::json tmp = {{"cases", nlohmann::json::array()}};
  for (std::size_t i = 0; i < bands.rows; ++i) tmp["cases"].push_back(nlohmann::json::object());
  report::add_uncertainty_json(tmp, bands.result);
  auto& rows = document["rows"];
  for (std::size_t i = 0; i < bands.rows && i < rows.size(); ++i) {
    rows[i]["uncertainty"] = tmp["cases"][i]["uncertainty"];
    rows[i]["outside_band"] = bands.outside[i];
  }
  for (const char* k : {"uncertainty_method", "uncertainty_check", "uncertainty_inputs",
                        "uncertainty_evaluations"}) {
    document[k] = tmp[k];
  }
}

}  // namespace modaltyre::app
