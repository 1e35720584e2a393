#pragma once
// The figures of `identify bevameter` and `identify shear` (docs/soil.md section 6): the fitted
// laws over the data.
#include <string>

#include "modaltyre/rheology/bevameter.h"

namespace modaltyre::app {

void plot_bevameter(const rheology::PlateData& data, const rheology::BevameterResult& res,
                    const std::string& path);
void plot_shear(const rheology::ShearData& data, const rheology::ShearResult& res,
                const std::string& path);

}  // namespace modaltyre::app
