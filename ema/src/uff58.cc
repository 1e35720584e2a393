#include "modaltyre/ema/uff58.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <sstream>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"
#include "modaltyre/core/input_file.h"
#include "modaltyre/ema/uff_geometry.h"

namespace modaltyre::ema {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> tokens(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

std::string column(const std::string& line, std::size_t start, std::size_t width) {
  return start < line.size() ? line.substr(start, width) : std::string();
}

std::optional<long> parse_int(const std::string& text) {
  const std::string t = trim(text);
  if (t.empty() || t.size() > 12) return std::nullopt;
  std::size_t i = (t[0] == '-' || t[0] == '+') ? 1 : 0;
  if (i == t.size()) return std::nullopt;
  for (std::size_t k = i; k < t.size(); ++k) {
    if (t[k] < '0' || t[k] > '9') return std::nullopt;
  }
  return std::stol(t);
}

// Fortran writers may use a 'D' exponent (1.0D+00).
std::optional<double> parse_real(const std::string& text) {
  std::string t = trim(text);
  for (char& c : t) {
    if (c == 'D' || c == 'd') c = 'E';
  }
  return parse_finite_double(t);
}

struct Header {  // records 6-10 of one dataset 58
  long function_type = 0;
  RawDof response, reference;  // as the file states them (mapped once the whole file is read)
  long ordinate_type = 0;      // 2 real single, 4 real double, 5 complex single, 6 complex double
  long points = 0;
  bool even = true;
  double x_min = 0, x_inc = 0;
  std::optional<FrfType> type;
  int line = 0;  // line of the "58" header
};

class Reader {
 public:
  Reader(std::string path, const FrfLimits& limits) : path_(std::move(path)), limits_(limits) {}

  FrfSet read() {
    load();
    FrfSet set;
    set.path = path_;
    std::optional<FrfType> type;
    int type_line = 0;
    std::size_t skipped = 0;
    std::string line;
    while (next_line(line)) {
      if (trim(line).empty()) continue;
      if (trim(line) != "-1") fail(line_, "", "expected '    -1' that starts a dataset");
      const int start = line_;
      if (!next_line(line)) fail(start, "", "dataset starts at the end of the file");
      const auto t = tokens(line);
      const std::string id = t.empty() ? "" : t[0];
      if (id == "15" || id == "2411" || id == "2420") {
        const UffDatasetLines d = dataset_lines(start, id);
        if (id == "2420") {
          read_uff_coordinate_systems(d, geometry_);
        } else {
          read_uff_nodes(d, id == "2411", geometry_);
        }
        continue;
      }
      if (id != "58" && id != "58b") {
        skip_dataset(start, id);
        continue;
      }
      std::optional<FrfChannel> ch = read_dataset58(id == "58b", line, set, type, type_line);
      if (!ch) {
        ++skipped;
        continue;
      }
      if (set.channels.size() >= limits_.max_channels) {
        fail(start, "", "more than " + std::to_string(limits_.max_channels) + " FRFs; refusing");
      }
      set.channels.push_back(std::move(*ch));
      raw_.push_back(last_response_);
      raw_.push_back(last_reference_);
    }
    if (set.channels.empty()) {
      fail(0, "",
           "contains no frequency response function (dataset 58 with function type 4)" +
               (skipped ? "; " + std::to_string(skipped) + " other datasets 58 were skipped"
                        : std::string()));
    }
    set.type = type.value_or(FrfType::accelerance);
    set.type_from_file = type.has_value();
    map_directions(set);
    check_frf_set(set, limits_);
    return set;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& field, const std::string& message) const {
    throw InputError({path_, line, field}, message);
  }

  void load() {
    text_ = read_input_file(path_, "a UFF file", "UFF files", limits_.max_bytes);
    // A UTF-8 byte-order mark (a Windows editor's save) before the first "-1": not data.
    if (text_.rfind("\xEF\xBB\xBF", 0) == 0) text_.erase(0, 3);
  }

  bool next_line(std::string& out) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    out = text_.substr(pos_, end - pos_);
    if (!out.empty() && out.back() == '\r') out.pop_back();
    pos_ = std::min(end + 1, text_.size());  // a last line without '\n' must not step past the end
    ++line_;
    return true;
  }

  // The DOFs as tyre DOFs: through the file's geometry when it has one (uff_geometry.h), else
  // by the implied convention (+-3 radial, +-1 tangential in each point's local frame). A
  // negative direction flips the FRF's sign (both negative cancel).
  void map_directions(FrfSet& set) const {
    MappedDofs m;
    if (!geometry_.nodes.empty()) {
      m = map_dofs(path_, geometry_, raw_);
      set.point_angle_deg = m.angle_deg;
    } else {
      for (const auto& r : raw_) {
        if (r.direction != 3 && r.direction != -3 && r.direction != 1 && r.direction != -1) {
          fail(r.line, r.direction_field,
               "direction " + std::to_string(r.direction) +
                   " is neither radial (+-3) nor tangential (+-1) in the point's local frame "
                   "(the file has no geometry, datasets 15/2411, to read other directions by)");
        }
        m.dofs.push_back({static_cast<int>(r.node),
                          std::abs(r.direction) == 3 ? Direction::radial : Direction::tangential});
        m.signs.push_back(r.direction > 0 ? 1 : -1);
      }
    }
    for (std::size_t c = 0; c < set.channels.size(); ++c) {
      FrfChannel& ch = set.channels[c];
      ch.response = m.dofs[2 * c];
      ch.reference = m.dofs[2 * c + 1];
      const double sign = m.signs[2 * c] * m.signs[2 * c + 1];
      if (sign < 0) {
        for (auto& v : ch.values) v = -v;
      }
    }
  }

  UffDatasetLines dataset_lines(int start, const std::string& id) {
    UffDatasetLines d{path_, start + 2, {}};
    std::string line;
    while (next_line(line)) {
      if (trim(line) == "-1") return d;
      d.lines.push_back(line);
    }
    fail(start, "", "dataset " + printable(id) + " starting here has no closing '    -1'");
  }

  void skip_dataset(int start, const std::string& id) {
    std::string line;
    while (next_line(line)) {
      if (trim(line) == "-1") return;
    }
    fail(start, "", "dataset " + printable(id) + " starting here has no closing '    -1'");
  }

  std::string record(int start, int number) {
    std::string line;
    if (!next_line(line) || trim(line) == "-1") {
      fail(start, "record " + std::to_string(number),
           "dataset 58 starting here ends before record " + std::to_string(number));
    }
    return line;
  }

  // Record 6: Format(2(I5,I10),2(1X,10A1,I10,I4)); entity names may hold blanks, so the
  // columns come first and blank-separated fields (names without blanks) second.
  void read_record6(const std::string& line, Header& h) {
    const auto func = parse_int(column(line, 0, 5));
    const auto rn = parse_int(column(line, 41, 10)), rd = parse_int(column(line, 51, 4));
    const auto fn = parse_int(column(line, 66, 10)), fd = parse_int(column(line, 76, 4));
    long v[5];
    if (func && rn && rd && fn && fd) {
      const long fixed[5] = {*func, *rn, *rd, *fn, *fd};
      std::copy(fixed, fixed + 5, v);
    } else {
      const auto t = tokens(line);
      const int at[5] = {0, 5, 6, 8, 9};
      for (int k = 0; k < 5; ++k) {
        const auto x = t.size() == 10 ? parse_int(t[at[k]]) : std::nullopt;
        if (!x) {
          fail(line_, "record 6",
               "expected function type, ids, response entity/node/direction and reference "
               "entity/node/direction in the columns of Format(2(I5,I10),2(1X,10A1,I10,I4))");
        }
        v[k] = *x;
      }
    }
    h.function_type = v[0];
    h.response = dof(v[1], v[2], "record 6 field 6 (response node)",
                     "record 6 field 7 (response direction)");
    h.reference = dof(v[3], v[4], "record 6 field 9 (reference node)",
                      "record 6 field 10 (reference direction)");
  }

  RawDof dof(long node, long dir, const std::string& node_field,
             const std::string& dir_field) const {
    if (node < 1 || node > kMaxPointNumber) {
      fail(line_, node_field,
           "node " + std::to_string(node) + " is not a point number from 1 to " +
               std::to_string(kMaxPointNumber));
    }
    if (dir == 0 || dir < -3 || dir > 3) {
      fail(line_, dir_field,
           "direction " + std::to_string(dir) +
               " is not a translation: ema reads radial (+-3) and tangential (+-1) DOFs, or "
               "directions 1-3 of the node's coordinate system when the file has a geometry");
    }
    return {node, dir, line_, node_field, dir_field};
  }

  // Record 7: Format(3I10,3E13.5).
  void read_record7(const std::string& line, Header& h) {
    auto t = tokens(line);
    std::optional<long> type, n, even;
    std::optional<double> x0, dx;
    if (t.size() >= 5) {
      type = parse_int(t[0]), n = parse_int(t[1]), even = parse_int(t[2]);
      x0 = parse_real(t[3]), dx = parse_real(t[4]);
    }
    if (!(type && n && even && x0 && dx)) {
      type = parse_int(column(line, 0, 10)), n = parse_int(column(line, 10, 10));
      even = parse_int(column(line, 20, 10));
      x0 = parse_real(column(line, 30, 13)), dx = parse_real(column(line, 43, 13));
    }
    if (!type || (*type != 2 && *type != 4 && *type != 5 && *type != 6)) {
      fail(line_, "record 7 field 1 (ordinate data type)",
           "must be 2 (real single), 4 (real double), 5 (complex single) or 6 (complex double)");
    }
    if (!n || *n < 2 || *n > static_cast<long>(limits_.max_lines)) {
      fail(line_, "record 7 field 2 (number of values)",
           "must be a whole number from 2 to " + std::to_string(limits_.max_lines));
    }
    if (!even || (*even != 0 && *even != 1)) {
      fail(line_, "record 7 field 3 (abscissa spacing)", "must be 0 (uneven) or 1 (even)");
    }
    if (!x0) fail(line_, "record 7 field 4 (abscissa minimum)", "is not a number");
    if (!dx || (*even == 1 && !(*dx > 0))) {
      fail(line_, "record 7 field 5 (abscissa increment)",
           "must be a number, > 0 for even spacing");
    }
    h.ordinate_type = *type;
    h.points = *n;
    h.even = *even == 1;
    h.x_min = *x0;
    h.x_inc = *dx;
  }

  long data_type(const std::string& line, int number, int at) const {
    auto v = parse_int(column(line, 0, 10));
    if (!v) {
      const auto t = tokens(line);
      if (!t.empty()) v = parse_int(t[0]);
    }
    if (!v) {
      fail(at, "record " + std::to_string(number) + " field 1 (specific data type)",
           "is not a whole number");
    }
    return *v;
  }

  // Records 8-10: abscissa, ordinate numerator and ordinate denominator data types.
  void read_data_types(const std::string& r8, const std::string& r9, const std::string& r10,
                       int first, Header& h) const {
    const long x = data_type(r8, 8, first);
    if (x != 0 && x != 1 && x != 18) {
      fail(first, "record 8 field 1 (abscissa data type)",
           "is " + std::to_string(x) + "; an FRF's abscissa is frequency (18)");
    }
    const long num = data_type(r9, 9, first + 1);
    const long den = data_type(r10, 10, first + 2);
    if (den != 0 && den != 1 && den != 13) {
      fail(first + 2, "record 10 field 1 (ordinate denominator data type)",
           "is " + std::to_string(den) + "; ema reads FRFs per excitation force (13)");
    }
    switch (num) {
      case 12:
        h.type = FrfType::accelerance;
        break;
      case 11:
        h.type = FrfType::mobility;
        break;
      case 8:
        h.type = FrfType::receptance;
        break;
      case 0:
      case 1:
        break;
      default:
        fail(first + 1, "record 9 field 1 (ordinate numerator data type)",
             "is " + std::to_string(num) +
                 "; expected acceleration (12), velocity (11) or displacement (8)");
    }
  }

  std::size_t value_count(const Header& h) const {
    const bool cplx = h.ordinate_type >= 5;
    return static_cast<std::size_t>(h.points) * ((cplx ? 2 : 1) + (h.even ? 0 : 1));
  }

  // Width of value k of record 12 in the specification's columns.
  static int width(const Header& h, std::size_t k) {
    if (h.ordinate_type == 2 || h.ordinate_type == 5) return 13;  // 6E13.5
    if (h.even) return 20;                                        // 4E20.12
    const std::size_t per = h.ordinate_type == 6 ? 3 : 2;         // E13.5,2E20.12 / 2(E13.5,E20.12)
    return k % per == 0 ? 13 : 20;
  }

  std::vector<double> read_ascii_values(const Header& h, int start) {
    const std::size_t n = value_count(h);
    std::vector<double> v;
    v.reserve(n);
    std::string line;
    while (v.size() < n) {
      if (!next_line(line) || trim(line) == "-1") {
        fail(line_, "record 12",
             "has " + std::to_string(v.size()) + " values; record 7 (line " +
                 std::to_string(start + 7) + ") promises " + std::to_string(n));
      }
      std::vector<double> got;
      bool ok = true;
      for (const auto& t : tokens(line)) {  // blank-separated first, then the columns
        const auto x = parse_real(t);
        ok = ok && x.has_value();
        if (ok) got.push_back(*x);
      }
      if (!ok) {
        got.clear();
        const std::string body = line.substr(0, line.find_last_not_of(" \t") + 1);
        for (std::size_t off = 0, k = v.size(); off < body.size(); ++k) {
          const int w = width(h, k);
          const auto x = parse_real(body.substr(off, w));
          if (!x) {
            fail(line_, "record 12 value " + std::to_string(k + 1),
                 "'" + printable(trim(body.substr(off, w))) + "' is not a number");
          }
          got.push_back(*x);
          off += w;
        }
      }
      if (v.size() + got.size() > n) {
        fail(line_, "record 12",
             "has more values than the " + std::to_string(n) + " record 7 promises");
      }
      v.insert(v.end(), got.begin(), got.end());
    }
    if (!next_line(line) || trim(line) != "-1") {
      fail(line_, "record 12", "expected '    -1' after the " + std::to_string(n) + " values");
    }
    return v;
  }

  std::vector<double> read_binary_values(const Header& h, bool little, int start) {
    const bool single = h.ordinate_type == 2 || h.ordinate_type == 5;
    const std::size_t n = value_count(h), size = single ? 4 : 8;
    const std::size_t left = text_.size() - pos_;  // pos_ <= size: next_line clamps it
    if (n > left / size) {
      fail(start, "record 12 (binary)",
           "the file ends after " + std::to_string(left) + " bytes of the " +
               std::to_string(n * size) + " that record 7 promises");
    }
    std::vector<double> v(n);
    const bool swap = little != (std::endian::native == std::endian::little);
    for (std::size_t i = 0; i < n; ++i) {
      unsigned char b[8];
      std::memcpy(b, text_.data() + pos_ + i * size, size);
      if (swap) std::reverse(b, b + size);
      if (single) {
        float f;
        std::memcpy(&f, b, 4);
        v[i] = f;
      } else {
        std::memcpy(&v[i], b, 8);
      }
      if (!std::isfinite(v[i])) {
        fail(start, "record 12 (binary) value " + std::to_string(i + 1), "is not finite");
      }
    }
    // Keep the line count of a text editor across the binary block.
    for (std::size_t i = 0; i < n * size; ++i) line_ += text_[pos_ + i] == '\n';
    pos_ += n * size;
    std::string line;
    if (next_line(line) && trim(line).empty()) next_line(line);  // writers differ here
    if (trim(line) != "-1") {
      fail(line_, "record 12 (binary)",
           "expected '    -1' after the " + std::to_string(n * size) + " data bytes");
    }
    return v;
  }

  std::optional<FrfChannel> read_dataset58(bool binary, const std::string& id_line, FrfSet& set,
                                           std::optional<FrfType>& type, int& type_line) {
    const int start = line_;
    bool little = true;
    if (binary) {
      // "58b" then byte order (1 little, 2 big), floating-point format (2 IEEE 754), ASCII
      // lines that follow (11) and the byte count (not trusted: taken from record 7).
      const auto t = tokens(id_line.substr(id_line.find('b') + 1));
      const auto order = t.size() >= 3 ? parse_int(t[0]) : std::nullopt;
      const auto fp = t.size() >= 3 ? parse_int(t[1]) : std::nullopt;
      const auto ascii = t.size() >= 3 ? parse_int(t[2]) : std::nullopt;
      if (!order || (*order != 1 && *order != 2)) {
        fail(start, "58b field 1 (byte order)", "must be 1 (little endian) or 2 (big endian)");
      }
      if (!fp || *fp != 2)
        fail(start, "58b field 2 (floating-point format)", "must be 2 (IEEE 754)");
      if (!ascii || *ascii != 11) fail(start, "58b field 3 (ASCII lines)", "must be 11");
      little = *order == 1;
    }
    Header h;
    h.line = start;
    for (int r = 1; r <= 5; ++r) record(start, r);  // ID lines
    read_record6(record(start, 6), h);
    read_record7(record(start, 7), h);
    const int first = line_ + 1;
    const std::string r8 = record(start, 8), r9 = record(start, 9), r10 = record(start, 10);
    read_data_types(r8, r9, r10, first, h);
    record(start, 11);
    const auto v = binary ? read_binary_values(h, little, start) : read_ascii_values(h, start);
    if (h.function_type != 4) return std::nullopt;

    if (h.type) {
      if (type && *type != *h.type) {
        fail(first + 1, "record 9 field 1 (ordinate numerator data type)",
             std::string("this FRF is ") + to_string(*h.type) + ", the one at line " +
                 std::to_string(type_line) + " is " + to_string(*type));
      }
      type = h.type;
      type_line = first + 1;
    }
    const bool cplx = h.ordinate_type >= 5;
    const std::size_t stride = (cplx ? 2 : 1) + (h.even ? 0 : 1);
    last_response_ = h.response;
    last_reference_ = h.reference;
    FrfChannel ch{{}, {}, {}, start};
    std::vector<double> freq(h.points);
    ch.values.resize(h.points);
    for (long i = 0; i < h.points; ++i) {
      const double* p = v.data() + i * stride;
      freq[i] = h.even ? h.x_min + static_cast<double>(i) * h.x_inc : p[0];
      const double* y = h.even ? p : p + 1;
      ch.values[i] = std::complex<double>(y[0], cplx ? y[1] : 0.0);
    }
    if (set.channels.empty()) {
      set.freq_hz = freq;
    } else if (freq.size() != set.freq_hz.size()) {
      fail(start + 7, "record 7 field 2 (number of values)",
           std::to_string(freq.size()) + " lines; the first FRF (line " +
               std::to_string(set.channels.front().line) + ") has " +
               std::to_string(set.freq_hz.size()));
    } else {
      for (std::size_t i = 0; i < freq.size(); ++i) {
        if (std::abs(freq[i] - set.freq_hz[i]) > 1e-6 * std::abs(set.freq_hz[i]) + 1e-9) {
          fail(start + 7, "record 7 (abscissa)",
               "line " + std::to_string(i + 1) + " is at " + std::to_string(freq[i]) +
                   " Hz, the first FRF has " + std::to_string(set.freq_hz[i]) +
                   " Hz; every FRF needs the same frequencies");
        }
      }
    }
    return ch;
  }

  std::string path_;
  FrfLimits limits_;
  UffGeometry geometry_;
  std::vector<RawDof> raw_;  // response, reference of each channel in turn
  RawDof last_response_, last_reference_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

}  // namespace

FrfSet read_uff58(const std::string& path, const FrfLimits& limits) {
  return Reader(path, limits).read();
}

}  // namespace modaltyre::ema
