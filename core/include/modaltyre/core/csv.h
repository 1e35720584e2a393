#pragma once
// Strict reader for the small numeric CSV files researchers bring (hammer data, footprint
// measurements, test records). Every problem is an InputError naming file, line and column.
//
// Quoting (RFC 4180, one record per line): a field whose first non-blank character is '"' is
// quoted; inside it a comma is literal and "" stands for one '"' (what `modaltyre sweep` writes
// for messages with commas or quotes). Quoted text is kept as it is, unquoted fields are trimmed
// of blanks; a quoted number ("1.5") is read as a number. A line break inside quotes is refused
// (the quote is unterminated at the end of its line: sweep messages never span lines), as is
// anything but blanks after a closing quote; a '"' inside an unquoted field is an ordinary
// character.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace modaltyre {

struct CsvSchema {
  std::vector<std::string> required;  ///< columns that must be present
  std::vector<std::string> optional;  ///< columns that may be present
  /// Columns whose cells are text (e.g. "branch"); all other columns must be finite numbers.
  std::vector<std::string> text;
  /// Columns whose cells may be empty; an empty number cell is refused only when it is read
  /// (CsvTable::number), so that a caller can look at other cells of the row first.
  std::vector<std::string> may_be_empty;
  /// Words that mark a missing value in a may_be_empty column, read as an empty cell (e.g. R's
  /// and spreadsheets' NA); CsvTable::missing tells them apart from numbers.
  std::vector<std::string> missing_words;
  /// Accepts further header names as optional text columns (e.g. a sweep's dotted config-key
  /// columns); any other unknown name is still an error.
  std::function<bool(const std::string&)> accept_text_column;
  std::size_t max_rows = 1000000;  ///< refuse larger files with a clear message
  /// Refuse more cells (rows x columns) than this: a stored cell costs about 40 bytes.
  std::size_t max_cells = 8000000;
  /// Refuse files larger than this before reading them (a measurement table is far smaller).
  std::uintmax_t max_bytes = std::uintmax_t{64} << 20;
};

class CsvTable {
 public:
  const std::string& path() const { return path_; }
  std::size_t rows() const { return cells_.size(); }
  bool has(const std::string& column) const;
  /// Finite number at (row, column); column must be numeric and present. An empty cell (allowed
  /// by CsvSchema::may_be_empty) is an InputError naming file, line and column.
  double number(std::size_t row, const std::string& column) const;
  /// The cell is empty or one of CsvSchema::missing_words (a may_be_empty column).
  bool missing(std::size_t row, const std::string& column) const;
  /// Number or fallback when the column is absent.
  double number_or(std::size_t row, const std::string& column, double fallback) const;
  const std::string& text(std::size_t row, const std::string& column) const;
  /// 1-based line of a data row in the file (for messages).
  int line(std::size_t row) const { return lines_.at(row); }
  const std::vector<std::string>& columns() const { return columns_; }

  friend CsvTable read_csv(const std::string& path, const CsvSchema& schema);

 private:
  std::size_t index_of(const std::string& column) const;
  std::string path_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> cells_;
  std::vector<std::vector<double>> numbers_;
  std::vector<int> lines_;
};

/// Reads and validates a CSV file: header with known columns, same field count on each line,
/// numeric cells finite. Blank lines and lines starting with '#' are skipped. An empty file (or
/// one of comments only) and a header without data rows are refused at a line; whole-file
/// problems (missing, a directory, a pipe, too large) name the file only (line 0).
CsvTable read_csv(const std::string& path, const CsvSchema& schema);

/// The header's column names as read_csv() parses them; empty when the file is not a readable
/// regular file or its header cannot be parsed (read_csv() then says why). Never throws.
std::vector<std::string> read_csv_header(const std::string& path);

/// Text from a file made safe to quote in a message: control bytes and bytes that are not
/// UTF-8 become \xNN, and text longer than max_bytes is cut with "...".
std::string printable(const std::string& text, std::size_t max_bytes = 40);

/// Parses a finite double in decimal notation (digits, sign, '.', exponent); nullopt for anything
/// else: text, NaN, inf, trailing garbage and hexadecimal ("0x1p4"), which strtod would read.
std::optional<double> parse_finite_double(const std::string& text);

/// " (hexadecimal is not read: write the number in decimal)" when `text` looks like a
/// hexadecimal number, else "": appended to a reader's "is not a finite number".
std::string decimal_hint(const std::string& text);

}  // namespace modaltyre
