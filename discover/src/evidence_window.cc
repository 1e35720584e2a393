#include "modaltyre/discover/evidence_window.h"

#include <algorithm>
#include <cmath>

#include "modaltyre/contact/footprint.h"
#include "modaltyre/core/number_format.h"

namespace modaltyre::discover {

double rim_half_chord_m(double radius_m, double depth_m) {
  const double d = std::clamp(depth_m, 0.0, radius_m);
  return std::sqrt(2 * radius_m * d - d * d);
}

EvidenceWindow config_window(const contact::TyreConfig& config, const std::string& reason) {
  return {config.mesh.window_m, false,
          "the config's " + number_text(config.mesh.window_m * 1e3) + " mm (" + reason + ")"};
}

EvidenceWindow evidence_window(const contact::TyreConfig& config, double sinkage_m,
                               double road_deflection_m) {
  if (!(sinkage_m > 0)) return config_window(config, "no measured sinkage");
  const double depth_m = sinkage_m + std::max(road_deflection_m, 0.0);
  const double bound_m = 2 * rim_half_chord_m(config.outer_radius_m, depth_m);
  // Rounded up to 10 mm, as contact::suggested_window_mm rounds a grown window.
  const double want_m = std::ceil(bound_m * (1 + kWindowMargin) * 1e2 - 1e-9) * 1e-2;
  const std::string derivation = "measured sinkage " + number_text(sinkage_m * 1e3) +
                                 " mm + road deflection " + number_text(road_deflection_m * 1e3) +
                                 " mm: rim chord " + number_text(bound_m * 1e3) + " mm, +" +
                                 number_text(kWindowMargin * 100) + " %";
  if (want_m <= config.mesh.window_m)
    return config_window(config, derivation + " = " + number_text(want_m * 1e3) + " mm fits in it");
  const double cap_m = contact::max_window_m(config);
  EvidenceWindow w;
  w.window_m = std::max(config.mesh.window_m, std::min(want_m, cap_m));
  w.grown = w.window_m > config.mesh.window_m;
  w.why = number_text(w.window_m * 1e3) + " mm, grown from the config's " +
          number_text(config.mesh.window_m * 1e3) + " mm (" + derivation +
          (want_m > cap_m ? ", capped at the largest window allowed)" : ")");
  return w;
}

}  // namespace modaltyre::discover
