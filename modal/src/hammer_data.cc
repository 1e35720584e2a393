#include "modaltyre/modal/hammer_data.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

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

}  // namespace

HammerData read_hammer_csv(const std::string& path) {
  CsvSchema schema;
  schema.required = {"mode",      "freq_hz", "damping_ratio", "point",
                     "angle_deg", "radial",  "tangential"};
  const CsvTable t = read_csv(path, schema);

  HammerData data;
  data.path = path;
  std::map<int, std::size_t> index;               // mode id -> position in data.modes
  std::map<std::pair<int, int>, int> seen_point;  // (mode, point) -> line
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
      if (!(std::abs(t.number(r, col)) <= kMaxShape)) {
        throw InputError({path, line, col},
                         "shape value must be within +-1e6 kg^-1/2 "
                         "(mass-normalised shapes are of order 1)");
      }
    }
    m.radial.push_back(t.number(r, "radial"));
    m.tangential.push_back(t.number(r, "tangential"));
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
      throw InputError({path, m.first_line, "point"},
                       who + " has " + std::to_string(n) + " points, mode " +
                           std::to_string(data.modes.front().id) + " has " +
                           std::to_string(data.points) + "; every mode needs the same points");
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
    }
    const double spacing = 2 * kPi / n;
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
