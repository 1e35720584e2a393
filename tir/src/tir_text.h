#pragma once
// The .tir writer's line formats, shared by tir_export.cc and slip_text.cc (internal).
#include <cstdio>
#include <ostream>
#include <string>

namespace modaltyre::tir::detail {

/// A number as the .tir gets it: ten significant digits.
inline std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

/// `KEY                      = value                $note` (MF-Tool's layout: the value at
/// column 27, the comment at column 48).
inline void key_line(std::ostream& s, const std::string& k, const std::string& v,
                     const std::string& note) {
  s << k << std::string(k.size() < 25 ? 25 - k.size() : 1, ' ') << "= " << v;
  if (!note.empty()) s << std::string(v.size() < 20 ? 20 - v.size() : 1, ' ') << " $" << note;
  s << "\n";
}

/// A header comment line.
inline void comment_line(std::ostream& s, const std::string& text) {
  s << "! : COMMENT :           " << text << "\n";
}

}  // namespace modaltyre::tir::detail
