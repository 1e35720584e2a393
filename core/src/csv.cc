#include "modaltyre/core/csv.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>

#include "modaltyre/core/errors.h"

namespace modaltyre {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (char c : line) {
    if (c == ',') {
      out.push_back(trim(cell));
      cell.clear();
    } else {
      cell.push_back(c);
    }
  }
  out.push_back(trim(cell));
  return out;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace

std::optional<double> parse_finite_double(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (end != t.c_str() + t.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
  return v;
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
    throw InputError({path_, lines_.at(row), column}, "empty cell: '' is not a finite number");
  }
  return v;
}

double CsvTable::number_or(std::size_t row, const std::string& column, double fallback) const {
  return has(column) ? number(row, column) : fallback;
}

const std::string& CsvTable::text(std::size_t row, const std::string& column) const {
  return cells_.at(row).at(index_of(column));
}

CsvTable read_csv(const std::string& path, const CsvSchema& schema) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError({path, 0, ""}, "file not found");
  if (fs::is_directory(path, ec)) throw InputError({path, 0, ""}, "is a directory, not a CSV file");
  // A named pipe or device would block the read (or never end): refuse it.
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec)) {
    throw InputError({path, 0, ""}, "is not a regular file (a pipe or device?)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, ""}, "cannot open file for reading");

  CsvTable table;
  table.path_ = path;
  std::string raw;
  int line_no = 0;
  bool header_seen = false;
  std::vector<std::string> extra_text;  // header names accepted by schema.accept_text_column
  while (std::getline(in, raw)) {
    ++line_no;
    if (line_no == 1 && raw.size() >= 3 && raw.compare(0, 3, "\xEF\xBB\xBF") == 0) raw.erase(0, 3);
    const std::string line = trim(raw);
    if (line.empty() || line[0] == '#') continue;
    for (unsigned char c : line) {
      if (c < 0x20 && c != '\t') {
        throw InputError({path, line_no, ""}, "contains control or binary bytes; not a text CSV");
      }
    }
    const auto fields = split(line);
    if (!header_seen) {
      header_seen = true;
      for (const auto& name : fields) {
        if (name.empty()) throw InputError({path, line_no, ""}, "empty column name in header");
        const bool extra = schema.accept_text_column && schema.accept_text_column(name);
        if (extra) extra_text.push_back(name);
        if (!extra && !contains(schema.required, name) && !contains(schema.optional, name)) {
          std::string known;
          for (const auto& k : schema.required) known += (known.empty() ? "" : ", ") + k;
          for (const auto& k : schema.optional) known += ", " + k + " (optional)";
          throw InputError({path, line_no, name}, "unknown column; expected: " + known);
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
    if (fields.size() != table.columns_.size()) {
      throw InputError({path, line_no, ""}, "has " + std::to_string(fields.size()) +
                                                " fields, header has " +
                                                std::to_string(table.columns_.size()));
    }
    if (table.cells_.size() >= schema.max_rows) {
      throw InputError({path, line_no, ""},
                       "more than " + std::to_string(schema.max_rows) + " data rows; refusing");
    }
    std::vector<double> nums(fields.size(), 0.0);
    for (std::size_t c = 0; c < fields.size(); ++c) {
      if (fields[c].empty() && contains(schema.may_be_empty, table.columns_[c])) {
        nums[c] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
      if (contains(schema.text, table.columns_[c]) || contains(extra_text, table.columns_[c])) {
        if (fields[c].empty()) throw InputError({path, line_no, table.columns_[c]}, "empty cell");
        continue;
      }
      const auto v = parse_finite_double(fields[c]);
      if (!v) {
        throw InputError({path, line_no, table.columns_[c]},
                         "'" + fields[c] + "' is not a finite number");
      }
      nums[c] = *v;
    }
    table.cells_.push_back(fields);
    table.numbers_.push_back(std::move(nums));
    table.lines_.push_back(line_no);
  }
  if (!header_seen) throw InputError({path, 0, ""}, "file is empty (no header line)");
  if (table.cells_.empty()) throw InputError({path, 0, ""}, "has a header but no data rows");
  return table;
}

}  // namespace modaltyre
