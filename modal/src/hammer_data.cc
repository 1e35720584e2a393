#include "modaltyre/modal/hammer_data.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>

#include "modaltyre/core/csv.h"
#include "modaltyre/core/errors.h"

namespace modaltyre::modal {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Angles are typed by hand in degrees; 1 % of the spacing separates a rounding from a misplacement.
constexpr double kSpacingTolerance = 0.01;
constexpr double kMaxShape = 1e6;  // kg^-1/2
constexpr double kMaxFrequency_Hz = 1e5;

int as_index(const CsvTable& t, std::size_t row, const std::string& col) {
  const double v = t.number(row, col);
  if (v != std::floor(v) || v < 1 || v > 1e6) {
    throw InputError({t.path(), t.line(row), col}, "must be a positive whole number");
  }
  return static_cast<int>(v);
}

using PointLines = std::map<std::pair<int, int>, int>;  // (mode, point) -> line

std::set<int> points_of(const PointLines& seen, int mode) {
  std::set<int> out;
  for (const auto& [key, line] : seen) {
    if (key.first == mode) out.insert(key.second);
  }
  return out;
}

// ": point 7 is missing (mode 1 has it on line 8)" when `mode` lacks points `reference` has,
// or the other way round; empty when the point numbers do not tell.
std::string missing_rows(const PointLines& seen, int mode, int reference) {
  const std::set<int> mine = points_of(seen, mode), theirs = points_of(seen, reference);
  std::string out;
  for (int p : theirs) {
    if (mine.count(p)) continue;
    out += (out.empty() ? ": point " : ", point ") + std::to_string(p) + " is missing (mode " +
           std::to_string(reference) + " has it on line " +
           std::to_string(seen.at({reference, p})) + ")";
  }
  for (int p : mine) {
    if (theirs.count(p)) continue;
    out += (out.empty() ? ": mode " : ", mode ") + std::to_string(reference) + " lacks point " +
           std::to_string(p) + " (line " + std::to_string(seen.at({mode, p})) + ")";
  }
  return out;
}

// A row left out of an equally spaced set shows as gaps that are whole multiples of the
// smallest one: ": no point at 300 deg (point 11?) - the others are 30 deg apart, 12 expected,
// 11 given". Empty when the gaps do not look like that.
std::string missing_angles(const std::vector<double>& sorted, const PointLines& seen, int mode) {
  const int n = static_cast<int>(sorted.size());
  std::vector<double> gaps(n);
  for (int i = 0; i < n; ++i) {
    gaps[i] = (i + 1 < n ? sorted[i + 1] : sorted[0] + 2 * kPi) - sorted[i];
  }
  const double base = *std::min_element(gaps.begin(), gaps.end());
  if (!(base > 1e-9)) return "";
  const long expected = std::lround(2 * kPi / base);
  if (expected <= n || std::abs(expected * base - 2 * kPi) > kSpacingTolerance * base) return "";
  std::vector<double> holes;
  for (int i = 0; i < n; ++i) {
    const long k = std::lround(gaps[i] / base);
    if (k < 1 || std::abs(gaps[i] - k * base) > kSpacingTolerance * base) return "";
    for (long j = 1; j < k; ++j) holes.push_back(std::fmod(sorted[i] + j * base, 2 * kPi));
  }
  std::ostringstream s;
  s.precision(4);
  s << ": no point at";
  for (std::size_t h = 0; h < holes.size(); ++h) s << (h ? ", " : " ") << holes[h] * 180 / kPi;
  s << " deg";
  // Points numbered 1..expected: name the numbers that are not there.
  const std::set<int> ids = points_of(seen, mode);
  if (!ids.empty() && *ids.begin() >= 1 && *ids.rbegin() <= expected) {
    std::string numbers;
    for (int p = 1; p <= expected; ++p) {
      if (!ids.count(p)) numbers += (numbers.empty() ? "" : ", ") + std::to_string(p);
    }
    s << " (point " << numbers << "?)";
  }
  s << " - the others are " << base * 180 / kPi << " deg apart: " << expected
    << " points expected, " << n << " given (a row left out?)";
  return s.str();
}

}  // namespace

HammerData read_hammer_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"mode",      "freq_hz", "damping_ratio", "point",
                     "angle_deg", "radial",  "tangential"};
  schema.optional = {"scaling", "freq_std_hz", "damping_std", "radial_std", "tangential_std"};
  schema.text = {"scaling"};
  // A std cell is empty where `ema` measured no FRF (the value's cell is empty too) or where a
  // value was typed by hand: read as 0, no estimate.
  schema.may_be_empty = {"radial", "tangential", "radial_std", "tangential_std"};
  // The hammer test's FRFs (a UFF file starts with "-1"; the long FRF CSV with response_point)
  // are the input of `ema`, not of the model (issue 38: "unknown column -1").
  const auto header = read_csv_header(path);
  if (!header.empty() && (header.front() == "-1" || header.front() == "response_point")) {
    throw InputError({path, 1, ""},
                     std::string("is ") +
                         (header.front() == "-1" ? "a UFF file" : "a CSV of FRFs") +
                         " (the hammer test's FRFs), not the hammer CSV of modes: identify the "
                         "modes first with `modaltyre ema " +
                         path + " --output hammer.csv` and give hammer.csv");
  }
  const CsvTable t = read_csv(path, schema);

  HammerData data;
  data.path = path;
  // The standard deviations `ema` writes (docs/uncertainty.md section 5): all four or none.
  const char* std_cols[] = {"freq_std_hz", "damping_std", "radial_std", "tangential_std"};
  int std_count = 0;
  for (const char* col : std_cols) std_count += t.has(col) ? 1 : 0;
  if (std_count != 0 && std_count != 4) {
    std::string have;
    for (const char* col : std_cols) have += t.has(col) ? std::string(" ") + col : "";
    throw InputError({path, 1, ""},
                     "the standard-deviation columns come as four "
                     "(freq_std_hz, damping_std, radial_std, tangential_std); "
                     "the header has only" +
                         have);
  }
  data.has_std = std_count == 4;
  std::map<int, std::size_t> index;  // mode id -> position in data.modes
  PointLines seen_point;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const int line = t.line(r);
    const int id = as_index(t, r, "mode");
    const int point = as_index(t, r, "point");
    const double f = t.number(r, "freq_hz");
    const double z = t.number(r, "damping_ratio");
    // A tyre's structural modes lie below a few kHz; 100 kHz is a unit error (and its squared
    // circular frequency would overflow the carcass kernel long before 1e308 Hz).
    if (!(f > 0 && f <= kMaxFrequency_Hz)) {
      throw InputError({path, line, "freq_hz"}, "frequency must be in (0, 1e5] Hz");
    }
    if (z < 0 || z >= 1) {
      throw InputError({path, line, "damping_ratio"},
                       "damping ratio must be in [0, 1) (a fraction, not a percentage)");
    }
    if (auto it = seen_point.find({id, point}); it != seen_point.end()) {
      throw InputError({path, line, "point"}, "duplicate point " + std::to_string(point) +
                                                  " of mode " + std::to_string(id) +
                                                  " (first at line " + std::to_string(it->second) +
                                                  ")");
    }
    seen_point[{id, point}] = line;
    auto [it, inserted] = index.try_emplace(id, data.modes.size());
    if (inserted) {
      MeasuredMode m;
      m.id = id;
      m.freq_hz = f;
      m.damping_ratio = z;
      m.first_line = line;
      data.modes.push_back(m);
    }
    MeasuredMode& m = data.modes[it->second];
    if (data.has_std) {
      const auto cell = [&](const char* col) { return t.missing(r, col) ? 0.0 : t.number(r, col); };
      for (const char* col : std_cols) {
        const double v = cell(col);
        if (!(v >= 0 && v <= (col[0] == 'f' ? kMaxFrequency_Hz : kMaxShape))) {
          throw InputError({path, line, col}, "a standard deviation must be >= 0 and finite");
        }
      }
      if (inserted) {
        m.freq_std_hz = t.number(r, "freq_std_hz");
        m.damping_std = t.number(r, "damping_std");
      } else if (m.freq_std_hz != t.number(r, "freq_std_hz") ||
                 m.damping_std != t.number(r, "damping_std")) {
        throw InputError({path, line, "freq_std_hz"},
                         "mode " + std::to_string(id) +
                             " has a different freq_std_hz or damping_std than on line " +
                             std::to_string(m.first_line));
      }
      m.radial_std.push_back(cell("radial_std"));
      m.tangential_std.push_back(cell("tangential_std"));
    }
    if (std::abs(m.freq_hz - f) > 1e-9 * f || std::abs(m.damping_ratio - z) > 1e-12) {
      throw InputError({path, line, "freq_hz"},
                       "mode " + std::to_string(id) +
                           " has a different frequency or damping than on line " +
                           std::to_string(m.first_line));
    }
    double a = std::fmod(t.number(r, "angle_deg"), 360.0);
    if (a < 0) a += 360.0;
    m.angle_rad.push_back(a * kPi / 180.0);
    // Mass-normalised shapes are of order 1 kg^-1/2; far beyond, their squares in the harmonic
    // fits overflow (NaN in the output) instead of the reader naming the cell.
    for (const char* col : {"radial", "tangential"}) {
      if (t.text(r, col).empty()) {
        throw InputError({path, line, col},
                         "empty cell: '' is not a finite number; the hammer test measured no "
                         "FRF at point " +
                             std::to_string(point) +
                             " in this direction (modaltyre ema leaves "
                             "such a DOF out of the shape); fit-modes and the tyre model need "
                             "a value at every point: measure it, or write 0 if you know the "
                             "point does not move this way");
      }
      if (!(std::abs(t.number(r, col)) <= kMaxShape)) {
        throw InputError({path, line, col},
                         "shape value must be within +-1e6 kg^-1/2 "
                         "(mass-normalised shapes are of order 1)");
      }
    }
    m.radial.push_back(t.number(r, "radial"));
    m.tangential.push_back(t.number(r, "tangential"));
    // The scaling marker of `ema --unscaled` (one word for the whole file).
    const bool unscaled_row = t.has("scaling") && t.text(r, "scaling") == "unscaled";
    if (t.has("scaling") && !unscaled_row && t.text(r, "scaling") != "mass_normalised") {
      throw InputError({path, line, "scaling"}, "'" + printable(t.text(r, "scaling")) +
                                                    "' is neither mass_normalised nor unscaled");
    }
    if (r > 0 && unscaled_row != data.unscaled) {
      throw InputError({path, line, "scaling"},
                       "differs from the first row's: one file holds one scaling");
    }
    data.unscaled = unscaled_row;
  }

  for (auto& m : data.modes) {
    const int n = static_cast<int>(m.angle_rad.size());
    const std::string who = "mode " + std::to_string(m.id);
    if (n < kMinHammerPoints) {
      throw InputError({path, m.first_line, "point"},
                       who + " has " + std::to_string(n) + " points; at least " +
                           std::to_string(kMinHammerPoints) + " are needed");
    }
    if (data.points == 0) data.points = n;
    if (n != data.points) {
      const int first = data.modes.front().id;
      throw InputError({path, m.first_line, "point"}, who + " has " + std::to_string(n) +
                                                          " points, mode " + std::to_string(first) +
                                                          " has " + std::to_string(data.points) +
                                                          "; every mode needs the same points" +
                                                          missing_rows(seen_point, m.id, first));
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return m.angle_rad[a] < m.angle_rad[b]; });
    MeasuredMode sorted = m;
    for (int i = 0; i < n; ++i) {
      sorted.angle_rad[i] = m.angle_rad[order[i]];
      sorted.radial[i] = m.radial[order[i]];
      sorted.tangential[i] = m.tangential[order[i]];
      if (data.has_std) {
        sorted.radial_std[i] = m.radial_std[order[i]];
        sorted.tangential_std[i] = m.tangential_std[order[i]];
      }
    }
    const double spacing = 2 * kPi / n;
    const std::string missing = missing_angles(sorted.angle_rad, seen_point, m.id);
    if (!missing.empty()) throw InputError({path, m.first_line, "angle_deg"}, who + missing);
    for (int i = 0; i < n; ++i) {
      const double next = i + 1 < n ? sorted.angle_rad[i + 1] : sorted.angle_rad[0] + 2 * kPi;
      const double gap = next - sorted.angle_rad[i];
      if (gap < 1e-12) {
        throw InputError({path, m.first_line, "angle_deg"},
                         who + " has two points at the same angle " +
                             std::to_string(sorted.angle_rad[i] * 180 / kPi) + " deg");
      }
      if (std::abs(gap - spacing) > kSpacingTolerance * spacing) {
        throw InputError({path, m.first_line, "angle_deg"},
                         who + ": points are not equally spaced (gap of " +
                             std::to_string(gap * 180 / kPi) + " deg after " +
                             std::to_string(sorted.angle_rad[i] * 180 / kPi) + " deg, expected " +
                             std::to_string(spacing * 180 / kPi) + " deg)");
      }
    }
    m = sorted;
  }
  return data;
}

}  // namespace modaltyre::modal
