// The .tir reader (tir_file.h): one pass over the lines, every refusal naming file, line and key.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/input_file.h"
#include "modaltyre/tir/tir_file.h"

namespace modaltyre::tir {
namespace {

std::string trim(const std::string& s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f'; };
  std::size_t b = 0, e = s.size();
  while (b < e && blank(s[b])) ++b;
  while (e > b && blank(s[e - 1])) --e;
  return s.substr(b, e - b);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool is_name(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

// A number as .tir writers spell it: C syntax or a Fortran double ("1.5D+03"). nullopt for
// anything else; `non_finite` is set for a number that overflows or is written inf/nan.
std::optional<double> parse_number(const std::string& text, bool* non_finite = nullptr) {
  std::string t = text;
  const std::size_t d = t.find_first_of("Dd");
  if (d != std::string::npos && d > 0 && std::isdigit(static_cast<unsigned char>(t[d - 1])) &&
      d + 1 < t.size()) {
    t[d] = 'e';
  }
  if (auto v = parse_finite_double(t)) return v;
  if (non_finite) {
    char* end = nullptr;
    const double v = std::strtod(t.c_str(), &end);
    *non_finite = !t.empty() && end == t.c_str() + t.size() && !std::isfinite(v);
  }
  return std::nullopt;
}

// Splits off a comment ('$' or '!' outside quotes); returns the content before it.
std::string strip_comment(const std::string& line, std::string* comment) {
  char quote = 0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '\'' || c == '"') {
      quote = c;
    } else if (c == '$' || c == '!') {
      *comment = line.substr(i + 1);
      return line.substr(0, i);
    }
  }
  return line;
}

constexpr std::size_t kMaxNotes = 100;

class Parser {
 public:
  Parser(const std::string& name, const TirLimits& limits) : limits_(limits) { file_.path = name; }

  void line(std::string raw, int no) {
    no_ = no;
    const std::size_t cr = raw.find('\r');
    if (cr != std::string::npos && cr + 1 < raw.size()) {
      fail("",
           "a carriage return ends a line on its own (old Mac line ends?): save the file with "
           "LF or CRLF line ends");
    }
    if (raw.size() > limits_.max_line_bytes) {
      fail("", "line of " + std::to_string(raw.size()) + " bytes; refusing lines over " +
                   std::to_string(limits_.max_line_bytes) + " bytes (is it a .tir file?)");
    }
    if (raw.find('\0') != std::string::npos) fail("", "contains a NUL byte: not a text file");
    if (no == 1 && raw.rfind("\xEF\xBB\xBF", 0) == 0) raw.erase(0, 3);
    std::string comment;
    const std::string content = trim(strip_comment(raw, &comment));
    // Comments may carry a writer's Latin-1 (a degree sign): they are kept, never interpreted.
    if (!valid_utf8(content)) {
      const std::size_t eq = content.find('=');
      const std::string key = eq == std::string::npos ? "" : upper(trim(content.substr(0, eq)));
      fail(is_name(key) ? dotted(key) : "",
           "'" + printable(content) +
               "' has bytes that are not UTF-8 (a Latin-1 or Windows-1252 file?): save the file "
               "as UTF-8");
    }
    if (!comment.empty() && file_.comments.size() < 1000) file_.comments.push_back(comment);
    if (content.empty()) return;
    if (content[0] == '[') return section_header(content);
    if (content[0] == '{') return table_header(content);
    if (content.find('=') != std::string::npos) return entry(content);
    table_row(content);
  }

  TirFile take() { return std::move(file_); }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError({file_.path, no_, key}, message);
  }
  std::string dotted(const std::string& key) const {
    return file_.sections.empty() ? key : file_.sections.back().name + "." + key;
  }
  TirSection& current(const std::string& what) {
    if (file_.sections.empty()) fail("", what + " before the first [SECTION] header");
    return file_.sections.back();
  }

  void section_header(const std::string& content) {
    if (content.back() != ']') fail("", "section header '" + printable(content) + "' lacks ']'");
    const std::string name = upper(trim(content.substr(1, content.size() - 2)));
    if (!is_name(name)) {
      fail("", "'" + printable(content) + "' is not a section name (letters, digits, '_')");
    }
    // A section given twice is compared with its first when the file is read (same_contents).
    if (file_.sections.size() >= limits_.max_sections) {
      fail(name, "more than " + std::to_string(limits_.max_sections) + " sections");
    }
    file_.sections.push_back({name, no_, {}, {}});
  }

  void table_header(const std::string& content) {
    TirSection& s = current("a {...} table header");
    if (content.back() != '}') fail(s.name, "table header '" + printable(content) + "' lacks '}'");
    if (!s.table.columns.empty() || !s.table.rows.empty()) {
      fail(s.name, "a second table header in [" + s.name + "]");
    }
    std::istringstream words(content.substr(1, content.size() - 2));
    for (std::string w; words >> w;) {
      if (!is_name(w)) fail(s.name, "table column '" + printable(w) + "' is not a name");
      if (s.table.columns.size() >= limits_.max_table_columns) {
        fail(s.name, "more than " + std::to_string(limits_.max_table_columns) + " columns");
      }
      s.table.columns.push_back(upper(w));
    }
    if (s.table.columns.empty()) fail(s.name, "empty table header {}");
    s.table.header_line = no_;
  }

  void entry(const std::string& content) {
    const std::size_t eq = content.find('=');
    const std::string key = upper(trim(content.substr(0, eq)));
    if (!is_name(key)) {
      fail("", "'" + printable(content) + "' is not KEY = value (a key is letters, digits, '_')");
    }
    TirSection& s = current("key " + key);
    if (s.entries.count(key)) {
      fail(dotted(key), "key given twice in [" + s.name + "] (first on line " +
                            std::to_string(s.entries.at(key).line) + ")");
    }
    if (++entries_ > limits_.max_entries) {
      fail(dotted(key), "more than " + std::to_string(limits_.max_entries) + " keys");
    }
    s.entries[key] = value(trim(content.substr(eq + 1)), dotted(key));
  }

  TirValue value(const std::string& v, const std::string& key) const {
    TirValue out;
    out.line = no_;
    if (v.empty()) return out;  // `KEY =`: written for a parameter that is not set
    if (v[0] == '\'' || v[0] == '"') {
      const std::size_t close = v.find(v[0], 1);
      if (close == std::string::npos) fail(key, "unterminated quoted string");
      if (close + 1 != v.size()) {
        fail(key, "text after the closing quote: '" + printable(v.substr(close + 1)) + "'");
      }
      out.text = v.substr(1, close - 1);
      out.quoted = true;
      return out;
    }
    bool non_finite = false;
    out.text = v;
    out.number = parse_number(v, &non_finite);
    if (non_finite) fail(key, "'" + printable(v) + "' is not a finite number");
    if (!out.number && v.find_first_of(" \t=") != std::string::npos) {
      fail(key, "'" + printable(v) + "' is neither a number nor one word (quote text values)");
    }
    return out;
  }

  void table_row(const std::string& content) {
    std::vector<double> row;
    std::istringstream words(content);
    for (std::string w; words >> w;) {
      bool non_finite = false;
      const auto v = parse_number(w, &non_finite);
      if (!v) {
        fail(file_.sections.empty() ? "" : file_.sections.back().name,
             non_finite ? "'" + printable(w) + "' is not a finite number"
                        : "'" + printable(content) +
                              "' is not KEY = value, a [SECTION], a {...} table header or a "
                              "row of numbers");
      }
      row.push_back(*v);
      if (row.size() > limits_.max_table_columns) {
        fail("",
             "table row of more than " + std::to_string(limits_.max_table_columns) + " numbers");
      }
    }
    TirSection& s = current("a table row");
    TirTable& t = s.table;
    const std::size_t want = !t.columns.empty() ? t.columns.size()
                             : t.rows.empty()   ? row.size()
                                                : t.rows.front().size();
    if (row.size() != want) {
      fail(s.name, "table row of " + std::to_string(row.size()) + " numbers; [" + s.name +
                       "] has " + std::to_string(want) + " columns");
    }
    if (++rows_ > limits_.max_table_rows) {
      fail(s.name, "more than " + std::to_string(limits_.max_table_rows) + " table rows");
    }
    t.rows.push_back(std::move(row));
    t.row_lines.push_back(no_);
  }

  TirLimits limits_;
  TirFile file_;
  int no_ = 0;
  std::size_t entries_ = 0, rows_ = 0;
};

bool same_contents(const TirSection& a, const TirSection& b) {
  if (a.entries.size() != b.entries.size()) return false;
  for (const auto& [key, value] : a.entries) {
    const auto it = b.entries.find(key);
    if (it == b.entries.end() || it->second.text != value.text ||
        it->second.quoted != value.quoted) {
      return false;
    }
  }
  return a.table.columns == b.table.columns && a.table.rows == b.table.rows;
}

// A section given twice: a verbatim repeat is harmless (noted, the first is used); a repeat
// with other contents states two values for one parameter, which simulators resolve
// differently (Project Chrono's reader takes the first by a search from the top, a reader that
// overwrites takes the last): refused, as a key given twice is (issue 38).
void check_repeated_sections(TirFile& file) {
  for (std::size_t i = 0; i < file.sections.size(); ++i) {
    const TirSection& again = file.sections[i];
    for (std::size_t j = 0; j < i; ++j) {
      const TirSection& first = file.sections[j];
      if (first.name != again.name) continue;
      if (!same_contents(first, again)) {
        throw InputError({file.path, again.line, again.name},
                         "section [" + again.name +
                             "] given again with other contents (first on "
                             "line " +
                             std::to_string(first.line) +
                             "): which one a simulator uses depends on its reader; delete the "
                             "one that does not hold your tyre's values");
      }
      if (file.notes.size() < kMaxNotes) {
        file.notes.push_back(file.path + ":" + std::to_string(again.line) + ": section [" +
                             again.name + "] given again (first on line " +
                             std::to_string(first.line) + ") with the same contents");
      }
      break;
    }
  }
}

}  // namespace

const TirSection* TirFile::section(const std::string& name) const {
  for (const auto& s : sections) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

const TirValue* TirFile::value(const std::string& section_name, const std::string& key) const {
  const TirSection* s = section(section_name);
  if (!s) return nullptr;
  const auto it = s->entries.find(key);
  // `KEY =` is a parameter the writer left unset: the same as no key for whoever asks for it.
  if (it == s->entries.end() || (it->second.text.empty() && !it->second.quoted)) return nullptr;
  return &it->second;
}

TirFile parse_tir(const std::string& text, const std::string& name, const TirLimits& limits) {
  if (text.size() > limits.max_bytes) {
    throw InputError({name, 0, ""}, "is " + std::to_string(text.size() >> 20) +
                                        " MB; refusing .tir files over " +
                                        std::to_string(limits.max_bytes >> 20) + " MB");
  }
  Parser parser(name, limits);
  std::size_t pos = 0;
  int no = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    parser.line(text.substr(pos, end - pos), ++no);
    pos = end + 1;
  }
  TirFile file = parser.take();
  if (file.sections.empty()) {
    throw InputError({name, 0, ""}, "no [SECTION] header: not a .tir property file");
  }
  check_repeated_sections(file);
  return file;
}

TirFile read_tir(const std::string& path, const TirLimits& limits) {
  return parse_tir(read_input_file(path, "a .tir file", ".tir files", limits.max_bytes), path,
                   limits);
}

}  // namespace modaltyre::tir
