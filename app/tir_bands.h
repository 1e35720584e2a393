#pragma once
// `tir export --uncertainty` (issue 35, docs/uncertainty.md section 9): the config's uncertain
// inputs (the hammer shapes' noise, stated standard deviations) propagated to the fitted MF
// coefficients, by the same linearised-or-sampled propagation as the footprint's bands.
#include <string>
#include <vector>

#include "modaltyre/tir/tir_export.h"
#include "modaltyre/uncertainty/propagation.h"

namespace modaltyre::app {

struct TirBands {
  std::vector<std::string> names;         ///< the .tir keys, VERTICAL_STIFFNESS in N/mm
  uncertainty::PropagationResult result;  ///< one row: the bands per name
};

/// Re-fits the coefficients the nominal fit `f` carries at each perturbed input.
TirBands tir_bands(const contact::TyreConfig& config, const tir::TirExportOptions& options,
                   const tir::TirFit& f, const uncertainty::PropagationOptions& propagation);

/// The header comments of the .tir (value, std and 95 % band per coefficient, the method).
std::vector<std::string> tir_band_comments(const TirBands& bands);

/// The text table: value +- 2 sigma per coefficient, then the inputs.
void print_tir_bands(const TirBands& bands);

}  // namespace modaltyre::app
