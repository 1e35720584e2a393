#include "transient_bands.h"

#include "footprint_report.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/report/uncertainty_json.h"
#include "modaltyre/transient/decay.h"
#include "modaltyre/transient/model.h"

namespace modaltyre::app {

std::vector<double> transient_summary(const transient::TransientResult& r,
                                      std::vector<std::string>* names) {
  const auto& fin = r.samples.back();
  std::vector<std::pair<std::string, double>> v = {
      {"sinking_mm", fin.sinking_m * 1e3}, {"contact_length_mm", fin.contact_length_m * 1e3}};
  if (r.patch_3d) {
    v.emplace_back("width_mm", fin.width_m * 1e3);
    v.emplace_back("contact_area_mm2", fin.contact_area_m2 * 1e6);
  }
  // The rolling resistance is a mean force over the run's last tenth: a quantity of the
  // scenarios that roll (at rest it is the solver's residual).
  if (r.scenario == transient::Scenario::rolling || r.scenario == transient::Scenario::cleat) {
    v.emplace_back("rolling_resistance_N", r.rolling_resistance_N);
  }
  if (r.on_soil) {
    v.emplace_back("soil_sinkage_mm", fin.soil_sinkage_m * 1e3);
    v.emplace_back("compaction_resistance_N", fin.soil_resistance_N);
  }
  if (r.scenario == transient::Scenario::free_vibration) {
    const transient::BounceDecay d = transient::bounce_decay(r);
    if (d.peaks >= 2) {
      v.emplace_back("period_s", d.period_s);
      v.emplace_back("log_decrement", d.log_decrement);
    }
  }
  std::vector<double> values;
  if (names) names->clear();
  for (const auto& [name, value] : v) {
    values.push_back(value);
    if (names) names->push_back(name);
  }
  return values;
}

TransientBands transient_bands(const contact::TyreConfig& config, transient::Scenario scenario,
                               const transient::TransientResult& nominal,
                               const uncertainty::PropagationOptions& propagation) {
  TransientBands b;
  const std::vector<double> values = transient_summary(nominal, &b.names);
  // e.g. a perturbed free vibration that decays in fewer than two peaks: not a band.
  const uncertainty::RowEvaluator rerun = [scenario](const contact::TyreConfig& c,
                                                     const modal::ModeIdentification& m,
                                                     const std::string& what) {
    const auto model = transient::build_transient_model(contact::build_tyre_model(c, m));
    const transient::TransientResult r = transient::run_scenario(model, scenario, {});
    if (!r.ok()) {
      throw ComputationError("transient --uncertainty: the run with " + what +
                             " failed: " + r.message);
    }
    std::vector<std::string> names;
    std::vector<double> v = transient_summary(r, &names);
    return std::make_pair(std::move(names), std::move(v));
  };
  b.result = uncertainty::propagate_row(config, contact::config_modes(config), rerun, b.names,
                                        values, "the run's end", "transient", propagation);
  return b;
}

void add_transient_bands_json(nlohmann::json& document, const TransientBands& bands) {
  document["uncertainty"] = report::bands_json(bands.names, bands.result.cases.front().bands);
  report::add_uncertainty_method_json(document, bands.result);
}

void print_transient_bands(const TransientBands& bands) {
  print_named_bands(bands.names, bands.result);
}

}  // namespace modaltyre::app
