#pragma once
// Reader of `.tir` tyre property files (MF-Tyre 5.x, 6.x and MF-Swift 6.x as written by MF-Tool
// and copied around the vehicle-dynamics ecosystem; docs/tir.md).
//
// Syntax (the MDI/TeimOrbit property-file layout):
//   $ ...            comment to the end of the line (outside quotes), e.g. `$-----units`
//   ! ...            comment to the end of the line (outside quotes)
//   [SECTION]        starts a section; names are letters, digits and '_'
//   KEY = value      a number (Fortran 'D' exponents accepted), a quoted string '...' or "...",
//                    or a bare word (kept as text)
//   {col1 col2 ...}  names the columns of a table section such as [DEFLECTION_LOAD_CURVE]
//   1.0  2.0 ...     a table row (numbers only), with or without a {...} header
// Section and key names are compared case-insensitively (stored upper-case). Sections and keys
// the bridge does not use are kept, not rejected. A key given twice in a section is refused
// (which value would a simulator take?), as is a key outside any section. A section given twice
// with different contents is refused for the same reason (simulators disagree: Project Chrono's
// reader takes the first, a reader that overwrites takes the last); a verbatim repeat is read
// once, with a note. `KEY =` with
// nothing after it (written by some tools for a parameter that is not set) has no value.
//
// Every problem is an InputError naming the file, the line and the key (SECTION.KEY); sizes are
// bounded (TirLimits). The reader knows nothing about which tyre model a file holds: mf_tyre.h
// interprets it (and refuses an FTire file, which shares the extension).
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace modaltyre::tir {

struct TirLimits {
  std::size_t max_bytes = std::size_t{16} << 20;  ///< a real .tir is 10-100 kB
  std::size_t max_line_bytes = 4096;
  std::size_t max_sections = 1000;
  std::size_t max_entries = 100000;     ///< keys over all sections
  std::size_t max_table_rows = 100000;  ///< rows over all tables
  std::size_t max_table_columns = 64;
};

struct TirValue {
  std::string text;              ///< as written (quotes removed); empty for `KEY =`
  std::optional<double> number;  ///< set when the value is a finite number
  bool quoted = false;
  int line = 0;
};

struct TirTable {
  std::vector<std::string> columns;  ///< upper-case names from {...}; empty without a header
  std::vector<std::vector<double>> rows;
  std::vector<int> row_lines;
  int header_line = 0;
};

struct TirSection {
  std::string name;  ///< upper-case, without brackets
  int line = 0;
  std::map<std::string, TirValue> entries;  ///< upper-case key -> value
  TirTable table;                           ///< rows of a table section (may be empty)
};

struct TirFile {
  std::string path;                  ///< as given, for messages
  std::vector<TirSection> sections;  ///< in file order (a repeated section after its first)
  /// Every comment's text (without '$'/'!'), for recognising files by their header lines.
  std::vector<std::string> comments;
  /// What the reader accepted but a user should know ("file:line: ..."), e.g. a repeated section.
  std::vector<std::string> notes;

  const TirSection* section(const std::string& name) const;
  /// SECTION.KEY in the first [SECTION]; nullptr when absent or written `KEY =` (no value).
  const TirValue* value(const std::string& section, const std::string& key) const;
};

/// Parses `.tir` text; `name` is used in messages.
TirFile parse_tir(const std::string& text, const std::string& name, const TirLimits& limits = {});

/// Reads and parses a file (refuses a missing file, a directory, a pipe, an oversized file).
TirFile read_tir(const std::string& path, const TirLimits& limits = {});

}  // namespace modaltyre::tir
