#include "modaltyre/init/tyre_size.h"

#include <cctype>
#include <regex>

#include "modaltyre/core/errors.h"

namespace modaltyre::init {

TyreSize parse_tyre_size(const std::string& text, const std::string& option) {
  // Optional service prefix (P, LT, T), width, "/", aspect, optional speed letter, construction
  // R (radial), optional space, rim; a load index and speed symbol may follow.
  static const std::regex re(
      R"(^\s*(?:P|LT|T)?\s*(\d{2,3})\s*/\s*(\d{2,3})\s*[A-Z]?R\s*(\d{1,2}(?:\.\d)?)(?:\s+\d{2,3}[A-Z]{1,2})?\s*$)",
      std::regex::icase);
  std::smatch m;
  auto bad = [&](const std::string& why) {
    return InputError({option, 0, ""}, "'" + text + "' " + why +
                                           " (a tyre size designation such as 195/60R14 or "
                                           "205/60 R15: section width mm / aspect % R rim in)");
  };
  if (text.size() > 64 || !std::regex_match(text, m, re)) throw bad("is not a size designation");
  TyreSize s;
  s.text = text;
  s.section_width_mm = std::stod(m[1].str());
  s.aspect_ratio = std::stod(m[2].str()) / 100.0;
  s.rim_diameter_in = std::stod(m[3].str());
  if (s.section_width_mm < 50 || s.section_width_mm > 700)
    throw bad("has a width outside 50-700 mm");
  if (s.aspect_ratio < 0.2 || s.aspect_ratio > 1.2)
    throw bad("has an aspect ratio outside 20-120 %");
  if (s.rim_diameter_in < 8 || s.rim_diameter_in > 30) throw bad("has a rim outside 8-30 in");
  return s;
}

}  // namespace modaltyre::init
