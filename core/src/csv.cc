#include "modaltyre/core/csv.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include "modaltyre/core/errors.h"
#include "modaltyre/core/input_file.h"

namespace modaltyre {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string hex_byte(unsigned char c) {
  static const char* digits = "0123456789ABCDEF";
  return std::string("\\x") + digits[c >> 4] + digits[c & 0xF];
}

// Column of field i for messages: its header name, or its position where there is none.
using ColumnName = std::function<std::string(std::size_t)>;

// Splits one line into fields by the quoting rule of csv.h, refusing control bytes on the way
// (a binary file or an old Mac file with CR line ends) so that the column can be named.
std::vector<std::string> split(const std::string& line, const std::string& path, int line_no,
                               const ColumnName& column) {
  std::vector<std::string> out;
  auto fail = [&](const std::string& message) {
    throw InputError({path, line_no, column(out.size())}, message);
  };
  auto check_byte = [&](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\r')
      fail(
          "carriage return inside the line (old Mac line endings?): save the file "
          "with LF or CRLF line endings");
    if ((c < 0x20 && c != '\t') || c == 0x7F)
      fail("contains control or binary byte " + hex_byte(c) + "; not a text CSV");
  };
  const std::size_t n = line.size();
  std::size_t i = 0;
  while (true) {
    std::size_t j = i;
    while (j < n && (line[j] == ' ' || line[j] == '\t')) ++j;
    std::string cell;
    if (j < n && line[j] == '"') {
      std::size_t k = j + 1;
      bool closed = false;
      while (k < n) {
        if (line[k] == '"') {
          if (k + 1 < n && line[k + 1] == '"') {
            cell.push_back('"');
            k += 2;
            continue;
          }
          closed = true;
          ++k;
          break;
        }
        check_byte(line[k]);
        cell.push_back(line[k++]);
      }
      if (!closed) {
        fail(
            "unterminated quoted field: the closing '\"' is missing (a quoted field must end "
            "on its line)");
      }
      while (k < n && is_blank(line[k])) ++k;
      if (k < n && line[k] != ',') {
        fail(
            "text after the closing quote of a quoted field (write \"\" for a quote inside "
            "quotes)");
      }
      i = k;
    } else {
      std::size_t k = i;
      for (; k < n && line[k] != ','; ++k) check_byte(line[k]);
      cell = trim(line.substr(i, k - i));
      i = k;
    }
    out.push_back(std::move(cell));
    if (i >= n) break;
    ++i;  // past the comma
  }
  return out;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

void check_csv_file(const std::string& path, std::uintmax_t max_bytes) {
  check_input_file(path, "a CSV file", "CSV files", max_bytes);
}

// The first byte of `text` that is not UTF-8, as "\xNN"; empty when it is all UTF-8.
std::string first_non_utf8(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = utf8_sequence(text, i);
    if (n == 0) return hex_byte(static_cast<unsigned char>(text[i]));
    i += n;
  }
  return "";
}

void refuse_non_utf8(const std::string& text, const std::string& path, int line_no,
                     const std::string& where) {
  const std::string byte = first_non_utf8(text);
  if (byte.empty()) return;
  throw InputError(
      {path, line_no, where},
      "byte " + byte + " is not UTF-8 (a Latin-1 or Windows-1252 file?): save the file as UTF-8");
}

// The next line that is neither blank nor a comment, trimmed; false at the end of the file. A
// comment is text like the rest of the file: UTF-8, as the YAML files are (a Latin-1 degree
// sign in a comment is the file's encoding, which its numbers' units may share).
bool next_content_line(std::istream& in, std::string& line, int& line_no, const std::string& path) {
  std::string raw;
  while (std::getline(in, raw)) {
    ++line_no;
    if (line_no == 1 && raw.size() >= 3 && raw.compare(0, 3, "\xEF\xBB\xBF") == 0) raw.erase(0, 3);
    line = trim(raw);
    if (line_no == 1 && line.size() >= 2 &&
        (line.compare(0, 2, "\xFF\xFE") == 0 || line.compare(0, 2, "\xFE\xFF") == 0)) {
      return true;  // UTF-16: read_csv names it
    }
    if (!line.empty() && line[0] == '#') refuse_non_utf8(line, path, line_no, "comment");
    if (!line.empty() && line[0] != '#') return true;
  }
  return false;
}

}  // namespace

std::string printable(const std::string& text, std::size_t max_bytes) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (out.size() >= max_bytes) return out + "...";
    const auto c = static_cast<unsigned char>(text[i]);
    const std::size_t n = utf8_sequence(text, i);
    if (n == 0 || c < 0x20 || c == 0x7F) {
      out += hex_byte(c);
      ++i;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

std::optional<double> parse_finite_double(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty()) return std::nullopt;
  // Decimal notation only: strtod also reads hexadecimal ("0x853", "0x10p4"), "inf" and "nan",
  // which no measurement or config is written in; a stray 0x is a typo or the wrong column.
  if (t.find_first_not_of("0123456789+-.eE") != std::string::npos) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  // Overflow gives +-inf (refused below); underflow (1e-400) is a finite number that rounds to
  // a subnormal or zero, which the readers' own range checks then judge.
  if (end != t.c_str() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::string decimal_hint(const std::string& text) {
  const std::string t = trim(text);
  const std::size_t x = t.find_first_of("xX");
  if (x != std::string::npos && x > 0 && t[x - 1] == '0') {
    return " (hexadecimal is not read: write the number in decimal)";
  }
  return "";
}

bool CsvTable::has(const std::string& column) const { return contains(columns_, column); }

std::size_t CsvTable::index_of(const std::string& column) const {
  const auto it = std::find(columns_.begin(), columns_.end(), column);
  MODALTYRE_CHECK(it != columns_.end(), "CSV column '" + column + "' requested but absent");
  return static_cast<std::size_t>(it - columns_.begin());
}

double CsvTable::number(std::size_t row, const std::string& column) const {
  const double v = numbers_.at(row).at(index_of(column));
  // Parsed numbers are always finite: NaN marks an empty cell.
  if (std::isnan(v)) {
    throw InputError({path_, lines_.at(row), column},
                     "empty cell: '" + printable(cells_.at(row).at(index_of(column))) +
                         "' is not a finite number");
  }
  return v;
}

bool CsvTable::missing(std::size_t row, const std::string& column) const {
  return std::isnan(numbers_.at(row).at(index_of(column)));
}

double CsvTable::number_or(std::size_t row, const std::string& column, double fallback) const {
  return has(column) ? number(row, column) : fallback;
}

const std::string& CsvTable::text(std::size_t row, const std::string& column) const {
  return cells_.at(row).at(index_of(column));
}

CsvTable read_csv(const std::string& path, const CsvSchema& schema) {
  check_csv_file(path, schema.max_bytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "cannot open file for reading");

  CsvTable table;
  table.path_ = path;
  std::string line;
  int line_no = 0;
  int header_line = 0;
  std::vector<std::string> extra_text;  // header names accepted by schema.accept_text_column
  const ColumnName header_column = [](std::size_t i) { return "column " + std::to_string(i + 1); };
  const ColumnName data_column = [&](std::size_t i) {
    return i < table.columns_.size() ? table.columns_[i] : header_column(i);
  };
  while (next_content_line(in, line, line_no, path)) {
    if (line_no == 1 && line.size() >= 2 &&
        (line.compare(0, 2, "\xFF\xFE") == 0 || line.compare(0, 2, "\xFE\xFF") == 0)) {
      throw InputError({path, 1, ""}, "is UTF-16 encoded; save it as UTF-8 (\"CSV UTF-8\")");
    }
    if (header_line == 0) {
      header_line = line_no;
      const auto fields = split(line, path, line_no, header_column);
      for (std::size_t c = 0; c < fields.size(); ++c) {
        const std::string& name = fields[c];
        if (name.empty()) {
          throw InputError({path, line_no, header_column(c)}, "empty column name in header");
        }
        const bool extra = schema.accept_text_column && schema.accept_text_column(name);
        // An accepted free-form name (a sweep's dotted key) is printed back: UTF-8 only.
        if (extra && !valid_utf8(name)) {
          throw InputError({path, line_no, printable(name)},
                           "column name has bytes that are not UTF-8: save the file as UTF-8");
        }
        if (extra) extra_text.push_back(name);
        if (!extra && !contains(schema.required, name) && !contains(schema.optional, name)) {
          std::string known;
          for (const auto& k : schema.required) known += (known.empty() ? "" : ", ") + k;
          for (const auto& k : schema.optional) known += ", " + k + " (optional)";
          // A semicolon-separated file (a spreadsheet's export in many locales) arrives as
          // one long header cell: say so instead of listing columns.
          if (name.find(';') != std::string::npos) {
            throw InputError({path, line_no, printable(name)},
                             "the header is separated by ';' but the separator is ','; save the "
                             "file as comma-separated CSV (decimal point '.'), columns: " +
                                 known);
          }
          throw InputError({path, line_no, printable(name)}, "unknown column; expected: " + known);
        }
        if (contains(table.columns_, name))
          throw InputError({path, line_no, name}, "column appears twice in the header");
        table.columns_.push_back(name);
      }
      for (const auto& req : schema.required) {
        if (!contains(table.columns_, req))
          throw InputError({path, line_no, req}, "required column is missing from the header");
      }
      continue;
    }
    const auto fields = split(line, path, line_no, data_column);
    const std::size_t ncol = table.columns_.size();
    const std::string counts =
        "has " + std::to_string(fields.size()) + " fields, header has " + std::to_string(ncol);
    if (fields.size() < ncol) {
      throw InputError({path, line_no, table.columns_[fields.size()]},
                       counts + ": no value for this column");
    }
    if (fields.size() > ncol) {
      throw InputError({path, line_no, header_column(ncol)},
                       counts + ": field " + std::to_string(ncol + 1) + " has no column");
    }
    if (table.cells_.size() >= schema.max_rows) {
      throw InputError({path, line_no, ""},
                       "more than " + std::to_string(schema.max_rows) + " data rows; refusing");
    }
    if ((table.cells_.size() + 1) * ncol > schema.max_cells) {
      throw InputError({path, line_no, ""}, "more than " + std::to_string(schema.max_cells) +
                                                " cells (rows x columns); refusing");
    }
    std::vector<double> nums(fields.size(), 0.0);
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const std::string& col = table.columns_[c];
      if ((fields[c].empty() || contains(schema.missing_words, fields[c])) &&
          contains(schema.may_be_empty, col)) {
        nums[c] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      if (contains(schema.text, col) || contains(extra_text, col)) {
        if (fields[c].empty()) throw InputError({path, line_no, col}, "empty cell");
        continue;
      }
      const auto v = parse_finite_double(fields[c]);
      if (!v) {
        throw InputError({path, line_no, col},
                         "'" + printable(fields[c]) + "' is not a finite number" +
                             (valid_utf8(fields[c]) ? decimal_hint(fields[c])
                                                    : " (bytes that are not UTF-8: save "
                                                      "the file as UTF-8)"));
      }
      nums[c] = *v;
    }
    table.cells_.push_back(fields);
    table.numbers_.push_back(std::move(nums));
    table.lines_.push_back(line_no);
  }
  if (header_line == 0) {
    throw InputError({path, std::max(line_no, 1), ""},
                     line_no == 0 ? "the file is empty: no header line"
                                  : "the file is empty: only blank and comment lines, no header");
  }
  if (table.cells_.empty()) {
    throw InputError({path, header_line, ""}, "header only, no data rows");
  }
  return table;
}

std::vector<std::string> read_csv_header(const std::string& path) {
  try {
    check_csv_file(path, CsvSchema{}.max_bytes);
    std::ifstream in(path, std::ios::binary);
    std::string line;
    int line_no = 0;
    if (!in || !next_content_line(in, line, line_no, path)) return {};
    return split(line, path, line_no, [](std::size_t) { return std::string(); });
  } catch (const InputError&) {
    return {};
  }
}

}  // namespace modaltyre
