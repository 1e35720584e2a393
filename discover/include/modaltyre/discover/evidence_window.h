#pragma once
// The candidate window a group of traction rows (one load and speed) rolls on in discover,
// decided once from the measured data, never per evaluation (docs/discover.md, "Hidden soil
// effects"; traction_evidence.cc says why).
//
// Bound: a tyre of outer radius R whose soil sinks z below the undisturbed surface and whose
// own deflection is delta has its wheel centre at R - z - delta above the deepest point; where
// it touches the soil (at or below the surface ahead) its surface is pressed inward, never out,
// so the undeformed circle there lies at least at the surface's height:
//   |x_edge| <= a(d) = sqrt(2 R d - d^2),  d = z + delta   (the circle's half chord at depth d).
// Both edges (entry ahead, exit over the rebounded rut behind) obey it, and the window is
// centred on the wheel, so it needs the length 2 a(d). The tyre's deflection on the soil is
// taken at most its deflection on the rigid road at the same load (the soil carries part of
// the compliance in series). The window is 2 a(d) (1 + margin),
// rounded up to 10 mm, never shorter than the config's and at most contact::max_window_m.
#include <string>

#include "modaltyre/contact/tyre_config.h"

namespace modaltyre::discover {

/// Share added to the bound's length: a trial set may sink (1.1)^2 - 1 = 21 % deeper than the
/// data (total depth z + delta) before its row reaches the edge; the measured sinkage's noise
/// (~2 %) moves the bound by half its share.
inline constexpr double kWindowMargin = 0.1;

/// The half chord of a circle of radius R at depth d below its lowest point [m] (R at d >= R).
double rim_half_chord_m(double radius_m, double depth_m);

struct EvidenceWindow {
  double window_m = 0;  ///< the window the group's rows roll on
  bool grown = false;   ///< longer than the config's
  std::string why;      ///< in words, for the report
};

/// The config's window, kept for `reason` (in words).
EvidenceWindow config_window(const contact::TyreConfig& config, const std::string& reason);

/// The window for measured soil sinkage `sinkage_m` (the group's largest; <= 0: none measured)
/// and the tyre's road deflection `road_deflection_m` at the group's load (the rigid wheel
/// rolls on no candidate window: traction_evidence.cc keeps the config's for it).
EvidenceWindow evidence_window(const contact::TyreConfig& config, double sinkage_m,
                               double road_deflection_m);

}  // namespace modaltyre::discover
