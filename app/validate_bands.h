#pragma once
// `validate --uncertainty` (issue 35, docs/uncertainty.md section 7): the model's 95 % band at
// every measured row, from the config's uncertain inputs and the
// calibrated scalars' covariance, and which measured values lie outside it once their own
// stated noise (the `*_std` columns) is added.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "modaltyre/studies/validation.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::app {

/// validate's observables and their index in uncertainty::output_names().
struct BandObservable {
  const char* observable;  ///< "sinking_mm", "length_mm", "width_mm"
  std::size_t output;      ///< 0, 1, 2
};
const std::vector<BandObservable>& band_observables();

struct ValidationBands {
  uncertainty::PropagationResult result;  ///< cases: the rows
  std::size_t rows = 0;
  /// Per row: the observables whose measured value lies outside the band widened by its noise.
  std::vector<std::vector<std::string>> outside;
};

/// Whether `measured` lies outside the band widened by its std: each half-width h becomes
/// sqrt(h^2 + (1.96 std)^2) (model and measurement independent).
bool outside_band(const uncertainty::Band& b, double measured, double measured_std);

/// Propagates to the rows' conditions, with the calibration's inputs added.
ValidationBands validation_bands(const studies::ValidationReport& rep,
                                 const uncertainty::PropagationOptions& options);

/// Adds per row `uncertainty` (the bands) and `outside_band`, and the method, check and inputs.
void add_validation_bands_json(nlohmann::json& document, const ValidationBands& bands);

}  // namespace modaltyre::app
