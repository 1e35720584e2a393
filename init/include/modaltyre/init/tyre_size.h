#pragma once
// A tyre's ISO metric size designation, e.g. "195/60R14", "205/60 R15", "P205/60R15 91H",
// "225/45ZR17": nominal section width (mm), aspect ratio (%), construction, rim diameter (in).
// The nominal geometry follows from it (ETRTO / ISO 4000-1 designation): rim radius
// = 25.4 D / 2 mm, section height = width x aspect, outer radius = rim radius + height.
#include <string>

namespace modaltyre::init {

struct TyreSize {
  std::string text;             ///< as given
  double section_width_mm = 0;  ///< nominal section width
  double aspect_ratio = 0;      ///< section height / width (0.60 for "/60")
  double rim_diameter_in = 0;   ///< nominal rim diameter [in]

  double rim_radius_mm() const { return 25.4 * rim_diameter_in / 2; }
  double section_height_mm() const { return section_width_mm * aspect_ratio; }
  double outer_radius_mm() const { return rim_radius_mm() + section_height_mm(); }
};

/// Parses a designation; InputError naming `option` (e.g. "--size") and what a valid one looks
/// like. Widths 50-700 mm, aspect 20-120 %, rims 8-30 in (passenger to light-truck sizes and
/// well beyond; a value outside is a typo).
TyreSize parse_tyre_size(const std::string& text, const std::string& option = "--size");

}  // namespace modaltyre::init
