// The footprint's outputs as the propagation's (propagation.h): sinking, length, width, peak and
// mean pressure per load, and the caller's extra outputs (the pressure map's cells).
#include <stdexcept>
#include <string>
#include <vector>

#include "modaltyre/contact/footprint_measures.h"
#include "modaltyre/contact/predictor.h"
#include "modaltyre/contact/tyre_model.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::uncertainty {
namespace {

/// peak_pressure_kPa's index in output_names(): a maximum over the grid's cells, whose second
/// differences are the grid's, not the physics'; it is left out of the curvature check.
constexpr std::size_t kPeakOutput = 3;

using Outputs = std::vector<std::vector<double>>;  // [case][output]

Outputs footprint_outputs(const contact::TyreConfig& config, const modal::ModeIdentification& modes,
                          const std::vector<contact::OperatingConditions>& cases,
                          const ExtraOutputs& extra, const std::string& what) {
  const contact::TyreModel model = contact::build_tyre_model(config, modes);
  Outputs out;
  for (const auto& c : cases) {
    const contact::Prediction p = contact::predict(model, c);
    if (!p.ok()) {
      throw ComputationError("uncertainty: the prediction at " + std::to_string(c.load_N) +
                             " N with " + what + " failed: " + p.message);
    }
    out.push_back(footprint_output_values(p));
    if (extra.count > 0) {
      std::vector<double> more = extra.values(out.size() - 1, p);
      more.resize(extra.count, 0.0);
      out.back().insert(out.back().end(), more.begin(), more.end());
    }
  }
  return out;
}

}  // namespace

std::vector<double> footprint_output_values(const contact::Prediction& p) {
  return {p.sinking_mm, p.length_mm, p.width_mm, contact::peak_pressure_Pa(p) * 1e-3,
          contact::smooth_mean_pressure_Pa(p) * 1e-3};
}

PropagationResult propagate(const contact::TyreConfig& config,
                            const modal::ModeIdentification& modes,
                            const std::vector<contact::OperatingConditions>& cases,
                            const PropagationOptions& options) {
  return propagate(config, modes, cases, options, ExtraOutputs{});
}

PropagationResult propagate(const contact::TyreConfig& config,
                            const modal::ModeIdentification& modes,
                            const std::vector<contact::OperatingConditions>& cases,
                            const PropagationOptions& options, const ExtraOutputs& extra) {
  if (extra.count > 0 && !extra.values) {
    throw std::invalid_argument("uncertainty: ExtraOutputs.count > 0 needs its values function");
  }
  OutputSet outputs;
  outputs.names = output_names();
  outputs.curved.assign(outputs.names.size(), true);
  outputs.curved[kPeakOutput] = false;  // a maximum over the grid's cells: piecewise, not curved
  for (std::size_t k = 0; k < extra.count; ++k) {
    outputs.names.push_back(extra.label + " " + std::to_string(k + 1));
    outputs.curved.push_back(false);
  }
  for (const auto& c : cases) {
    outputs.row_labels.push_back(std::to_string(static_cast<long>(c.load_N)) + " N");
  }
  const Evaluator footprints = [&cases, &extra](const contact::TyreConfig& c,
                                                const modal::ModeIdentification& m,
                                                const std::string& what) {
    return footprint_outputs(c, m, cases, extra, what);
  };
  PropagationResult r = propagate_outputs(config, modes, footprints, outputs, options);
  for (std::size_t c = 0; c < cases.size(); ++c) r.cases[c].load_N = cases[c].load_N;
  return r;
}

}  // namespace modaltyre::uncertainty
