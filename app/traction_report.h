#pragma once
// What `modaltyre traction` prints and draws (docs/soil.md section 5): the table of the cases
// with each curve's rolling radius, towed and self-propelled points, and the figure.
#include <string>
#include <vector>

#include "modaltyre/contact/traction.h"
#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::app {

struct TractionRun {
  const contact::TyreConfig* config = nullptr;  ///< as run (a 3D config's 2D patch applied)
  const ground::GroundSettings* ground = nullptr;
  bool rigid = false;
  int passes = 1;
  contact::SlipReference reference = contact::SlipReference::rolling;
};

void print_traction_table(const TractionRun& run,
                          const std::vector<contact::TractionResult>& results);

void plot_traction(const TractionRun& run, const std::vector<contact::TractionResult>& results,
                   const std::string& path);

}  // namespace modaltyre::app
